#pragma once
// The paper's quality-improvement smoothing of a hex mesh, made monotone: a node moves only
// when no hex around it gets worse.
//
// Interior nodes go to the mean of their edge neighbours (Laplacian, after Canann et al.).
// Boundary nodes go to the mean of their boundary-edge neighbours projected onto the node's
// tangent plane, whose normal is the sum of the vector areas of the node's boundary quads, so
// that a node on a flat face stays exactly on it. A boundary node whose quads bend by more
// than the feature angle (a crease or corner of the boundary) is kept, since the paper moves
// boundary nodes without changing the shape of the boundary.
//
// A move is accepted when the least scaled Jacobian over the node's hexes does not fall and
// every one of them that passed the ten corner tets (hex_corner_tets_positive) still does;
// otherwise half the step is tried, up to `halvings` times, and then the node stays. So the
// mesh's least scaled Jacobian never falls and no valid hex becomes invalid. Nodes are
// visited in index order (Gauss-Seidel), which makes the result deterministic.
#include <vector>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh {

struct SmoothingOptions {
  // The paper gives no count; sweeps also stop early once no node moves.
  int sweeps = 10;
  int halvings = 4;  // a rejected step is halved this many times before the node is kept
  // Boundary nodes whose quad normals differ from their mean normal by more than this are
  // kept in place: below the 45° of a box edge, so that box edges and corners stay.
  double feature_angle_deg = 40.0;
};

struct SmoothingStats {
  int sweeps = 0;             // sweeps run
  Index moves_accepted = 0;   // node moves accepted (at the full or a halved step)
  Index moves_rejected = 0;   // node moves rejected at every step size
  double min_scaled_jacobian_before = 0.0, min_scaled_jacobian_after = 0.0;
  Index invalid_hexes_before = 0, invalid_hexes_after = 0;  // failing the ten corner tets
  std::vector<double> min_scaled_jacobian_per_sweep;        // after each sweep
};

// Moves mesh.points in place; connectivity and boundary faces are unchanged. The boundary is
// taken from mesh.boundary_faces. An empty mesh is left as it is. Throws InputError for
// negative sweeps or halvings or a feature angle outside [0, 180] degrees.
SmoothingStats smooth_hexes(HexMesh& mesh, const SmoothingOptions& options = {});

}  // namespace volmesh
