#pragma once
// The buffer layer following the surface's creases (pillow.hpp, features.hpp).
//
// Before the layer is made, each crease gets a chain of boundary edges: the path between the
// boundary nodes nearest its ends that is shortest by length plus kOffCrease times its
// edges' distances to the crease (a closed crease is split at its middle point into two).
// Each corner is pinned to its nearest boundary node first, and the chains end there. The chain
// nodes move onto the crease (their closest point on it), the corner nodes onto their corners.
//
// Where a crease runs diagonally to the quads, its chain is a staircase, and the quad inside
// each step gets two chain edges: on a straight crease a 180° angle. After the layer is made,
// the boundary quads fall into patches, the quads joined across edges that are not on a chain;
// every patch bordering another across a chain is pillowed again (its layer hexes the shrink
// set): a strip of quads runs along each side of every chain, and each step's quad keeps its
// angles. The patch's layer then has two hexes through its thickness.
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/hexdc/features.hpp"

namespace volmesh {

// The weight of a chain edge's distance to its crease against its length.
inline constexpr double kOffCrease = 4.0;

// A boundary node on a crease or a corner, and where it belongs.
struct PinnedNode {
  Index node = 0;
  Vec3 target = Vec3::Zero();
  bool corner = false;
};

struct FeatureLayer {
  std::vector<FeatureChain> chains;
  std::vector<PinnedNode> pinned;  // in node order
  Index patches_pillowed = 0;      // patches pillowed a second time
  Index strip_hexes = 0;           // hexes that second pillowing added
};

// The chains and pinned nodes of `features` on the boundary of `mesh` (before the layer).
FeatureLayer chain_features(const HexMesh& mesh, const SurfaceFeatures& features);

// Pillows every patch bordering another across a chain of `layer` (after the layer), adding to
// its counts. Chain and corner nodes keep their indices.
void pillow_patches(HexMesh& mesh, FeatureLayer& layer);

}  // namespace volmesh
