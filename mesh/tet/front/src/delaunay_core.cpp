#include "delaunay_core.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Hilbert_sort_3.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>

#include "aux_grid.hpp"
#include "volmesh/core/element_mesh.hpp"

namespace volmesh::tet::front {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, K>;
using Delaunay = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb>>;
using HilbertTraits =
    CGAL::Spatial_sort_traits_adapter_3<K, CGAL::Pointer_property_map<Point>::type>;

using Tri = std::array<Index, 3>;
using Tet = std::array<Index, 4>;
using Edge = std::array<Index, 2>;
using Cell = std::array<long long, 3>;  // a lattice point's grid coordinates, at half the step

// The lattice points inside the region at least `clearance` from its faces (and, with a
// graded field, where it has grown to h), in grid order:
// the points of a grid of half the step whose three coordinates are all even (corners) or
// all odd (centres).
void lattice_points(const std::vector<Vec3>& points, const std::vector<Tri>& faces,
                    double step, double clearance, const SizeField* field, double h,
                    std::vector<Vec3>& at, std::vector<Cell>& cells) {
  const AuxGrid grid = make_aux_grid(points, faces, step / 2.0);
  Triangles triangles;
  for (const Tri& t : faces) {
    const auto p = [&](int c) {
      return Point(points[t[c]].x(), points[t[c]].y(), points[t[c]].z());
    };
    triangles.emplace_back(p(0), p(1), p(2));
  }
  const Tree tree(triangles.begin(), triangles.end());
  const double limit = clearance * clearance;
  Point hint = triangles.front()[0];
  for (long long k = 0; k < grid.n[2]; ++k)
    for (long long j = 0; j < grid.n[1]; ++j)
      for (long long i = 0; i < grid.n[0]; ++i) {
        if ((i - j) % 2 != 0 || (j - k) % 2 != 0 || !grid.alive(grid.at(i, j, k))) continue;
        const Vec3 x = grid.point(i, j, k);
        const Point q(x.x(), x.y(), x.z());
        hint = tree.closest_point(q, hint);
        if (CGAL::squared_distance(q, hint) < limit) continue;
        if (field != nullptr && field->at(x) < h) continue;
        at.push_back(x);
        cells.push_back({i, j, k});
      }
}

// Whether two lattice points are neighbours in its Delaunay tets: a cube edge (two steps of
// the half-step grid along one axis) or a corner to a centre (one step along each).
bool lattice_edge(const Cell& a, const Cell& b) {
  std::array<long long, 3> d{std::llabs(a[0] - b[0]), std::llabs(a[1] - b[1]),
                             std::llabs(a[2] - b[2])};
  std::sort(d.begin(), d.end());
  return d == std::array<long long, 3>{0, 0, 2} || d == std::array<long long, 3>{1, 1, 1};
}

// The Delaunay tets of the points whose six edges are lattice edges: the lattice's own tets,
// those whose four corners are all present (any other tet of the Delaunay spans a missing
// point, near the boundary or outside). Positive, sorted.
std::vector<Tet> lattice_tets(const std::vector<Vec3>& at, const std::vector<Cell>& cells) {
  std::vector<Point> points;
  for (const Vec3& x : at) points.emplace_back(x.x(), x.y(), x.z());
  // A Hilbert order without randomness (the median policy, no shuffle), each point inserted
  // from its predecessor's cell.
  // (Hilbert_sort_3 itself: CGAL::hilbert_sort shuffles first.)
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  CGAL::Hilbert_sort_3<HilbertTraits, CGAL::Hilbert_sort_median_policy>(
      HilbertTraits(CGAL::make_property_map(points)))(order.begin(), order.end());
  Delaunay dt;
  Delaunay::Cell_handle hint;
  for (const std::size_t v : order) {
    const Delaunay::Vertex_handle handle = dt.insert(points[v], hint);
    handle->info() = static_cast<Index>(v);
    hint = handle->cell();
  }
  std::vector<Tet> tets;
  // CGAL's cells are positively oriented.
  for (const Delaunay::Cell_handle c : dt.finite_cell_handles()) {
    const Tet t{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
                c->vertex(3)->info()};
    bool lattice = true;
    for (int a = 0; a < 4 && lattice; ++a)
      for (int b = a + 1; b < 4 && lattice; ++b) lattice = lattice_edge(cells[t[a]], cells[t[b]]);
    if (!lattice) continue;
    // The least corner first, the orientation kept.
    const int m = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
    tets.push_back(m % 2 == 0 ? Tet{t[m], t[(m + 1) % 4], t[(m + 2) % 4], t[(m + 3) % 4]}
                              : Tet{t[m], t[(m + 2) % 4], t[(m + 1) % 4], t[(m + 3) % 4]});
  }
  std::sort(tets.begin(), tets.end());
  return tets;
}

Tri sorted(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
}

// The faces of the tets that no other tet shares, each facing out of its tet.
std::vector<Tri> boundary_faces(const std::vector<Tet>& tets) {
  std::vector<std::pair<Tri, Tri>> all;  // (corners sorted, face)
  for (const Tet& t : tets)
    for (const auto& f : kTetFaces) {
      const Tri face{t[f[0]], t[f[1]], t[f[2]]};
      all.emplace_back(sorted(face), face);
    }
  std::sort(all.begin(), all.end());
  std::vector<Tri> out;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t e = i + 1;
    while (e < all.size() && all[e].first == all[i].first) ++e;
    if (e - i == 1) out.push_back(all[i].second);
    i = e;
  }
  return out;
}

