#pragma once
// The paper's boundary refinement: boundary nodes moved onto the isosurface at the end, so that
// the mesh boundary lies on the surface it stands for (the QEF vertex only approximates it).
//
// Each boundary node (a node of mesh.boundary_faces) moves to the closest point of the surface,
// which is a move along the surface normal there. Nodes on a crease or corner of the mesh
// boundary (quad normals spread beyond the feature angle, as in pillow.hpp)
// cannot: the closest surface point of a point beside a convex edge lies on one of the two
// faces, so projecting would round the edge off. Nor are they left where the QEF put them: its
// crossings' normals come from central differences, which blend the two faces' near the edge,
// and leave the vertex off it by a fraction of a voxel. A feature node moves instead to the
// point nearest it on the surface's tangent planes beside it (one per quad,
// through the closest point of a probe just inside the quad's centre, whose segment to it is
// normal to the surface): two faces' planes meet in the crease, three in the corner. Feature
// nodes move first in each pass, so that their neighbours are projected beside where they end.
//
// A move is accepted when every hex of the node passing the ten corner tets still does and the
// least scaled Jacobian over its hexes stays at or above min(what it was, the floor); otherwise
// half the step is tried, up to `halvings` times, and then the node stays. The floor, 0.3, is the
// least scaled Jacobian aimed at for every hex: projection may spend quality down to it,
// never below. Nodes are visited in index order, in `passes` passes (a neighbour's move can make
// room for a node held back), which makes the result deterministic. What the guard holds back,
// the global optimiser (optimise.hpp) takes onto the surface as it frees the hexes around.
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/hexdc/feature_layer.hpp"
#include "volmesh/hexdc/surface_projector.hpp"

namespace volmesh {

struct ProjectOptions {
  // As SmoothingOptions' and PillowOptions': boundary nodes beyond it are feature nodes.
  double feature_angle_deg = 40.0;
  // A move may lower the least scaled Jacobian of the node's hexes, but not below this (nor
  // below what it was, if that is lower).
  double min_scaled_jacobian = 0.3;
  int halvings = 4;  // a rejected step is halved this many times before the node is kept
  int passes = 3;    // projection passes
  // A node this close to its projection, relative to the mesh's bounding-box diagonal, is on
  // the surface already.
  double tolerance = 1e-12;
  // Nodes the buffer layer chose for the input's creases and corners (feature_layer.hpp): moved
  // to their targets first in each pass, guarded with this floor instead: a crease through a
  // quad's corner costs that corner its angle until the optimiser spreads it.
  const std::vector<PinnedNode>* pinned = nullptr;
  double pinned_min_scaled_jacobian = 0.0;
};

struct ProjectStats {
  Index boundary_nodes = 0;
  Index projected = 0;      // non-feature nodes that end on the surface
  Index feature_nodes = 0;  // crease and corner nodes, moved onto the feature
  Index pinned_nodes = 0;   // ProjectOptions::pinned
  Index pinned_held_back = 0;  // of those, left off their targets
  Index held_back = 0;      // non-feature nodes left off the surface (by the quality guard)
  double max_distance_before = 0.0;   // over the non-feature nodes, to their projection
  double max_distance_left = 0.0;     // the same after: over the held-back nodes
  double max_feature_distance = 0.0;  // of the feature nodes to the surface, after
  double min_scaled_jacobian_before = 0.0, min_scaled_jacobian_after = 0.0;
  Index invalid_hexes_before = 0, invalid_hexes_after = 0;  // failing the ten corner tets
};

// Moves mesh.points in place; connectivity and boundary faces are unchanged. An empty mesh is
// left as it is. Throws InputError for negative halvings, passes < 1, a feature angle outside
// [0, 180] degrees or a negative tolerance.
ProjectStats project_boundary(HexMesh& mesh, const SurfaceProjector& closest_point,
                              const ProjectOptions& options = {});

}  // namespace volmesh
