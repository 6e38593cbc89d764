// Stage 4: the prisms' faces. Every surface point on the vertical line over a plane vertex
// becomes a mesh point (the heights of the vertex); over each plane edge the surface lines
// cut the vertical strip into bands, and each band is triangulated once, canonically, with
// the heights on its two sides as its only corners. Both prisms beside a side face cut it
// from the same bands, so their triangles match, and every prism's boundary is closed.
#include <algorithm>
#include <string>
#include <tuple>

#include "plane_cache.hpp"
#include "projection_data.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh::tet::detail {

namespace {

// Height over (x, y), on its projection, of the edge p -> r, which is not vertical.
Rational edge_height(const Surfaces& in, Index p, Index r, const std::array<Rational, 2>& q) {
  const RationalPoint &a = in.points[p], &b = in.points[r];
  const Rational dx = b.x - a.x, dy = b.y - a.y;
  return a.z + (b.z - a.z) * ((q[0] - a.x) * dx + (q[1] - a.y) * dy) / (dx * dx + dy * dy);
}

// Heights of WALL triangle w over plane vertex q (at xy) of its projection: where its edges
// pass over q.
void wall_heights(const Surfaces& in, Index w, const Point2& q, const std::array<Rational, 2>& xy,
                  std::vector<Rational>& out) {
  const auto& c = in.triangles[w];
  for (int k = 0; k < 3; ++k) {
    const Index p = c[k], r = c[(k + 1) % 3];
    const Point2 &p2 = in.projected[p], &r2 = in.projected[r];
    if (p2 == r2) {
      if (p2 == q) out.push_back(in.points[p].z);
    } else if (K::Segment_2(p2, r2).has_on(q)) {
      out.push_back(edge_height(in, p, r, xy));
    }
  }
}

bool wall_contains(const Surfaces& in, Index w, const Point2& q) {
  const auto& c = in.triangles[w];
  for (int k = 0; k < 3; ++k) {
    const Point2 &p2 = in.projected[c[k]], &r2 = in.projected[c[(k + 1) % 3]];
    if (p2 != r2 && K::Segment_2(p2, r2).has_on(q)) return true;
  }
  return false;
}

// A surface line over a plane edge: the places of its heights in the height lists of the
// edge's lower- and higher-numbered ends, and the triangles along it. Lines over an edge
// do not cross, so ordering them by (at_lo, at_hi) orders them upwards.
struct Line {
  Index at_lo = 0, at_hi = 0;
  std::vector<Index> owners;
};

[[noreturn]] void crossing(const Point2& q) {
  throw InputError("the surfaces cross or self-intersect over the point (" +
                   std::to_string(CGAL::to_double(q.x())) + ", " +
                   std::to_string(CGAL::to_double(q.y())) + ") of the projection plane");
}

Index place_of(const std::vector<Height>& heights, const Rational& z) {
  const auto it = std::lower_bound(heights.begin(), heights.end(), z,
                                   [](const Height& h, const Rational& v) { return h.z < v; });
  return static_cast<Index>(it - heights.begin());
}

class Stitcher {
 public:
  explicit Stitcher(State& state) : s_(state), in_(state.input), walls_(wall_rectangles()) {}

  void run() {
    collect_heights();
    s_.prism_boundary.assign(s_.prisms.size(), {});
    for (std::size_t p = 0; p < s_.prisms.size(); ++p) caps(static_cast<Index>(p));
    for (auto e = s_.plane.finite_edges_begin(); e != s_.plane.finite_edges_end(); ++e)
      strip(e->first, e->second);
  }

 private:
  State& s_;
  const Surfaces& in_;
  PlaneCache walls_;
  // Per vertex: (sloped triangle, its place in the vertex's heights), by triangle.
  std::vector<std::vector<std::pair<Index, Index>>> places_;

  PlaneCache wall_rectangles() {
    std::vector<Rectangle> r;
    for (Index t = 0; t < static_cast<Index>(in_.triangles.size()); ++t) {
      if (in_.facing[t] != Facing::wall) continue;
      s_.walls.push_back(t);
      r.push_back(projected_box(in_, t));
    }
    return PlaneCache(r);
  }

  template <class Visit>
  void walls_over(const Point2& q, const std::array<Rational, 2>& xy, Visit visit) const {
    for (const Index item : walls_.near(xy[0].get_d(), xy[1].get_d()))
      if (wall_contains(in_, s_.walls[item], q)) visit(s_.walls[item]);
  }

