// Signed-distance voxels: the exact closest point of every sample (surface_closest.hpp),
// the sign from its feature's pseudo-normal. z-slices go to the cores; within a slice the
// samples are visited in a snake, each query starting from the previous sample's triangle,
// which bounds the search tightly from the start. A slice starts afresh, so the values do
// not depend on which core computes which slice.
#include "volmesh/domain/grid_sdf.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include "surface/surface_closest.hpp"

namespace volmesh {

namespace surface {

struct DistanceData {
  explicit DistanceData(SurfaceGeometry g) : geometry(std::move(g)), tree(geometry) {}

  double at(const Vec3& p, Index& hint) const {
    const ClosestPoint c = tree.closest(p, hint);
    hint = c.triangle;
    return signed_distance(geometry, p, c);
  }

  SurfaceGeometry geometry;
  ClosestTree tree;
};

}  // namespace surface

namespace {

// Samples per brick side in sample_band: 512 samples per far query, bricks small enough
// that a band a few samples wide leaves most of them far.
constexpr Index kBrick = 8;

surface::SurfaceGeometry geometry_of(TriSurface s, const std::string& name) {
  surface::SurfaceGeometry g;
  surface::add_surface(g, std::move(s), name);
  return g;
}

}  // namespace

bool is_octree_dim(Index dim) { return dim >= 3 && ((dim - 1) & (dim - 2)) == 0; }

VoxelGrid sdf_layout(const Box3& box, Index dim, double margin) {
  if (!is_octree_dim(dim)) throw std::invalid_argument("sdf_layout: dim must be 2^k + 1, k >= 1");
  if (!(margin >= 0.0) || !std::isfinite(margin))
    throw std::invalid_argument("sdf_layout: margin must be finite and >= 0");
  const double side = (box.hi - box.lo).maxCoeff();
  if (!(side > 0.0) || !std::isfinite(side) || !box.lo.allFinite())
    throw std::invalid_argument("sdf_layout: empty or non-finite box");
  VoxelGrid grid;
  grid.dims = {dim, dim, dim};
  const double exact = side * (1.0 + 2.0 * margin) / (dim - 1);
  float h = static_cast<float>(exact);
  if (h < exact) h = std::nextafter(h, 2.0f * h);  // never shorter than asked
  grid.spacing = Vec3::Constant(h);
  const Vec3 origin = box.centre() - Vec3::Constant(0.5 * h * (dim - 1));
  for (int a = 0; a < 3; ++a) grid.origin[a] = static_cast<float>(origin[a]);
  return grid;
}

SignedDistance::SignedDistance(TriSurface surface, const std::string& name)
    : data_(std::make_unique<const surface::DistanceData>(geometry_of(std::move(surface), name))) {}
SignedDistance::~SignedDistance() = default;
SignedDistance::SignedDistance(SignedDistance&&) noexcept = default;
SignedDistance& SignedDistance::operator=(SignedDistance&&) noexcept = default;

double SignedDistance::operator()(const Vec3& p) const {
  Index hint = kNoIndex;
  return data_->at(p, hint);
}

Vec3 SignedDistance::closest_point(const Vec3& p) const { return data_->tree.closest(p).point; }

Box3 SignedDistance::bounds() const { return surface::bounding_box(data_->geometry); }

namespace {

// Checks the grid's layout and sizes its values, for SignedDistance's `what`.
void prepare(VoxelGrid& grid, const char* what) {
  const auto& n = grid.dims;
  if (n[0] < 1 || n[1] < 1 || n[2] < 1 || !grid.origin.allFinite() || !grid.spacing.allFinite())
    throw std::invalid_argument(std::string("SignedDistance::") + what +
                                ": dims < 1 or non-finite geometry");
  grid.values.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0.0f);
}

// Runs slab(s) for s in [0, slabs) on every core, reporting the fraction of slabs done.
template <class Slab>
void for_each_slab(Index slabs, const std::function<void(double)>& progress, const Slab& slab) {
  std::mutex reporting;
  Index done = 0;
  const auto run = [&](const tbb::blocked_range<Index>& r) {
    for (Index s = r.begin(); s != r.end(); ++s) {
      slab(s);
      if (progress) {
        const std::lock_guard lock(reporting);
        progress(static_cast<double>(++done) / slabs);
      }
    }
  };
  tbb::parallel_for(tbb::blocked_range<Index>(0, slabs, 1), run);
}

}  // namespace

void SignedDistance::sample(VoxelGrid& grid, const std::function<void(double)>& progress) const {
  prepare(grid, "sample");
  const auto& n = grid.dims;
  for_each_slab(n[2], progress, [&](Index k) {
    Index hint = kNoIndex;
    for (Index j = 0; j < n[1]; ++j)
      for (Index step = 0; step < n[0]; ++step) {
        const Index i = j % 2 ? n[0] - 1 - step : step;
        grid.values[grid.index(i, j, k)] = static_cast<float>(data_->at(grid.point(i, j, k), hint));
      }
  });
}

void SignedDistance::sample_band(VoxelGrid& grid, double band,
                                 const std::function<void(double)>& progress) const {
  if (!(band >= 0.0)) throw std::invalid_argument("SignedDistance::sample_band: band < 0");
  prepare(grid, "sample_band");
  const auto& n = grid.dims;
  const std::array<Index, 3> bricks{(n[0] + kBrick - 1) / kBrick, (n[1] + kBrick - 1) / kBrick,
                                    (n[2] + kBrick - 1) / kBrick};
  for_each_slab(bricks[2], progress, [&](Index bk) {
    Index hint = kNoIndex;
    for (Index bj = 0; bj < bricks[1]; ++bj)
      for (Index bi = 0; bi < bricks[0]; ++bi) {
        const std::array<Index, 3> lo{bi * kBrick, bj * kBrick, bk * kBrick};
        std::array<Index, 3> hi{};
        for (int a = 0; a < 3; ++a) hi[a] = std::min(lo[a] + kBrick, n[a]) - 1;
        const Vec3 a = grid.point(lo[0], lo[1], lo[2]), b = grid.point(hi[0], hi[1], hi[2]);
        const Vec3 centre = 0.5 * (a + b);
        const double d = data_->at(centre, hint);
        const bool far = std::abs(d) > band + 0.5 * (b - a).norm();
        for (Index k = lo[2]; k <= hi[2]; ++k)
          for (Index j = lo[1]; j <= hi[1]; ++j)
            for (Index i = lo[0]; i <= hi[0]; ++i) {
              const Vec3 p = grid.point(i, j, k);
              const double v = far ? std::copysign(std::abs(d) - (p - centre).norm(), d)
                                   : data_->at(p, hint);
              grid.values[grid.index(i, j, k)] = static_cast<float>(v);
            }
      }
  });
}

}  // namespace volmesh
