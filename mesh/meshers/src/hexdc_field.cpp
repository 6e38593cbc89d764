#include "hexdc_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <oneapi/tbb/parallel_for.h>

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

// The samples of plane k (x fastest): the field is computed a plane at a time, so that no
// array of the grid's size holds more than its values (a 1025^3 grid has 4 GB of them).
std::vector<Vec3> plane_points(const VoxelGrid& grid, Index k) {
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(grid.dims[0]) * grid.dims[1]);
  for (Index j = 0; j < grid.dims[1]; ++j)
    for (Index i = 0; i < grid.dims[0]; ++i) points.push_back(grid.point(i, j, k));
  return points;
}

std::size_t plane_size(const VoxelGrid& grid) {
  return static_cast<std::size_t>(grid.dims[0]) * static_cast<std::size_t>(grid.dims[1]);
}

void resample(const SdfGridDomain& source, VoxelGrid& grid) {
  tbb::parallel_for(Index{0}, grid.dims[2], [&](Index k) {
    const std::vector<Vec3> points = plane_points(grid, k);
    const std::size_t first = k * plane_size(grid);
    for (std::size_t s = 0; s < points.size(); ++s)
      grid.values[first + s] = static_cast<float>(source.value(points[s]));
  });
}

// The exact signed distance of a domain of one analytic primitive: positive inside, which is
// region != 0, the magnitude the distance to the primitive's closest surface point.
void sample_primitive(const AnalyticDomain& domain, VoxelGrid& grid) {
  const Primitive& primitive = domain.primitives().front();
  const double floor = kOutsideFloor * grid.spacing.minCoeff();
  std::vector<Index> region(plane_size(grid));
  for (Index k = 0; k < grid.dims[2]; ++k) {
    const std::vector<Vec3> points = plane_points(grid, k);
    domain.region(points, region);
    const std::size_t first = k * plane_size(grid);
    tbb::parallel_for(std::size_t{0}, points.size(), [&](std::size_t s) {
      const Vec3& p = points[s];
      const double distance = (closest_surface_point(primitive, p).point - p).norm();
      grid.values[first + s] =
          static_cast<float>(region[s] != 0 ? distance : -std::max(distance, floor));
    });
  }
}

// Sign from the regions, magnitude from the crossings of the grid edges whose ends differ,
// one spacing where none of a sample's edges is crossed.
void sample_domain(const Domain& domain, VoxelGrid& grid) {
  const std::size_t plane = plane_size(grid);
  std::vector<std::uint8_t> inside(grid.values.size());
  std::vector<Index> region(plane);
  for (Index k = 0; k < grid.dims[2]; ++k) {
    domain.region(plane_points(grid, k), region);
    for (std::size_t s = 0; s < plane; ++s) inside[k * plane + s] = region[s] != 0;
  }
  const auto spacing = static_cast<float>(grid.spacing.minCoeff());
  std::fill(grid.values.begin(), grid.values.end(), spacing);  // the magnitude, for now

  // Plane k's edges along x and y, and those along z up to plane k + 1.
  std::vector<Vec3> a, b;
  std::vector<std::array<std::int64_t, 2>> ends;  // the samples at a and b
  std::vector<std::vector<Crossing>> hits;
  for (Index k = 0; k < grid.dims[2]; ++k) {
    a.clear();
    b.clear();
    ends.clear();
    for (Index j = 0; j < grid.dims[1]; ++j)
      for (Index i = 0; i < grid.dims[0]; ++i) {
        const std::array<Index, 3> at{i, j, k};
        for (int axis = 0; axis < 3; ++axis) {
          if (at[axis] + 1 == grid.dims[axis]) continue;
          std::array<Index, 3> next = at;
          ++next[axis];
          const std::int64_t s = grid.index(i, j, k), t = grid.index(next[0], next[1], next[2]);
          if (inside[s] == inside[t]) continue;
          a.push_back(grid.point(i, j, k));
          b.push_back(grid.point(next[0], next[1], next[2]));
          ends.push_back({s, t});
        }
      }
    domain.crossings(a, b, hits);
    for (std::size_t e = 0; e < ends.size(); ++e) {
      if (hits[e].empty()) continue;
      const double length = (b[e] - a[e]).norm();
      auto& [s, t] = ends[e];
      grid.values[s] = std::min(grid.values[s], static_cast<float>(hits[e].front().t * length));
      grid.values[t] =
          std::min(grid.values[t], static_cast<float>((1.0 - hits[e].back().t) * length));
    }
  }
  const auto floor = static_cast<float>(kOutsideFloor * grid.spacing.minCoeff());
  for (std::size_t s = 0; s < grid.values.size(); ++s)
    grid.values[s] = inside[s] != 0 ? grid.values[s] : -std::max(grid.values[s], floor);
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

std::shared_ptr<const SignedDistance> outer_surface_distance(const Domain& domain) {
  const auto* surfaces = dynamic_cast<const SurfaceDomain*>(&domain);
  const Index outer = surfaces != nullptr ? outermost_surface(*surfaces) : kNoIndex;
  if (outer == kNoIndex) return nullptr;
  return std::make_shared<const SignedDistance>(surfaces->surface(outer), "surface");
}

VoxelGrid hexdc_field(const Domain& domain, int depth, double margin,
                      const SignedDistance* outer) {
  const Index dim = (Index{1} << depth) + 1;
  const auto* sdf = dynamic_cast<const SdfGridDomain*>(&domain);
  if (sdf != nullptr && sdf->grid().dims == std::array<Index, 3>{dim, dim, dim})
    return sdf->grid();
  VoxelGrid grid = sdf_layout(domain.bounds(), dim, margin);
  grid.values.resize(static_cast<std::size_t>(dim) * dim * dim);
  const auto* analytic = dynamic_cast<const AnalyticDomain*>(&domain);
  if (sdf != nullptr)
    resample(*sdf, grid);
  else if (outer != nullptr)
    outer->sample_band(grid, kExactBandSpacings * grid.spacing.maxCoeff());  // positive inside
  else if (analytic != nullptr && analytic->primitives().size() == 1)
    sample_primitive(*analytic, grid);
  else
    sample_domain(domain, grid);
  return grid;
}

}  // namespace volmesh::meshers
