// Validation of a triangulated surface as the boundary of a solid, and its measures.
#include "volmesh/geometry/surface_check.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>

#include "triangle_predicates.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/geometry/self_intersections.hpp"

namespace volmesh {

namespace {

// The triangles a non-manifold edge's message lists, at most.
constexpr std::size_t kListedTriangles = 5;

// One side of a triangle. Uses are grouped by edge, in triangle order within an edge, which
// keeps every result independent of hashing or sorting details.
struct EdgeUse {
  std::uint64_t key;  // lower vertex << 32 | higher vertex
  Index triangle;
  bool forward;  // the triangle runs along it from the lower vertex to the higher
};

// Counting sort by lower vertex (linear time), then each vertex's few uses by higher vertex.
std::vector<EdgeUse> edge_uses(const TriSurface& surface) {
  auto sides = [&](auto f) {
    for (Index t = 0; t < surface.num_triangles(); ++t)
      for (int k = 0; k < 3; ++k) {
        const Index a = surface.triangles[t][k], b = surface.triangles[t][(k + 1) % 3];
        f(t, std::min(a, b), std::max(a, b), a < b);
      }
  };
  std::vector<std::size_t> begin(surface.points.size() + 1, 0);
  sides([&](Index, Index lo, Index, bool) { ++begin[lo + 1]; });
  std::partial_sum(begin.begin(), begin.end(), begin.begin());
  std::vector<EdgeUse> uses(3 * surface.triangles.size());
  std::vector<std::size_t> next(begin.begin(), begin.end() - 1);
  sides([&](Index t, Index lo, Index hi, bool forward) {
    uses[next[lo]++] = {static_cast<std::uint64_t>(lo) << 32 | static_cast<std::uint64_t>(hi), t,
                        forward};
  });
  for (std::size_t v = 0; v + 1 < begin.size(); ++v)
    std::sort(uses.data() + begin[v], uses.data() + begin[v + 1],
              [](const EdgeUse& x, const EdgeUse& y) {
                return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
              });
  return uses;
}

// Calls f with the uses of each edge in turn.
template <class F>
void for_each_edge(const std::vector<EdgeUse>& uses, F f) {
  std::size_t begin = 0;
  while (begin < uses.size()) {
    std::size_t end = begin + 1;
    while (end < uses.size() && uses[end].key == uses[begin].key) ++end;
    f(std::span<const EdgeUse>(uses.data() + begin, end - begin));
    begin = end;
  }
}

std::string edge_name(std::uint64_t key) {
  return "edge " + std::to_string(key >> 32) + "-" + std::to_string(key & 0xffffffffu);
}

// Every edge of a closed, consistently oriented surface is run along once in each direction.
// Reports the first non-manifold edge, else the first boundary edge, else the first
// orientation conflict.
void check_edges(const std::vector<EdgeUse>& uses, const std::string& source) {
  std::span<const EdgeUse> non_manifold, inconsistent;
  const EdgeUse* boundary = nullptr;
  std::size_t boundary_edges = 0;
  for_each_edge(uses, [&](std::span<const EdgeUse> edge) {
    if (edge.size() > 2 && non_manifold.empty()) non_manifold = edge;
    if (edge.size() == 1 && boundary_edges++ == 0) boundary = &edge[0];
    if (edge.size() == 2 && edge[0].forward == edge[1].forward && inconsistent.empty())
      inconsistent = edge;
  });
  if (!non_manifold.empty()) {
    std::string triangles;
    for (const EdgeUse& u : non_manifold.first(std::min(non_manifold.size(), kListedTriangles)))
      triangles += (triangles.empty() ? "" : ", ") + std::to_string(u.triangle);
    if (non_manifold.size() > kListedTriangles) triangles += ", ...";
    throw InputError(source + ": " + edge_name(non_manifold[0].key) + ": non-manifold, shared by " +
                     std::to_string(non_manifold.size()) + " triangles (" + triangles +
                     "); a closed surface has exactly two per edge");
  }
  if (boundary)
    throw InputError(source + ": " + edge_name(boundary->key) + " of triangle " +
                     std::to_string(boundary->triangle) +
                     ": boundary edge, the surface has a hole (" + std::to_string(boundary_edges) +
                     " boundary edges in all)");
  if (!inconsistent.empty()) {
    const std::uint64_t lo = inconsistent[0].key >> 32, hi = inconsistent[0].key & 0xffffffffu;
    const bool forward = inconsistent[0].forward;
    throw InputError(source + ": triangle " + std::to_string(inconsistent[1].triangle) +
                     ": orientation inconsistent with triangle " +
                     std::to_string(inconsistent[0].triangle) + " (both run along " +
                     edge_name(inconsistent[0].key) + " from " + std::to_string(forward ? lo : hi) +
                     " to " + std::to_string(forward ? hi : lo) + ")");
  }
}

// Components connected through edges, by union-find over the triangles around each edge.
Index count_components(const std::vector<EdgeUse>& uses, Index num_triangles) {
  std::vector<Index> parent(num_triangles);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for_each_edge(uses, [&](std::span<const EdgeUse> edge) {
    for (const EdgeUse& u : edge.subspan(1)) parent[root(u.triangle)] = root(edge[0].triangle);
  });
  Index components = 0;
  for (Index t = 0; t < num_triangles; ++t) components += root(t) == t;
  return components;
}

void check_points_finite(const TriSurface& surface, const std::string& source) {
  for (Index i = 0; i < surface.num_points(); ++i) {
    const Vec3& p = surface.points[i];
    if (!p.allFinite()) {
      std::string coordinates;
      for (int k = 0; k < 3; ++k) {
        char digits[32];  // shortest text that reads back to the same double
        if (k > 0) coordinates += ' ';
        coordinates.append(digits, std::to_chars(digits, digits + sizeof digits, p[k]).ptr);
      }
      throw InputError(source + ": vertex " + std::to_string(i) + ": coordinate is not finite (" +
                       coordinates + ")");
    }
  }
}

void check_not_degenerate(const TriSurface& surface, const std::string& source) {
  for (Index t = 0; t < surface.num_triangles(); ++t) {
    const auto& tri = surface.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] == tri[(k + 1) % 3])
        throw InputError(source + ": triangle " + std::to_string(t) + ": degenerate, vertex " +
                         std::to_string(tri[k]) + " appears twice");
  }
  if (auto t = geometry_detail::first_collinear_triangle(surface)) {
    const auto& tri = surface.triangles[*t];
    throw InputError(source + ": triangle " + std::to_string(*t) + ": degenerate, its vertices " +
                     std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + ", " +
                     std::to_string(tri[2]) + " are collinear");
  }
}

