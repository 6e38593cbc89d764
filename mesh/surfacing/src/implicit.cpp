#include "volmesh/surfacing/implicit.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>

#include "volmesh/core/errors.hpp"

namespace volmesh::surfacing {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using LabelledDomain = CGAL::Labeled_mesh_domain_3<K>;

// Mesh_3's facet criteria: the angle bound and the surface Delaunay ball radius for edge h
// (an equilateral triangle of edge h has circumradius h / √3).
constexpr double kFacetAngleDegrees = 30.0;
const double kBallRadiusPerEdge = 1.0 / std::sqrt(3.0);
// The chordal distance bound, relative to h: inactive where the curvature radius exceeds
// about h (the sagitta of a chord h is h² / 8R), refining where the surface bends sharper.
constexpr double kDistancePerEdge = 0.1;
// Seed lines per axis direction (kSeedLines² lines along each axis), and the margin by which
// they reach beyond the bounds so that their ends lie outside every region.
constexpr int kSeedLines = 5;
constexpr double kSeedMargin = 0.05;
// More triangles than this over the bounds' surface area at edge h: h is absurdly small.
constexpr double kMaxFacets = 5e7;

// Labeled_mesh_domain_3 starting from given surface points instead of random rays from the
// bounds' centre. make_mesh_3 calls construct_initial_points_object() on the domain type it
// is given, so this one hides the base's.
class SeededDomain : public LabelledDomain {
 public:
  using Seeds = std::vector<std::pair<Point, LabelledDomain::Index>>;
  SeededDomain(LabelledDomain base, Seeds seeds)
      : LabelledDomain(std::move(base)), seeds_(std::move(seeds)) {}

  struct Construct_initial_points {
    const Seeds* seeds;
    template <class Out>
    Out operator()(Out out, int = 0) const {
      for (const auto& s : *seeds) *out++ = s;
      return out;
    }
  };
  Construct_initial_points construct_initial_points_object() const { return {&seeds_}; }

 private:
  Seeds seeds_;
};

using Tr = CGAL::Mesh_triangulation_3<SeededDomain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

Vec3 to_vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

std::string number_text(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// Interface crossings on kSeedLines² lines along each axis, at least h apart.
SeededDomain::Seeds seeds(const Domain& domain, const LabelledDomain& labelled, double h) {
  const Box3 box = domain.bounds();
  const Vec3 margin = kSeedMargin * box.size() + Vec3::Constant(h);
  const Vec3 lo = box.lo - margin, hi = box.hi + margin;
  SeededDomain::Seeds out;
  std::vector<Vec3> taken;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int i = 1; i <= kSeedLines; ++i)
      for (int j = 1; j <= kSeedLines; ++j) {
        Vec3 a = lo, b = lo;
        a[u] = b[u] = lo[u] + (hi[u] - lo[u]) * i / (kSeedLines + 1);
        a[v] = b[v] = lo[v] + (hi[v] - lo[v]) * j / (kSeedLines + 1);
        b[axis] = hi[axis];
        for (const Crossing& c : domain.crossings(a, b)) {
          if (c.before == c.after) continue;
          bool near = false;
          for (const Vec3& t : taken) near = near || (t - c.point).norm() < h;
          if (near) continue;
          taken.push_back(c.point);
          out.emplace_back(Point(c.point.x(), c.point.y(), c.point.z()),
                           labelled.index_from_surface_patch_index(
                               {static_cast<int>(c.before), static_cast<int>(c.after)}));
        }
      }
  }
  return out;
}

