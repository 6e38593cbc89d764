// The driver of surface_distance: the mesh's faces as a triangulated surface, measured against
// the reference by bounded subdivision when it is a triangulation, by samples otherwise.
#include "volmesh/quality/surface_distance.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_reduce.h>

#include <functional>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "volmesh/core/boundary.hpp"

namespace volmesh {
namespace {

// Parts (and points of a part) handed to one task at a time.
constexpr std::size_t kGrain = 256;

void add(FarthestPoint& f, double distance, const Vec3& p) {
  if (distance > f.distance) std::tie(f.distance, f.at) = std::pair(distance, p);
  ++f.points;
}

// Ties go to the left operand, so that the result does not depend on the thread count.
void join(FarthestPoint& left, const FarthestPoint& right) {
  if (right.distance > left.distance) std::tie(left.distance, left.at) = std::pair(right.distance, right.at);
  left.points += right.points;
}

// Slot 0 takes every point, slot 1 + g those within the feature band of group g.
using Slots = std::vector<FarthestPoint>;

void join(Slots& left, const Slots& right) {
  for (std::size_t k = 0; k < left.size(); ++k) join(left[k], right[k]);
}

// Slots joined over items [0, n), each item's points added by visit(i, slots), in parallel.
Slots parallel_worst(std::size_t n, std::size_t slots,
                     const std::function<void(std::size_t, Slots&)>& visit) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, kGrain), Slots(slots),
      [&](const tbb::blocked_range<std::size_t>& range, Slots w) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) visit(i, w);
        return w;
      },
      [](Slots a, const Slots& b) {
        join(a, b);
        return a;
      });
}

// Over the samples of every part of `from`: the distance to `to`, into the slots of the
// reference's feature groups whose edges are within `band`.
Slots sampled_one_sided(const ReferenceSurface& from, const ReferenceSurface& to,
                        const ReferenceSurface& reference, const SurfaceDistanceOptions& options,
                        std::size_t slots) {
  const auto measure = [&](Slots& w, const Vec3& p) {
    const double d = to.distance(p);
    add(w[0], d, p);
    for (std::size_t g = 0; g + 1 < slots; ++g)
      if (reference.feature_distance(g, p) <= options.feature_band) add(w[1 + g], d, p);
  };
  return parallel_worst(from.num_parts(), slots, [&](std::size_t part, Slots& w) {
    // Made per part, never all stored: a fine mesh has tens of millions of samples.
    std::vector<Vec3> samples;
    from.sample(part, options.tolerance, samples);
    if (samples.size() <= kGrain) {
      for (const Vec3& p : samples) measure(w, p);
      return;
    }
    join(w, parallel_worst(samples.size(), slots,
                           [&](std::size_t i, Slots& v) { measure(v, samples[i]); }));
  });
}

SurfaceDistance sampled_distance(const TriangulatedSurface& mesh, const ReferenceSurface& reference,
                                 const SurfaceDistanceOptions& options) {
  const std::size_t groups = options.feature_band > 0.0 ? reference.feature_groups().size() : 0;
  const Slots from_mesh = sampled_one_sided(mesh, reference, reference, options, 1 + groups);
  const Slots from_surface = sampled_one_sided(reference, mesh, reference, options, 1 + groups);
  SurfaceDistance d;
  d.all = {from_mesh[0], from_surface[0]};
  for (std::size_t g = 0; g < groups; ++g) d.features.push_back({from_mesh[1 + g], from_surface[1 + g]});
  return d;
}

}  // namespace

double ReferenceSurface::feature_distance(std::size_t, const Vec3&) const {
  return std::numeric_limits<double>::infinity();
}

SurfaceDistance surface_distance(const PolyMesh& mesh, const ReferenceSurface& reference,
                                 const SurfaceDistanceOptions& options) {
  if (!(options.tolerance > 0.0))
    throw std::invalid_argument("surface_distance: the tolerance must be > 0");
  TriSurface faces = options.interfaces ? region_boundary_surface(mesh) : boundary_surface(mesh);
  if (faces.triangles.empty())
    throw std::invalid_argument("surface_distance: the mesh has no boundary faces");
  const TriangulatedSurface measured(std::move(faces));
  if (const TriangulatedSurface* triangles = reference.triangulation()) {
    SurfaceDistance d;
    d.all = {triangles->farthest_from(measured.surface(), options.tolerance),
             measured.farthest_from(triangles->surface(), options.tolerance)};
    return d;
  }
  return sampled_distance(measured, reference, options);
}

}  // namespace volmesh
