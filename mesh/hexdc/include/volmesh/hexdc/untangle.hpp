#pragma once
// Local optimisation of the worst hexes, after smoothing: each interior node of a hex whose
// quality is below a target moves to raise the least quality among its hexes, so that folded
// hexes unfold and poor ones improve where the Laplacian mean does not help.
//
// The quality of a hex (hex_shape_quality) is the least of its scaled Jacobian (the 8 corners
// and the centre) and the two inner tets of the ten corner tets, each as 6 V over the product
// of its three edges at its first corner, scaled to 1 in a cube. It is positive exactly when
// the hex passes the ten corner tets (the eight corner tets are the corner Jacobians) and the
// scaled Jacobian is positive, so raising it to above zero validates a hex by both tests.
//
// A node's move is found by a pattern search on the least quality of its hexes: the ascent
// direction of that least quality (central differences) and the 26 directions to the
// neighbours of a 3x3x3 stencil, at a step
// that starts at a fraction of the node's shortest edge and is halved when no direction
// improves. A move is accepted only if the node's least quality rises and every hex around it
// that passed the ten corner tets still does. So the mesh's least quality never falls and no
// valid hex becomes invalid. Nodes are visited in index order, which makes the result
// deterministic.
//
// Boundary nodes (on mesh.boundary_faces) are kept unless a surface is given. With one, a
// boundary node moves too, and every trial point is taken back onto the surface before it is
// judged. A node off the mesh boundary's creases and corners (the feature angle, as in
// smoothing.hpp) searches its tangent plane (the normal of its boundary quads) and its trial
// points go to their closest surface points; a feature node searches all directions and its
// trial points go to the nearest point of its feature (project.hpp's feature point: the crease
// line or the corner, so a corner node stays). Features are those of the surface (its normals
// under the node's quads), not of the mesh, so that a folded quad does not make its nodes
// features. Without those moves a buffer hex keeps its outer quad as projection left it, however
// folded. If hexes still fail after the sweeps, their feature nodes are released (moved as
// other boundary nodes, onto the closest surface point) and the sweeps run again: a hex whose
// outer quad has three corners on one crease cannot unfold otherwise.
#include <array>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/hexdc/surface_projector.hpp"

namespace volmesh {


struct UntangleOptions {
  // Nodes of hexes below this quality are optimised: the aim for the least scaled
  // Jacobian; hexes above it are left to smoothing.
  double target_quality = 0.5;
  int sweeps = 10;                 // sweeps stop early once no node moves
  double initial_step = 0.25;      // of the node's shortest edge
  double final_step = 1.0 / 512;   // of the node's shortest edge: the search stops below it
  int max_steps_per_node = 30;     // moves and halvings together, per node and sweep
  // As SmoothingOptions': boundary nodes beyond it are feature nodes.
  double feature_angle_deg = 40.0;
};

struct UntangleStats {
  int sweeps = 0;
  Index moves_accepted = 0;  // nodes moved, counted once per sweep
  Index features_released = 0;  // feature nodes of hexes left failing, then moved on the surface
  Index invalid_hexes_before = 0, invalid_hexes_after = 0;  // failing the ten corner tets
  double min_quality_before = 0.0, min_quality_after = 0.0;  // hex_shape_quality
};

// Moves mesh.points in place; connectivity and boundary faces are unchanged. An empty mesh is
// left as it is. Boundary nodes move only when `surface` is given (not empty), and then onto
// it. Throws InputError for a target outside (0, 1], negative sweeps, steps not in (0, 1]
// with final_step < initial_step or a feature angle outside [0, 180] degrees.
UntangleStats untangle_hexes(HexMesh& mesh, const UntangleOptions& options = {},
                             const SurfaceProjector& surface = {});

}  // namespace volmesh