Index find(std::vector<Index>& parent, Index i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<InterfaceSurface> mesh_interfaces(const Domain& domain, double h) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw InputError("surface meshing: the size " + number_text(h) +
                     " must be positive and finite");
  const Box3 box = domain.bounds();
  const Vec3 e = box.size();
  const double box_area = 2.0 * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
  if (box_area / (h * h) > kMaxFacets)
    throw InputError("surface meshing: the size " + number_text(h) +
                     " is too small for the domain's bounds (more than 5e7 triangles)");
  const Vec3 pad = kSeedMargin * e + Vec3::Constant(h);
  const Vec3 lo = box.lo - pad, hi = box.hi + pad;
  const std::function<int(const Point&)> label = [&domain](const Point& p) {
    return static_cast<int>(domain.region(to_vec(p)));
  };
  LabelledDomain labelled(label, CGAL::Bbox_3(lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()),
                          kRelativeError);
  SeededDomain::Seeds start = seeds(domain, labelled, h);
  if (start.empty())
    throw InputError("surface meshing: no interface found inside the domain's bounds");
  const SeededDomain seeded(std::move(labelled), std::move(start));
  namespace params = CGAL::parameters;
  const Criteria criteria(params::facet_angle = kFacetAngleDegrees,
                          params::facet_size = kBallRadiusPerEdge * h,
                          params::facet_distance = kDistancePerEdge * h);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(seeded, criteria, params::no_perturb(),
                                            params::no_exude(), params::manifold());
  const Tr& tr = c3t3.triangulation();
  const auto label_of = [&](Tr::Cell_handle c) {
    return c3t3.is_in_complex(c) ? static_cast<Index>(c3t3.subdomain_index(c)) : Index{0};
  };

  // Facets oriented out of the side with the larger label; vertices numbered as met.
  struct Facet {
    std::array<Index, 3> v;
    Index high, low;  // the labels of the side the normal leaves and of the side it enters
  };
  std::vector<Facet> facets;
  std::vector<Vec3> points;
  std::map<Tr::Vertex_handle, Index> number;
  for (auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    Tr::Facet facet = *f;
    if (tr.is_infinite(facet.first)) facet = tr.mirror_facet(facet);
    const Tr::Cell_handle c = facet.first;
    const int i = facet.second;
    std::array<Tr::Vertex_handle, 3> v{c->vertex((i + 1) & 3), c->vertex((i + 2) & 3),
                                       c->vertex((i + 3) & 3)};
    // Normal out of c: its opposite corner on the negative side.
    if (CGAL::orientation(v[0]->point().point(), v[1]->point().point(), v[2]->point().point(),
                          c->vertex(i)->point().point()) == CGAL::POSITIVE)
      std::swap(v[1], v[2]);
    const Index inner = label_of(c), outer = label_of(tr.mirror_facet(facet).first);
    if (inner < outer) std::swap(v[1], v[2]);
    Facet out{{}, std::max(inner, outer), std::min(inner, outer)};
    for (int k = 0; k < 3; ++k) {
      const auto [at, added] = number.emplace(v[k], static_cast<Index>(points.size()));
      if (added) points.push_back(to_vec(v[k]->point().point()));
      out.v[k] = at->second;
    }
    facets.push_back(out);
  }

  // Connected components through shared vertices, numbered by their first facet.
  std::vector<Index> parent(points.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const Facet& f : facets)
    for (int k = 1; k < 3; ++k) parent[find(parent, f.v[k])] = find(parent, f.v[0]);
  std::map<Index, std::size_t> component;
  std::vector<InterfaceSurface> out;
  std::vector<std::vector<Index>> local;  // per component: point -> its index there, or -1
  for (const Facet& f : facets) {
    const auto [at, added] = component.emplace(find(parent, f.v[0]), out.size());
    if (added) {
      out.push_back({{}, f.high, f.low});
      local.emplace_back(points.size(), -1);
    }
    InterfaceSurface& s = out[at->second];
    if (s.inside != f.high || s.outside != f.low)
      throw InputError("surface meshing: interfaces between more than two regions meet (" +
                       std::to_string(s.inside) + "|" + std::to_string(s.outside) + " and " +
                       std::to_string(f.high) + "|" + std::to_string(f.low) +
                       "); only nested, disjoint surfaces can be triangulated");
    std::array<Index, 3> t{};
    for (int k = 0; k < 3; ++k) {
      Index& n = local[at->second][f.v[k]];
      if (n < 0) {
        n = s.surface.num_points();
        s.surface.points.push_back(points[f.v[k]]);
      }
      t[k] = n;
    }
    s.surface.triangles.push_back(t);
  }
  // A component enclosing a negative volume has the larger label outside it.
  for (InterfaceSurface& s : out) {
    double volume = 0.0;
    for (const auto& t : s.surface.triangles)
      volume += s.surface.points[t[0]].dot(s.surface.points[t[1]].cross(s.surface.points[t[2]]));
    if (volume >= 0.0) continue;
    std::swap(s.inside, s.outside);
    for (auto& t : s.surface.triangles) std::swap(t[1], t[2]);
  }
  return out;
}

}  // namespace volmesh::surfacing
