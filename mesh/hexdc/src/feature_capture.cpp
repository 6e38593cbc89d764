// How far the creases lie from their chains on the final mesh (features.hpp).
#include <algorithm>
#include <limits>

#include "polyline.hpp"
#include "volmesh/hexdc/features.hpp"

namespace volmesh {
namespace {

// Points per segment at which one polyline's distance to another is taken.
constexpr int kSamples = 8;

}  // namespace

CaptureStats crease_capture(const HexMesh& mesh, const SurfaceFeatures& features,
                            const std::vector<FeatureChain>& chains) {
  using hexdc_detail::distance_to_polyline;
  using hexdc_detail::polyline_excess;
  CaptureStats stats;
  stats.creases = static_cast<Index>(features.creases.size());
  for (std::size_t c = 0; c < features.creases.size(); ++c) {
    const std::vector<Vec3>& crease = features.creases[c];
    std::vector<std::vector<Vec3>> lines;
    double length = 0.0;
    Index edges = 0;
    for (const FeatureChain& chain : chains) {
      if (chain.crease != static_cast<Index>(c)) continue;
      std::vector<Vec3> line;
      for (const Index v : chain.nodes) line.push_back(mesh.points[static_cast<std::size_t>(v)]);
      for (std::size_t i = 1; i < line.size(); ++i) length += (line[i] - line[i - 1]).norm();
      edges += static_cast<Index>(line.size()) - 1;
      lines.push_back(std::move(line));
    }
    if (lines.empty() || length <= 0.0) continue;
    double worst = 0.0;
    for (const auto& line : lines) worst = std::max(worst, polyline_excess(line, crease, kSamples));
    // The crease's points to the nearest of its chains.
    for (std::size_t i = 1; i < crease.size(); ++i)
      for (int k = 0; k <= kSamples; ++k) {
        const Vec3 p = crease[i - 1] + (crease[i] - crease[i - 1]) * (static_cast<double>(k) / kSamples);
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& line : lines) nearest = std::min(nearest, distance_to_polyline(p, line));
        worst = std::max(worst, nearest);
      }
    const double relative = worst / (length / static_cast<double>(edges));
    stats.max_relative_distance = std::max(stats.max_relative_distance, relative);
    if (relative <= kCapturedFraction) ++stats.captured;
  }
  return stats;
}

}  // namespace volmesh