  // The heights of every vertex, and the place among them of each sloped triangle over it.
  void collect_heights() {
    s_.points = in_.points;
    s_.heights.assign(s_.vertices.size(), {});
    places_.assign(s_.vertices.size(), {});
    std::vector<Rational> z;
    std::vector<Index> sloped;
    for (std::size_t v = 0; v < s_.vertices.size(); ++v) {
      const VertexHandle vh = s_.vertices[v];
      sloped.clear();
      auto f = s_.plane.incident_faces(vh), end = f;
      do {
        if (!s_.plane.is_infinite(f))
          sloped.insert(sloped.end(), s_.stack[f->info()].begin(), s_.stack[f->info()].end());
      } while (++f != end);
      std::sort(sloped.begin(), sloped.end());
      sloped.erase(std::unique(sloped.begin(), sloped.end()), sloped.end());
      z.clear();
      for (const Index t : sloped) z.push_back(height_at(s_, t, vh->info()));
      std::vector<std::pair<Index, Index>>& places = places_[v];
      for (std::size_t k = 0; k < sloped.size(); ++k) places.emplace_back(sloped[k], k);
      walls_over(vh->point(), s_.xy[v],
                 [&](Index w) { wall_heights(in_, w, vh->point(), s_.xy[v], z); });
      for (const Index p : s_.at_vertex[v]) z.push_back(in_.points[p].z);
      std::vector<Rational> distinct = z;
      std::sort(distinct.begin(), distinct.end());
      distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
      std::vector<Height>& heights = s_.heights[v];
      for (const Rational& h : distinct) {
        Index point = kNoIndex;
        for (const Index p : s_.at_vertex[v])
          if (in_.points[p].z == h) point = p;
        if (point == kNoIndex) {
          point = static_cast<Index>(s_.points.size());
          s_.points.push_back({s_.xy[v][0], s_.xy[v][1], h});
        }
        heights.push_back({h, point});
      }
      for (auto& [t, k] : places) k = place_of(heights, z[static_cast<std::size_t>(k)]);
    }
  }

  // Where sloped triangle t, which covers a face around v, passes over it.
  Index place_over(Index v, Index t) const {
    const auto& places = places_[v];
    return std::lower_bound(places.begin(), places.end(), std::pair<Index, Index>{t, 0})->second;
  }

  Index point_over(Index v, Index t) const { return s_.heights[v][place_over(v, t)].point; }

  // The prism's bottom and top: its plane triangle on the bottom and top triangles' planes.
  void caps(Index p) {
    const Prism& prism = s_.prisms[p];
    std::array<Index, 3> b{}, t{};
    for (int k = 0; k < 3; ++k) {
      const Index v = prism.face->vertex(k)->info();
      b[k] = point_over(v, prism.bottom);
      t[k] = point_over(v, prism.top);
    }
    s_.prism_boundary[p].push_back({{b[0], b[2], b[1]}, prism.bottom});
    s_.prism_boundary[p].push_back({{t[0], t[1], t[2]}, prism.top});
  }

  std::vector<Line> lines_over(FaceHandle f, int i, Index lo, Index hi) const {
    const FaceHandle g = f->neighbor(i);
    std::vector<Index> sloped = s_.stack[f->info()];
    if (!s_.plane.is_infinite(g))
      sloped.insert(sloped.end(), s_.stack[g->info()].begin(), s_.stack[g->info()].end());
    std::sort(sloped.begin(), sloped.end());
    sloped.erase(std::unique(sloped.begin(), sloped.end()), sloped.end());
    std::vector<Line> lines;
    for (const Index t : sloped) lines.push_back({place_over(lo, t), place_over(hi, t), {t}});
    const Point2& a = s_.vertices[lo]->point();
    const Point2& b = s_.vertices[hi]->point();
    const std::array<Rational, 2> middle{(s_.xy[lo][0] + s_.xy[hi][0]) / 2,
                                         (s_.xy[lo][1] + s_.xy[hi][1]) / 2};
    walls_over(CGAL::midpoint(a, b), middle, [&](Index w) {
      // The wall's two edges that span the plane edge bound it below and above.
      const auto& c = in_.triangles[w];
      for (int k = 0; k < 3; ++k) {
        const Index p = c[k], r = c[(k + 1) % 3];
        const Point2 &p2 = in_.projected[p], &r2 = in_.projected[r];
        if (p2 == r2) continue;
        const K::Segment_2 edge(p2, r2);
        if (!edge.has_on(a) || !edge.has_on(b)) continue;
        lines.push_back({place_of(s_.heights[lo], edge_height(in_, p, r, s_.xy[lo])),
                         place_of(s_.heights[hi], edge_height(in_, p, r, s_.xy[hi])),
                         {w}});
      }
    });
    std::sort(lines.begin(), lines.end(), [](const Line& x, const Line& y) {
      return std::tie(x.at_lo, x.at_hi) < std::tie(y.at_lo, y.at_hi);
    });
    std::vector<Line> merged;
    for (Line& l : lines) {
      if (!merged.empty() && merged.back().at_lo == l.at_lo && merged.back().at_hi == l.at_hi) {
        merged.back().owners.insert(merged.back().owners.end(), l.owners.begin(), l.owners.end());
        continue;
      }
      if (!merged.empty() && l.at_hi < merged.back().at_hi) crossing(CGAL::midpoint(a, b));
      merged.push_back(std::move(l));
    }
    return merged;
  }

