// A mesh's boundaries and interfaces against the true analytic surfaces: two-sided Hausdorff
// distance by dense sampling (CGAL's AABB tree for the distance to the mesh), region
// volumes, and the observed order of convergence.
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_reduce.h>

#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "geometric_error.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh::geometry {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalTriangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<CgalTriangle>::const_iterator;
using Tree = CGAL::AABB_tree<
    CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>>>;

using Triangle = std::array<Vec3, 3>;

// Boundary faces and faces between two regions, split around their vertex average (the
// triangles of cut faces stay as they are).
std::vector<Triangle> interface_triangles(const PolyMesh& mesh) {
  std::vector<Triangle> out;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const bool interface = mesh.is_boundary(f) ||
                           mesh.cell_region[mesh.owner[f]] != mesh.cell_region[mesh.neighbour[f]];
    if (!interface) continue;
    const std::span<const Index> loop = mesh.face(f);
    if (loop.size() == 3) {
      out.push_back({mesh.points[loop[0]], mesh.points[loop[1]], mesh.points[loop[2]]});
      continue;
    }
    Vec3 centre = Vec3::Zero();
    for (const Index v : loop) centre += mesh.points[v];
    centre /= static_cast<double>(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i)
      out.push_back({mesh.points[loop[i]], mesh.points[loop[(i + 1) % loop.size()]], centre});
  }
  return out;
}

// Barycentric grid of order n on the triangle: its vertices, edge points (midpoints when n is
// even) and interior points; plus the centroid.
void triangle_samples(const Triangle& t, double spacing, std::vector<Vec3>& out) {
  const double longest =
      std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
  int n = std::max(2, static_cast<int>(std::ceil(longest / spacing)));
  n += n % 2;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      out.push_back(t[0] + (t[1] - t[0]) * (double(i) / n) + (t[2] - t[0]) * (double(j) / n));
  out.push_back((t[0] + t[1] + t[2]) / 3.0);
}

// The largest error, its sample count and place, per slot: slot 0 takes every sample, slot
// 1 + i those near primitive i's sharp edges.
struct Slot {
  double max = 0.0;
  Index count = 0;
  Vec3 at = Vec3::Zero();
  void add(double error, const Vec3& p) {
    if (error > max) std::tie(max, at) = std::pair(error, p);
    ++count;
  }
  // Ties go to the left operand, so that the result does not depend on the thread count.
  void join(const Slot& other) {
    if (other.max > max) std::tie(max, at) = std::pair(other.max, other.at);
    count += other.count;
  }
};
using Slots = std::vector<Slot>;

// Slots joined over items [0, n), each item's samples added by visit(i, slots); both cores.
Slots parallel_worst(std::size_t n, std::size_t slots,
                     const std::function<void(std::size_t, Slots&)>& visit) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, 256), Slots(slots),
      [&](const tbb::blocked_range<std::size_t>& range, Slots w) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) visit(i, w);
        return w;
      },
      [](Slots a, const Slots& b) {
        for (std::size_t k = 0; k < a.size(); ++k) a[k].join(b[k]);
        return a;
      });
}

}  // namespace

HausdorffReport hausdorff(const PolyMesh& mesh, const AnalyticDomain& domain,
                          const HausdorffOptions& options) {
  if (!(options.spacing > 0.0)) throw std::invalid_argument("hausdorff: spacing must be > 0");
  const std::span<const Primitive> primitives = domain.primitives();
  const auto to_surface = [&](const Vec3& p) {
    double d = std::numeric_limits<double>::infinity();
    for (const Primitive& primitive : primitives) d = std::min(d, surface_distance(primitive, p));
    return d;
  };
  // The sample's error into slot 0 and the slots of the primitives whose edges are near.
  const auto add = [&](Slots& slots, double error, const Vec3& p) {
    slots[0].add(error, p);
    if (!(options.feature_band > 0.0)) return;
    for (std::size_t i = 0; i < primitives.size(); ++i)
      if (feature_distance(primitives[i], p) <= options.feature_band) slots[1 + i].add(error, p);
  };

  const std::vector<Triangle> triangles = interface_triangles(mesh);
  if (triangles.empty()) throw std::invalid_argument("hausdorff: the mesh has no boundary");
  std::vector<Vec3> surface_points;
  for (const Primitive& primitive : primitives)
    for (const SurfacePoint& s : sample_surface(primitive, options.spacing))
      surface_points.push_back(s.point);
  const std::size_t slots = 1 + primitives.size();

  // Mesh -> surface: the mesh samples are made per triangle, never all stored.
  const Slots from_mesh = parallel_worst(triangles.size(), slots, [&](std::size_t i, Slots& w) {
    thread_local std::vector<Vec3> samples;
    samples.clear();
    triangle_samples(triangles[i], options.spacing, samples);
    for (const Vec3& p : samples) add(w, to_surface(p), p);
  });

  std::vector<CgalTriangle> cgal_triangles;
  cgal_triangles.reserve(triangles.size());
  const auto point = [](const Vec3& p) { return Kernel::Point_3(p.x(), p.y(), p.z()); };
  for (const Triangle& t : triangles)
    cgal_triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  Tree tree(cgal_triangles.begin(), cgal_triangles.end());
  tree.build();
  tree.accelerate_distance_queries();
  // The first distance query builds the search structure: do it before the threads share it.
  tree.squared_distance(point(triangles[0][0]));
  const Slots from_surface =
      parallel_worst(surface_points.size(), slots, [&](std::size_t i, Slots& w) {
        add(w, std::sqrt(tree.squared_distance(point(surface_points[i]))), surface_points[i]);
      });

  const auto one_sided = [&](std::size_t k) {
    return OneSided{from_mesh[k].max, from_surface[k].max, from_mesh[k].count,
                    from_surface[k].count, from_mesh[k].at, from_surface[k].at};
  };
  HausdorffReport report;
  report.all = one_sided(0);
  for (std::size_t i = 0; i < primitives.size(); ++i) report.features.push_back(one_sided(1 + i));
  return report;
}

std::map<Index, double> region_volumes(const PolyMesh& mesh) {
  const MeshGeometry geometry = mesh_geometry(mesh, build_cell_faces(mesh));
  std::map<Index, double> out;
  for (Index c = 0; c < mesh.num_cells(); ++c) out[mesh.cell_region[c]] += geometry.cells[c].volume;
  return out;
}

double convergence_slope(const std::vector<double>& h, const std::vector<double>& error) {
  if (h.size() != error.size() || h.size() < 2)
    throw std::invalid_argument("convergence_slope: needs two or more (h, error) pairs");
  double mx = 0.0, my = 0.0;
  const double n = static_cast<double>(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    mx += std::log(h[i]) / n;
    my += std::log(error[i]) / n;
  }
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    sxy += (std::log(h[i]) - mx) * (std::log(error[i]) - my);
    sxx += (std::log(h[i]) - mx) * (std::log(h[i]) - mx);
  }
  return sxy / sxx;
}

}  // namespace volmesh::geometry
