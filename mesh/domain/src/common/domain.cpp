// Batch queries: in parallel through TBB; each result is written at its own index, so the
// output does not depend on the thread count or the scheduling.
#include "volmesh/domain/domain.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include <stdexcept>

namespace volmesh {
namespace {

template <class Body>
void for_each_index(std::size_t n, std::size_t grain, Body&& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
                    });
}

}  // namespace

void Domain::region(std::span<const Vec3> points, std::span<Index> out) const {
  if (points.size() != out.size())
    throw std::invalid_argument("Domain::region: points and out differ in size");
  for_each_index(points.size(), 1024, [&](std::size_t i) { out[i] = region(points[i]); });
}

void Domain::crossings(std::span<const Vec3> a, std::span<const Vec3> b,
                       std::vector<std::vector<Crossing>>& out) const {
  if (a.size() != b.size())
    throw std::invalid_argument("Domain::crossings: a and b differ in size");
  out.resize(a.size());
  for_each_index(a.size(), 64, [&](std::size_t i) { out[i] = crossings(a[i], b[i]); });
}

}  // namespace volmesh