  static Index line_of(const std::vector<Line>& lines, Index t) {
    for (std::size_t k = 0; k < lines.size(); ++k)
      if (std::find(lines[k].owners.begin(), lines[k].owners.end(), t) != lines[k].owners.end())
        return static_cast<Index>(k);
    return kNoIndex;
  }

  // The wall triangle band k lies in, if any: one owning the lines below and above it.
  static Index wall_of_band(const Surfaces& in, const std::vector<Line>& lines, Index k) {
    for (const Index w : lines[k].owners)
      if (in.facing[w] == Facing::wall &&
          std::find(lines[k + 1].owners.begin(), lines[k + 1].owners.end(), w) !=
              lines[k + 1].owners.end())
        return w;
    return kNoIndex;
  }

  // Band k's triangles, oriented with their normal to the right of lo -> hi: a zipper up
  // its two sides, taking the lower next height first (the lower end's on a tie).
  void band(const std::vector<Line>& lines, Index k, Index lo, Index hi, bool reverse, Index on,
            std::vector<BoundaryTriangle>& out) const {
    const std::vector<Height>& left = s_.heights[lo];
    const std::vector<Height>& right = s_.heights[hi];
    Index i = lines[k].at_lo, j = lines[k].at_hi;
    const Index i_end = lines[k + 1].at_lo, j_end = lines[k + 1].at_hi;
    while (i < i_end || j < j_end) {
      const bool up_left = j == j_end || (i < i_end && !(right[j + 1].z < left[i + 1].z));
      std::array<Index, 3> t{left[i].point, right[j].point,
                             up_left ? left[i + 1].point : right[j + 1].point};
      (up_left ? i : j) += 1;
      if (reverse) std::swap(t[1], t[2]);
      out.push_back({t, on});
    }
  }

  void strip(FaceHandle f, int i) {
    if (s_.plane.is_infinite(f)) {
      const FaceHandle finite = f->neighbor(i);
      i = finite->index(f);
      f = finite;
    }
    const FaceHandle g = f->neighbor(i);
    const bool f_has = s_.face_prisms[f->info()] < s_.face_prisms[f->info() + 1];
    const bool g_has = !s_.plane.is_infinite(g) &&
                       s_.face_prisms[g->info()] < s_.face_prisms[g->info() + 1];
    if (!f_has && !g_has) return;
    const Index a = f->vertex((i + 1) % 3)->info(), c = f->vertex((i + 2) % 3)->info();
    const Index lo = std::min(a, c), hi = std::max(a, c);
    const std::vector<Line> lines = lines_over(f, i, lo, hi);
    // f lies left of a -> c, g right of it: the canonical triangles face right of lo -> hi.
    const auto side = [&](FaceHandle face, bool face_left_of_lo_hi) {
      for (Index p = s_.face_prisms[face->info()]; p < s_.face_prisms[face->info() + 1]; ++p) {
        const Index kb = line_of(lines, s_.prisms[p].bottom);
        const Index kt = line_of(lines, s_.prisms[p].top);
        for (Index k = kb; k < kt; ++k)
          band(lines, k, lo, hi, !face_left_of_lo_hi, wall_of_band(in_, lines, k),
               s_.prism_boundary[p]);
      }
    };
    if (f_has) side(f, a == lo);
    if (g_has) side(g, a != lo);
  }
};

}  // namespace

Rational height_at(const State& state, Index t, Index v) {
  for (const Index corner : state.input.triangles[t])
    for (const Index p : state.at_vertex[v])
      if (p == corner) return state.input.points[p].z;
  return height_at(state.input, t, state.xy[v][0], state.xy[v][1]);
}

void stitch(State& state) { Stitcher(state).run(); }

}  // namespace volmesh::tet::detail
