// Self-intersections of a triangle soup with CGAL's exact predicates. CGAL 5.5 has no soup
// version of Polygon_mesh_processing::self_intersections, and its mesh version needs a valid
// halfedge structure, which non-manifold vertices or duplicate triangles do not give. So this
// runs PMP's algorithm on the soup itself: candidate pairs from box_self_intersection_d, then
// PMP's test for triangles sharing an edge, a vertex or nothing. Pairs are in the input
// numbering. This is the only translation unit that includes CGAL (it is slow to compile).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>

#include "triangle_predicates.hpp"
#include "volmesh/geometry/self_intersections.hpp"

namespace volmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Segment = Kernel::Segment_3;
using Box =
    CGAL::Box_intersection_d::Box_with_info_d<double, 3, Index,
                                              CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;

// box_self_intersection_d's cutoff (below it, boxes are compared pairwise): Polygon_mesh_
// processing's own choice for its self-intersection test, faster than the default 10.
constexpr std::ptrdiff_t kBoxCutoff = 2000;

Point point(const TriSurface& surface, Index v) {
  const Vec3& p = surface.points[v];
  return {p.x(), p.y(), p.z()};
}

bool collinear(const TriSurface& surface, const std::array<Index, 3>& t) {
  return CGAL::collinear(point(surface, t[0]), point(surface, t[1]), point(surface, t[2]));
}

// True if two non-degenerate triangles meet in more than the vertices and edge they share.
bool triangles_intersect(const TriSurface& surface, Index i, Index j) {
  const auto& a = surface.triangles[i];
  const auto& b = surface.triangles[j];
  int shared = 0, in_a[3], in_b[3];  // positions of the shared vertices in a and in b
  for (int ka = 0; ka < 3; ++ka)
    for (int kb = 0; kb < 3; ++kb)
      if (a[ka] == b[kb]) {
        in_a[shared] = ka;
        in_b[shared] = kb;
        ++shared;
      }
  auto p = [&](Index v) { return point(surface, v); };
  const Triangle ta(p(a[0]), p(a[1]), p(a[2])), tb(p(b[0]), p(b[1]), p(b[2]));
  switch (shared) {
    case 0:
      return CGAL::do_intersect(ta, tb);
    case 1: {  // they meet elsewhere iff an edge opposite the shared vertex meets the other
      const Segment sa(p(a[(in_a[0] + 1) % 3]), p(a[(in_a[0] + 2) % 3]));
      const Segment sb(p(b[(in_b[0] + 1) % 3]), p(b[(in_b[0] + 2) % 3]));
      return CGAL::do_intersect(ta, sb) || CGAL::do_intersect(tb, sa);
    }
    case 2: {  // they overlap iff coplanar with the far corners on the same side of the edge
      const Point u = p(a[in_a[0]]), v = p(a[in_a[1]]);
      const Point far_a = p(a[3 - in_a[0] - in_a[1]]), far_b = p(b[3 - in_b[0] - in_b[1]]);
      return CGAL::coplanar(u, v, far_a, far_b) &&
             CGAL::coplanar_orientation(u, v, far_a, far_b) == CGAL::POSITIVE;
    }
    default:  // the same triangle twice
      return true;
  }
}

}  // namespace

std::optional<Index> geometry_detail::first_collinear_triangle(const TriSurface& surface) {
  for (Index t = 0; t < surface.num_triangles(); ++t)
    if (collinear(surface, surface.triangles[t])) return t;
  return std::nullopt;
}

std::vector<std::pair<Index, Index>> find_self_intersections(const TriSurface& surface,
                                                             std::size_t max_pairs,
                                                             bool* truncated) {
  require_valid_indices(surface, "surface");
  // Degenerate triangles have no well-defined intersections; check_surface refuses them.
  std::vector<Box> boxes;
  boxes.reserve(surface.triangles.size());
  for (Index t = 0; t < surface.num_triangles(); ++t) {
    const auto& tri = surface.triangles[t];
    if (collinear(surface, tri)) continue;
    boxes.emplace_back(point(surface, tri[0]).bbox() + point(surface, tri[1]).bbox() +
                           point(surface, tri[2]).bbox(),
                       t);
  }
  std::vector<const Box*> box_pointers;
  box_pointers.reserve(boxes.size());
  for (const Box& b : boxes) box_pointers.push_back(&b);

  std::vector<std::pair<Index, Index>> pairs;
  bool more = false;
  struct Enough {};  // stops the search once max_pairs are found and one more exists
  try {
    CGAL::box_self_intersection_d(
        box_pointers.begin(), box_pointers.end(),
        [&](const Box* a, const Box* b) {
          const Index i = a->info(), j = b->info();
          if (!triangles_intersect(surface, i, j)) return;
          if (pairs.size() == max_pairs) {
            more = true;
            throw Enough{};
          }
          pairs.emplace_back(std::min(i, j), std::max(i, j));
        },
        kBoxCutoff);
  } catch (const Enough&) {
  }
  std::sort(pairs.begin(), pairs.end());
  if (truncated) *truncated = more;
  return pairs;
}

}  // namespace volmesh
