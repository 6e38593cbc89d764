#include "volmesh/geometry/cell_tessellation.hpp"

#include <algorithm>
#include <cmath>

#include "volmesh/core/geometry.hpp"
#include "volmesh/geometry/polygon_split.hpp"

namespace volmesh {
namespace {

// Sub-tetrahedron volume relative to the cube of its longest edge at or below which it counts
// as degenerate (a regular tet has 0.118).
constexpr double kDegenerateShape = 1e-12;

// The kernel search: projections over-relaxed by this factor (in (1, 2): finite termination);
// a margin that starts at this fraction of the cell's volume-to-area length and shrinks by
// kMarginShrink for each of kMarginAttempts tries, each of at most kMaxSweeps sweeps.
constexpr double kOverRelaxation = 1.5;
constexpr double kInitialMargin = 0.1;
constexpr double kMarginShrink = 0.25;
constexpr int kMarginAttempts = 6;
constexpr int kMaxSweeps = 500;

double shape_measure(const SubTetrahedron& t) {
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      longest = std::max(longest, (t.corners[i] - t.corners[j]).norm());
  const double volume = tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
  return longest > 0.0 ? volume / (longest * longest * longest) : 0.0;
}

bool sees_every_face(const PolyMesh& mesh, const FaceSplits& splits, std::span<const Index> faces,
                     Index c, const Vec3& x) {
  bool ok = true;
  for_each_sub_tetrahedron(mesh, splits, faces, c, x, [&](const SubTetrahedron& t) {
    ok = ok && shape_measure(t) > kDegenerateShape;
  });
  return ok;
}

}  // namespace

FaceSplits split_faces(const PolyMesh& mesh) {
  FaceSplits splits;
  splits.offsets.assign(mesh.num_faces() + 1, 0);
  splits.folded.assign(mesh.num_faces(), 0);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (const PolygonSplit split = split_polygon(mesh.points, mesh.face(f)); split.folded)
      splits.folded[f] = 1;
    else
      splits.triangles.insert(splits.triangles.end(), split.triangles.begin(),
                              split.triangles.end());
    splits.offsets[f + 1] = static_cast<Index>(splits.triangles.size());
  }
  return splits;
}

std::optional<Vec3> star_centre(const PolyMesh& mesh, const FaceSplits& splits,
                                std::span<const Index> faces, Index c) {
  std::vector<Index> vertices;
  for (Index f : faces) {
    const auto loop = mesh.face(f);
    vertices.insert(vertices.end(), loop.begin(), loop.end());
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  if (vertices.empty()) return std::nullopt;
  Vec3 average = Vec3::Zero();
  for (Index v : vertices) average += mesh.points[v];
  average /= static_cast<double>(vertices.size());
  if (sees_every_face(mesh, splits, faces, c, average)) return average;

  // The face triangles' planes, outward normals unit: the kernel is where n·x < n·p for all.
  std::vector<std::pair<Vec3, double>> planes;
  double volume = 0.0, area = 0.0;
  Vec3 moment = Vec3::Zero();
  for_each_sub_tetrahedron(mesh, splits, faces, c, average, [&](const SubTetrahedron& t) {
    const double v = tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
    volume += v;
    moment += v * (t.corners[0] + t.corners[1] + t.corners[2] + t.corners[3]) / 4.0;
    const Vec3 n = (t.corners[2] - t.corners[1]).cross(t.corners[3] - t.corners[1]);
    area += 0.5 * n.norm();
    if (n.norm() > 0.0) planes.emplace_back(n.normalized(), n.normalized().dot(t.corners[1]));
  });
  if (!(volume > 0.0) || !(area > 0.0)) return std::nullopt;
  Vec3 x = moment / volume;
  if (sees_every_face(mesh, splits, faces, c, x)) return x;

  // Cyclic over-relaxed projections onto the planes shifted inward by a margin, which end
  // after finitely many steps when the shifted kernel is not empty.
  double margin = kInitialMargin * volume / area;
  for (int attempt = 0; attempt < kMarginAttempts; ++attempt, margin *= kMarginShrink) {
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
      bool moved = false;
      for (const auto& [n, b] : planes) {
        const double excess = n.dot(x) - (b - margin);
        if (excess > 0.0) {
          x -= kOverRelaxation * excess * n;
          moved = true;
        }
      }
      if (!moved) break;
    }
    if (sees_every_face(mesh, splits, faces, c, x)) return x;
  }
  return std::nullopt;
}

}  // namespace volmesh
