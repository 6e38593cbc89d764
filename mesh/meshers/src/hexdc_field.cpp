#include "hexdc_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "volmesh/domain/analytic.hpp"
#include "volmesh/domain/analytic_closest.hpp"
#include "volmesh/domain/grid.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh::meshers {

namespace {

// A little more than one node, so that float rounding of the layout cannot eat into it.
constexpr double kMarginSlack = 1e-3;
// Contouring reads the field at the ends of crossed voxel edges and their neighbours (central
// differences): within two spacings of the surface. Farther samples need only their sign.
constexpr double kExactBandSpacings = 3.0;
// An outside sample on the surface stays below zero (F >= 0 is inside), by this many spacings.
constexpr double kOutsideFloor = 1e-6;

std::vector<Vec3> sample_points(const VoxelGrid& grid) {
  std::vector<Vec3> points;
  points.reserve(grid.values.size());
  for (Index k = 0; k < grid.dims[2]; ++k)
    for (Index j = 0; j < grid.dims[1]; ++j)
      for (Index i = 0; i < grid.dims[0]; ++i) points.push_back(grid.point(i, j, k));
  return points;
}

void resample(const SdfGridDomain& source, VoxelGrid& grid) {
  const std::vector<Vec3> points = sample_points(grid);
  for (std::size_t s = 0; s < points.size(); ++s)
    grid.values[s] = static_cast<float>(source.value(points[s]));
}

// The exact signed distance of a domain of one analytic primitive: positive inside, which is
// region != 0, the magnitude the distance to the primitive's closest surface point.
void sample_primitive(const AnalyticDomain& domain, VoxelGrid& grid) {
  const Primitive& primitive = domain.primitives().front();
  const std::vector<Vec3> points = sample_points(grid);
  std::vector<Index> region(points.size());
  domain.region(points, region);
  const double floor = kOutsideFloor * grid.spacing.minCoeff();
  for (std::size_t s = 0; s < points.size(); ++s) {
    const double distance = (closest_surface_point(primitive, points[s]).point - points[s]).norm();
    grid.values[s] = static_cast<float>(region[s] != 0 ? distance : -std::max(distance, floor));
  }
}

// Sign from the regions, magnitude from the crossings of the grid edges whose ends differ.
void sample_domain(const Domain& domain, VoxelGrid& grid) {
  const std::vector<Vec3> points = sample_points(grid);
  std::vector<Index> region(points.size());
  domain.region(points, region);

  std::vector<Vec3> a, b;
  std::vector<std::array<std::int64_t, 2>> ends;  // the samples at a and b
  for (Index k = 0; k < grid.dims[2]; ++k)
    for (Index j = 0; j < grid.dims[1]; ++j)
      for (Index i = 0; i < grid.dims[0]; ++i) {
        const std::array<Index, 3> at{i, j, k};
        for (int axis = 0; axis < 3; ++axis) {
          if (at[axis] + 1 == grid.dims[axis]) continue;
          std::array<Index, 3> next = at;
          ++next[axis];
          const std::int64_t s = grid.index(i, j, k), t = grid.index(next[0], next[1], next[2]);
          if ((region[s] != 0) == (region[t] != 0)) continue;
          a.push_back(points[s]);
          b.push_back(points[t]);
          ends.push_back({s, t});
        }
      }
  std::vector<std::vector<Crossing>> hits;
  domain.crossings(a, b, hits);

  std::vector<double> distance(points.size(), grid.spacing.minCoeff());
  for (std::size_t e = 0; e < ends.size(); ++e) {
    if (hits[e].empty()) continue;
    const double length = (b[e] - a[e]).norm();
    auto& [s, t] = ends[e];
    distance[s] = std::min(distance[s], hits[e].front().t * length);
    distance[t] = std::min(distance[t], (1.0 - hits[e].back().t) * length);
  }
  const double floor = kOutsideFloor * grid.spacing.minCoeff();
  for (std::size_t s = 0; s < points.size(); ++s)
    grid.values[s] = static_cast<float>(region[s] != 0 ? distance[s]
                                                       : -std::max(distance[s], floor));
}

}  // namespace

Index outermost_surface(const SurfaceDomain& domain) {
  const std::vector<Index>& depths = domain.depths();
  if (std::count(depths.begin(), depths.end(), 0) != 1) return kNoIndex;
  return static_cast<Index>(std::find(depths.begin(), depths.end(), 0) - depths.begin());
}

double hexdc_margin(int level) {
  // m L >= (1 + 2 m) L / 2^level for a box of largest side L: m >= 1 / (2^level - 2).
  return (1.0 + kMarginSlack) / static_cast<double>((std::int64_t{1} << level) - 2);
}

VoxelGrid hexdc_field(const Domain& domain, int depth, double margin) {
  const Index dim = (Index{1} << depth) + 1;
  const auto* sdf = dynamic_cast<const SdfGridDomain*>(&domain);
  if (sdf != nullptr && sdf->grid().dims == std::array<Index, 3>{dim, dim, dim})
    return sdf->grid();
  VoxelGrid grid = sdf_layout(domain.bounds(), dim, margin);
  grid.values.resize(static_cast<std::size_t>(dim) * dim * dim);
  const auto* surfaces = dynamic_cast<const SurfaceDomain*>(&domain);
  const Index outer = surfaces != nullptr ? outermost_surface(*surfaces) : kNoIndex;
  const auto* analytic = dynamic_cast<const AnalyticDomain*>(&domain);
  if (sdf != nullptr)
    resample(*sdf, grid);
  else if (outer != kNoIndex)
    SignedDistance(surfaces->surface(outer), "surface")
        .sample_band(grid, kExactBandSpacings * grid.spacing.maxCoeff());  // positive inside
  else if (analytic != nullptr && analytic->primitives().size() == 1)
    sample_primitive(*analytic, grid);
  else
    sample_domain(domain, grid);
  return grid;
}

}  // namespace volmesh::meshers
