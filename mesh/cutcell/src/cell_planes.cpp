#include "cell_planes.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace volmesh::cutcell {
namespace {

// Pushing a point off one face plane may push it toward another; three passes settle a
// point near a corner, where three planes meet.
constexpr int kClampPasses = 3;

// Corners of cell face k (axis k / 2, side k % 2) in a cyclic order.
std::array<int, 4> face_corners(int k) {
  const int axis = k / 2, side = k % 2;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  std::array<int, 4> out{};
  const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) out[i] = side << axis | uv[i][0] << u | uv[i][1] << v;
  return out;
}

// The planes of the six faces: centre and outward unit normal.
std::array<std::pair<Vec3, Vec3>, 6> face_planes(const std::array<Vec3, 8>& corners) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& c : corners) centre += c / 8.0;
  std::array<std::pair<Vec3, Vec3>, 6> planes;
  for (int k = 0; k < 6; ++k) {
    const std::array<int, 4> f = face_corners(k);
    const Vec3 face_centre = 0.25 * (corners[f[0]] + corners[f[1]] + corners[f[2]] + corners[f[3]]);
    Vec3 normal = (corners[f[2]] - corners[f[0]]).cross(corners[f[3]] - corners[f[1]]).normalized();
    if (normal.dot(face_centre - centre) < 0) normal = -normal;
    planes[k] = {face_centre, normal};
  }
  return planes;
}

}  // namespace

double depth_inside_cell(const std::array<Vec3, 8>& corners, const Vec3& p) {
  double depth = std::numeric_limits<double>::infinity();
  for (const auto& [centre, normal] : face_planes(corners)) depth = std::min(depth, normal.dot(centre - p));
  return depth;
}

std::optional<Vec3> clamp_into_cell(const std::array<Vec3, 8>& corners, Vec3 p, double margin,
                                    double reach) {
  const auto planes = face_planes(corners);
  double depth = std::numeric_limits<double>::infinity();
  for (const auto& [centre, normal] : planes) depth = std::min(depth, normal.dot(centre - p));
  if (depth < -reach) return std::nullopt;
  for (int pass = 0; pass < kClampPasses; ++pass)
    for (const auto& [centre, normal] : planes)
      if (const double d = normal.dot(centre - p); d < margin) p -= (margin - d) * normal;
  return p;
}

std::optional<Vec3> slide_into_cell(const std::array<Vec3, 8>& corners, const Vec3& p, const Vec3& direction,
                                    double margin, double reach) {
  // Each face plane bounds the move s: normal . (centre - p - s direction) >= margin.
  double lo = -reach, hi = reach;
  for (const auto& [centre, normal] : face_planes(corners)) {
    const double room = normal.dot(centre - p) - margin, rate = normal.dot(direction);
    if (rate > 0.0) hi = std::min(hi, room / rate);
    else if (rate < 0.0) lo = std::max(lo, room / rate);
    else if (room < 0.0) return std::nullopt;
  }
  if (lo > hi) return std::nullopt;
  const double s = lo > 0.0 ? lo : (hi < 0.0 ? hi : 0.0);
  return p + s * direction;
}

}  // namespace volmesh::cutcell