// Bounding box of the used points, area, and enclosed volume by the divergence theorem
// (tetrahedra from the box centre, which keeps the sum well conditioned).
void measure(const TriSurface& surface, SurfaceReport& report) {
  std::vector<char> used(surface.points.size(), 0);
  for (const auto& t : surface.triangles)
    for (Index v : t) used[v] = 1;
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (Index i = 0; i < surface.num_points(); ++i) {
    if (!used[i]) {
      ++report.unused_points;
      continue;
    }
    lo = lo.cwiseMin(surface.points[i]);
    hi = hi.cwiseMax(surface.points[i]);
  }
  report.bbox_min = lo;
  report.bbox_max = hi;
  const Vec3 centre = (lo + hi) / 2;
  double area = 0, six_volume = 0;
  for (const auto& t : surface.triangles) {
    const Vec3 a = surface.points[t[0]] - centre, b = surface.points[t[1]] - centre,
               c = surface.points[t[2]] - centre;
    area += (b - a).cross(c - a).norm();
    six_volume += a.dot(b.cross(c));
  }
  report.area = area / 2;
  report.volume = six_volume / 6;
}

}  // namespace

SurfaceReport check_surface(TriSurface& surface, const std::string& source,
                            const SurfaceCheckOptions& options) {
  if (surface.triangles.empty()) throw InputError(source + ": surface has no triangles");
  require_valid_indices(surface, source);
  check_points_finite(surface, source);
  check_not_degenerate(surface, source);
  const std::vector<EdgeUse> uses = edge_uses(surface);
  check_edges(uses, source);

  SurfaceReport report;
  report.points = surface.num_points();
  report.triangles = surface.num_triangles();
  report.components = count_components(uses, surface.num_triangles());
  measure(surface, report);
  if (report.volume < 0) {
    for (auto& t : surface.triangles) std::swap(t[1], t[2]);
    report.volume = -report.volume;
    report.flipped = true;
    report.warnings.push_back(source + ": the surface was oriented inward; all triangles flipped");
  }
  if (report.unused_points > 0)
    report.warnings.push_back(source + ": " + std::to_string(report.unused_points) +
                              " points are not used by any triangle");
  if (options.find_self_intersections) {
    report.self_intersections = find_self_intersections(surface, options.max_self_intersections,
                                                        &report.self_intersections_truncated);
    if (!report.self_intersections.empty())
      report.warnings.push_back(
          source + ": triangles " + std::to_string(report.self_intersections[0].first) + " and " +
          std::to_string(report.self_intersections[0].second) + " intersect (" +
          std::to_string(report.self_intersections.size()) +
          (report.self_intersections_truncated ? " or more" : "") + " intersecting pairs)");
  }
  return report;
}

}  // namespace volmesh
