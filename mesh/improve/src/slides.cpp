#include "volmesh/improve/slides.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <iterator>

namespace volmesh::improve {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

Point cg(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
Vec3 vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

// Whether p lies on the closed segment ab, exactly.
bool on_segment(const Point& a, const Point& b, const Point& p) {
  return CGAL::collinear(a, b, p) && CGAL::collinear_are_ordered_along_line(a, p, b);
}

// Where p may slide on the triangles holding it (each exactly).
Slide slide_among(const std::vector<K::Triangle_3>& holding, const Point& p) {
  Slide none;
  for (const auto& t : holding)
    for (int k = 0; k < 3; ++k)
      if (t.vertex(k) == p) return none;  // a surface vertex stays
  const K::Triangle_3& t = holding.front();
  for (int k = 0; k < 3; ++k) {
    const Point &a = t.vertex(k), &b = t.vertex((k + 1) % 3);
    if (on_segment(a, b, p)) return {SlideKind::Line, {vec(a), vec(b), vec(b)}};
  }
  if (holding.size() != 1) return none;  // inside several: the surface overlaps itself
  return {SlideKind::Plane, {vec(t.vertex(0)), vec(t.vertex(1)), vec(t.vertex(2))}};
}

}  // namespace

std::vector<Slide> slides_on_surface(const TetMesh& mesh, const TriSurface& surface) {
  Triangles triangles;
  for (const auto& t : surface.triangles) {
    K::Triangle_3 tri(cg(surface.points[t[0]]), cg(surface.points[t[1]]), cg(surface.points[t[2]]));
    if (!tri.is_degenerate()) triangles.push_back(tri);
  }
  std::vector<Slide> slides(mesh.points.size());
  if (triangles.empty()) return slides;
  const Tree tree(triangles.begin(), triangles.end());
  std::vector<char> done(mesh.points.size(), 0);
  for (const auto& f : mesh.boundary_faces)
    for (const Index v : f) {
      if (done[v]) continue;
      done[v] = 1;
      const Point p = cg(mesh.points[v]);
      std::vector<Primitive::Id> hits;
      tree.all_intersected_primitives(p, std::back_inserter(hits));
      std::sort(hits.begin(), hits.end());
      std::vector<K::Triangle_3> holding;
      for (const auto& id : hits) holding.push_back(*id);
      if (!holding.empty()) slides[v] = slide_among(holding, p);
    }
  return slides;
}

bool stays_within(const Slide& slide, const Vec3& p) {
  const Point a = cg(slide.corners[0]), b = cg(slide.corners[1]), q = cg(p);
  if (slide.kind == SlideKind::Line) return on_segment(a, b, q);
  if (slide.kind != SlideKind::Plane) return false;
  const Point c = cg(slide.corners[2]);
  return CGAL::coplanar(a, b, c, q) && K::Triangle_3(a, b, c).has_on(q);
}

}  // namespace volmesh::improve