// The vertices and edges where the boundary is not a 2-manifold: an edge of more than two
// boundary faces, a vertex whose boundary faces make more than one fan.
std::pair<std::vector<Index>, std::vector<Edge>> singular(const std::vector<Tri>& boundary) {
  std::vector<Edge> edges;
  // (vertex, the opposite edge of one of its faces): the vertex's link.
  std::vector<std::pair<Index, Edge>> link;
  for (const Tri& t : boundary)
    for (int c = 0; c < 3; ++c) {
      const Index a = t[c], b = t[(c + 1) % 3], o = t[(c + 2) % 3];
      edges.push_back({std::min(a, b), std::max(a, b)});
      link.push_back({o, {a, b}});
    }
  std::sort(edges.begin(), edges.end());
  std::vector<Edge> bad_edges;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t e = i + 1;
    while (e < edges.size() && edges[e] == edges[i]) ++e;
    if (e - i > 2) bad_edges.push_back(edges[i]);
    i = e;
  }
  // Around a vertex whose edges are manifold, each link vertex has two link edges: the link is
  // one cycle (one fan) when following it from any link edge visits all of them.
  std::sort(link.begin(), link.end());
  std::vector<Index> bad_vertices;
  for (std::size_t i = 0; i < link.size();) {
    std::size_t e = i + 1;
    while (e < link.size() && link[e].first == link[i].first) ++e;
    // The face after each: the one whose link edge starts where its link edge ends.
    std::size_t visited = 1;
    Index at = link[i].second[1];
    const Index start = link[i].second[0];
    while (at != start && visited <= e - i) {
      const auto next = std::find_if(link.begin() + static_cast<std::ptrdiff_t>(i),
                                     link.begin() + static_cast<std::ptrdiff_t>(e),
                                     [at](const auto& l) { return l.second[0] == at; });
      if (next == link.begin() + static_cast<std::ptrdiff_t>(e)) break;
      at = next->second[1];
      ++visited;
    }
    if (at != start || visited != e - i) bad_vertices.push_back(link[i].first);
    i = e;
  }
  return {bad_vertices, bad_edges};
}

// Drops the tets at singular vertices and edges of the boundary until there are none.
void make_manifold(std::vector<Tet>& tets) {
  for (;;) {
    const auto [vertices, edges] = singular(boundary_faces(tets));
    if (vertices.empty() && edges.empty()) return;
    const auto has = [](const Tet& t, Index v) {
      return std::find(t.begin(), t.end(), v) != t.end();
    };
    std::erase_if(tets, [&](const Tet& t) {
      return std::any_of(vertices.begin(), vertices.end(), [&](Index v) { return has(t, v); }) ||
             std::any_of(edges.begin(), edges.end(),
                         [&](const Edge& e) { return has(t, e[0]) && has(t, e[1]); });
    });
  }
}

}  // namespace

Core delaunay_core(const std::vector<Vec3>& points, const std::vector<Tri>& faces, double h,
                   const Progress& progress, const SizeField* field) {
  report(progress, "building the Delaunay interior", 0.0);
  std::vector<Vec3> at;
  std::vector<Cell> cells;
  lattice_points(points, faces, kLatticeStep * h, kCoreClearance * h, field, h, at, cells);
  std::vector<Tet> tets = lattice_tets(at, cells);
  make_manifold(tets);
  // The points of the tets kept, renumbered in the lattice's order.
  std::vector<Index> index(at.size(), kNoIndex);
  for (const Tet& t : tets)
    for (const Index v : t) index[v] = 0;
  Core core;
  for (std::size_t v = 0; v < at.size(); ++v)
    if (index[v] != kNoIndex) {
      index[v] = static_cast<Index>(core.points.size());
      core.points.push_back(at[v]);
    }
  for (Tet& t : tets)
    for (Index& v : t) v = index[v];
  core.faces = boundary_faces(tets);
  core.tets = std::move(tets);
  return core;
}

}  // namespace volmesh::tet::front
