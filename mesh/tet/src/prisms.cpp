// Stage 3: the triangles over each plane triangle, sorted upwards (they cannot cross inside
// it: every projected edge is a constraint), and a prism in each gap inside the domain.
#include <algorithm>
#include <string>

#include "plane_cache.hpp"
#include "projection_data.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh::tet::detail {

namespace {

bool covers(const Surfaces& in, Index t, const Point2& q) {
  const auto& c = in.triangles[t];
  const CGAL::Orientation inside = in.facing[t] == Facing::top ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
  for (int k = 0; k < 3; ++k)
    if (CGAL::orientation(in.projected[c[k]], in.projected[c[(k + 1) % 3]], q) != inside)
      return false;
  return true;
}

[[noreturn]] void not_a_volume(const Point2& q) {
  throw InputError("the surfaces do not bound a volume over the point (" +
                   std::to_string(CGAL::to_double(q.x())) + ", " +
                   std::to_string(CGAL::to_double(q.y())) +
                   ") of the projection plane: they are open, inward, crossing or "
                   "self-intersecting there");
}

}  // namespace

void build_prisms(State& state) {
  const Surfaces& in = state.input;
  std::vector<Index> sloped;
  std::vector<Rectangle> rectangles;
  for (Index t = 0; t < static_cast<Index>(in.triangles.size()); ++t)
    if (in.facing[t] != Facing::wall) {
      sloped.push_back(t);
      rectangles.push_back(projected_box(in, t));
    }
  const PlaneCache cache(rectangles);
  state.stack.assign(state.faces.size(), {});
  state.face_prisms.assign(state.faces.size() + 1, 0);
  std::vector<std::pair<Rational, Index>> over;
  std::vector<Index> entered;
  for (std::size_t f = 0; f < state.faces.size(); ++f) {
    const FaceHandle face = state.faces[f];
    Rational x = 0, y = 0;
    for (int k = 0; k < 3; ++k) {
      x += state.xy[face->vertex(k)->info()][0];
      y += state.xy[face->vertex(k)->info()][1];
    }
    x /= 3;
    y /= 3;
    const Point2 q{K::FT(x), K::FT(y)};  // the same centroid, for the exact predicates
    over.clear();
    for (const Index item : cache.near(x.get_d(), y.get_d())) {
      const Index t = sloped[item];
      if (covers(in, t, q)) over.emplace_back(height_at(in, t, x, y), t);
    }
    std::sort(over.begin(), over.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    entered.clear();
    for (std::size_t k = 0; k < over.size(); ++k) {
      const Index t = over[k].second, s = in.surface[t];
      if (k > 0 && over[k - 1].first == over[k].first) not_a_volume(q);
      if (in.facing[t] == Facing::bot) {
        if (std::find(entered.begin(), entered.end(), s) != entered.end()) not_a_volume(q);
        entered.push_back(s);
      } else {
        if (entered.empty() || entered.back() != s) not_a_volume(q);
        entered.pop_back();
      }
      state.stack[f].push_back(t);
      if (!entered.empty() && k + 1 < over.size())
        state.prisms.push_back({face, t, over[k + 1].second, in.label[entered.back()]});
    }
    if (!entered.empty()) not_a_volume(q);
    state.face_prisms[f + 1] = static_cast<Index>(state.prisms.size());
  }
}

}  // namespace volmesh::tet::detail
