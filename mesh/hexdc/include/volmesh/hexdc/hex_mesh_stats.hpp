#pragma once
// The figures of a hex mesh the paper tabulates (its Tables 1 and 2), plus the scaled Jacobian:
// what `volmesh mesh hexdc --json` reports for each stage of the mesher.
#include <map>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh {

struct HexMeshStats {
  Index nodes = 0;  // points used by a hex
  Index cells = 0;
  double max_edge = 0.0, min_edge = 0.0;  // over every hex edge
  double max_aspect_ratio = 0.0;          // of a hex: its longest edge over its shortest
  double max_quad_distortion_deg = 0.0;   // hex_quality's deviation of a quad angle from 90°
  double min_scaled_jacobian = 0.0, mean_scaled_jacobian = 0.0;
  Index degenerate = 0;  // hexes failing the ten corner tets (hex_corner_tets_positive)
  Index first_degenerate = kNoIndex;  // the lowest-numbered one, and its corners' centroid
  Vec3 first_degenerate_centre = Vec3::Zero();
  // The paper's c-valence: for each number of hexes around a node, how many nodes have it.
  std::map<Index, Index> valence;
};

// All zero for a mesh without cells.
HexMeshStats hex_mesh_stats(const HexMesh& mesh);

}  // namespace volmesh
