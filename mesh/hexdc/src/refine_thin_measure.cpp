#include "refine_thin_measure.hpp"

#include <numbers>
#include <vector>

namespace volmesh::hexdc_detail {
namespace {

// Steps of the walk across the solid, in voxels: fine enough not to step over a part a cell
// wide, at 2 or more voxels per cell.
constexpr double kWalkStep = 0.5;
constexpr double kStraightAngleDeg = 180.0;

// Where the field crosses zero between values a and b of opposite signs, as a fraction of the
// way from a to b.
double crossing(double a, double b) { return a / (a - b); }

// The field's gradient at a sample by central differences (one-sided at the grid's border).
Vec3 gradient(const VoxelGrid& field, const std::array<Index, 3>& at) {
  Vec3 g;
  for (std::size_t a = 0; a < 3; ++a) {
    std::array<Index, 3> lo = at, hi = at;
    lo[a] = std::max<Index>(at[a] - 1, 0);
    hi[a] = std::min<Index>(at[a] + 1, field.dims[a] - 1);
    const auto axis = static_cast<Eigen::Index>(a);
    g[axis] = (field.at(hi[0], hi[1], hi[2]) - field.at(lo[0], lo[1], lo[2])) /
              (static_cast<double>(hi[a] - lo[a]) * field.spacing[axis]);
  }
  return g;
}

// The field at p by trilinear interpolation; outside the grid it is outside the solid.
double trilinear(const VoxelGrid& field, const Vec3& p) {
  const Vec3 x = (p - field.origin).cwiseQuotient(field.spacing);
  std::array<Index, 3> base{};
  Vec3 t;
  for (std::size_t a = 0; a < 3; ++a) {
    const auto axis = static_cast<Eigen::Index>(a);
    if (!(x[axis] >= 0.0) || x[axis] > static_cast<double>(field.dims[a] - 1)) return -1.0;
    base[a] = std::min(static_cast<Index>(x[axis]), field.dims[a] - 2);
    t[axis] = x[axis] - static_cast<double>(base[a]);
  }
  double value = 0.0;
  for (int c = 0; c < 8; ++c) {
    double weight = 1.0;
    std::array<Index, 3> at = base;
    for (std::size_t a = 0; a < 3; ++a) {
      const bool up = ((c >> a) & 1) != 0;
      at[a] += up ? 1 : 0;
      const double ta = t[static_cast<Eigen::Index>(a)];
      weight *= up ? ta : 1.0 - ta;
    }
    value += weight * field.at(at[0], at[1], at[2]);
  }
  return value;
}

// From the crossing p inward along the unit normal n to where the field is negative again,
// crossing to crossing; kNoWidth if not within cap.
double across(const VoxelGrid& field, const Vec3& p, const Vec3& n, double cap) {
  const double step = kWalkStep * field.spacing.minCoeff();
  double last = 0.0;
  for (double t = step; t <= cap + step; t += step) {
    const double f = trilinear(field, p + t * n);
    if (f < 0.0) {
      const double width = t - step + step * crossing(last, f);
      return width <= cap ? width : kNoWidth;
    }
    last = f;
  }
  return kNoWidth;
}

}  // namespace

SurfaceMeasures surface_measures(const VoxelGrid& field, const SampleBox& box, double cap) {
  SurfaceMeasures m;
  std::vector<Vec3> normals;
  for (Index k = box.lo[2]; k <= box.hi[2]; ++k)
    for (Index j = box.lo[1]; j <= box.hi[1]; ++j)
      for (Index i = box.lo[0]; i <= box.hi[0]; ++i) {
        const std::array<Index, 3> at{i, j, k};
        const double here = field.at(i, j, k);
        for (std::size_t a = 0; a < 3; ++a) {
          std::array<Index, 3> next = at;
          if (++next[a] > box.hi[a]) continue;
          const double there = field.at(next[0], next[1], next[2]);
          if ((here >= 0.0) == (there >= 0.0)) continue;
          const double s = crossing(here, there);
          const Vec3 g = (1.0 - s) * gradient(field, at) + s * gradient(field, next);
          if (g.squaredNorm() == 0.0) continue;
          const Vec3 n = g.normalized();  // inward: the field is positive inside
          normals.push_back(n);
          const Vec3 p = (1.0 - s) * field.point(i, j, k) + s * field.point(next[0], next[1], next[2]);
          m.width = std::min(m.width, across(field, p, n, cap));
        }
      }
  if (normals.size() < 2) return m;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& n : normals) mean += n;
  if (mean.squaredNorm() == 0.0) {
    m.spread_deg = kStraightAngleDeg;
    return m;
  }
  mean.normalize();
  double least_cos = 1.0;
  for (const Vec3& n : normals) least_cos = std::min(least_cos, n.dot(mean));
  m.spread_deg = std::acos(std::clamp(least_cos, -1.0, 1.0)) * kStraightAngleDeg / std::numbers::pi;
  return m;
}

}  // namespace volmesh::hexdc_detail
