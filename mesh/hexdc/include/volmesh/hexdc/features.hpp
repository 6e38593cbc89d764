#pragma once
// The sharp features of the surface a hex mesh stands for, and how its boundary follows them.
//
// A sharp edge is an edge of the input triangles whose two triangles' normals meet at more than
// the feature angle. Sharp edges join into creases: polylines from corner to corner, or closed
// loops. A corner is a vertex where one or three or more sharp edges meet, or where a crease
// turns by more than kCornerTurnDegrees.
//
// The buffer layer (feature_layer.hpp) gives every crease a chain of boundary edges and every
// corner a boundary node; crease_capture measures, on the final mesh, how far each crease lies
// from its chain.
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/tri_surface.hpp"

namespace volmesh {

// A crease turning by more than this at a vertex has a corner there.
inline constexpr double kCornerTurnDegrees = 60.0;

struct SurfaceFeatures {
  // Each crease from one end to the other; a closed loop repeats its first point last.
  std::vector<std::vector<Vec3>> creases;
  std::vector<Vec3> corners;
};

// Throws InputError for a feature angle outside [0, 180] degrees. Edges with other than two
// triangles are not sharp (the surface domains are closed and manifold).
SurfaceFeatures sharp_features(const TriSurface& surface, double feature_angle_deg);

// A boundary chain following one crease: its nodes in order along it.
struct FeatureChain {
  Index crease = 0;          // in SurfaceFeatures::creases
  std::vector<Index> nodes;  // mesh nodes, consecutive ones joined by a boundary edge
};

struct CaptureStats {
  Index creases = 0;   // given
  Index captured = 0;  // with a chain within kCapturedFraction of its mean edge, both ways
  // The largest of the two-sided Hausdorff distances between a crease and its chain, over the
  // creases with a chain, relative to the chain's mean edge.
  double max_relative_distance = 0.0;
};

// A crease is captured when its chain and it lie within this fraction of the chain's mean edge
// of each other, both ways: the chain's edges run along the crease.
inline constexpr double kCapturedFraction = 0.1;

CaptureStats crease_capture(const HexMesh& mesh, const SurfaceFeatures& features,
                            const std::vector<FeatureChain>& chains);

}  // namespace volmesh
