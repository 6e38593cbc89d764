#include "cavity_pieces.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "volmesh/core/errors.hpp"

namespace volmesh::tet::front {

namespace {

using Q3 = std::array<mpq_class, 3>;

Q3 q3(const RationalPoint& p) { return {p.x, p.y, p.z}; }
Q3 minus(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
mpq_class dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero(const Q3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

// Whether q lies in the closed triangle a, b, c (exactly).
bool in_triangle(const Q3& a, const Q3& b, const Q3& c, const Q3& q) {
  const Q3 n = cross(minus(b, a), minus(c, a));
  if (sgn(dot(n, minus(q, a))) != 0) return false;
  int sign = 0;
  for (const auto& [u, v] : {std::pair{&a, &b}, std::pair{&b, &c}, std::pair{&c, &a}}) {
    const int s = sgn(dot(n, cross(minus(*v, *u), minus(q, *u))));
    if (s != 0 && sign != 0 && s != sign) return false;
    if (s != 0) sign = s;
  }
  return true;
}

struct Box {
  Vec3 lo, hi;
};

Box box_of(const TetMesh& m, const Tri& t) {
  Box b{m.points[t[0]], m.points[t[0]]};
  for (const Index v : t) {
    b.lo = b.lo.cwiseMin(m.points[v]);
    b.hi = b.hi.cwiseMax(m.points[v]);
  }
  return b;
}

}  // namespace

CavitySplit pieces_of_faces(const ProjectionMesh& exact, const TetMesh& rounded, Index cavity,
                            const std::vector<Tri>& faces) {
  // The pieces: faces of one kept tet only, oriented out of it (out of the cavity).
  std::map<Tri, std::pair<Tri, int>> seen;
  for (std::size_t c = 0; c < rounded.cells.size(); ++c) {
    if (rounded.cell_region[c] != cavity) continue;
    const auto& t = rounded.cells[c];
    for (const auto& f : kTetFaces) {
      const Tri face{t[f[0]], t[f[1]], t[f[2]]};
      auto& [oriented, count] = seen[corners_of(face)];
      oriented = face;
      ++count;
    }
  }
  std::map<Tri, Index> face_of;
  for (std::size_t f = 0; f < faces.size(); ++f) face_of[corners_of(faces[f])] = static_cast<Index>(f);
  std::vector<Box> boxes;
  for (const Tri& f : faces) boxes.push_back(box_of(rounded, f));
  std::map<Index, std::vector<Tri>> pieces;  // by cavity face
  for (const auto& [corners, piece] : seen) {
    if (piece.second != 1 || face_of.count(corners)) continue;
    const Tri& p = piece.first;
    Q3 centre{0, 0, 0};
    for (const Index v : p)
      for (int k = 0; k < 3; ++k) centre[k] += q3(exact.points[v])[k] / 3;
    const Box pb = box_of(rounded, p);
    Index carrier = kNoIndex;
    for (std::size_t f = 0; f < faces.size() && carrier == kNoIndex; ++f) {
      const Box& b = boxes[f];
      // Rounded Steiner points stray from their face by a rounding at most.
      const double slack = 1e-9 * (b.hi - b.lo).norm();
      if ((pb.lo.array() > b.hi.array() + slack).any() || (pb.hi.array() < b.lo.array() - slack).any())
        continue;
      const Tri& t = faces[f];
      if (in_triangle(q3(exact.points[t[0]]), q3(exact.points[t[1]]), q3(exact.points[t[2]]), centre))
        carrier = static_cast<Index>(f);
    }
    if (carrier == kNoIndex)
      throw InputError("tet-front: a boundary triangle of the cavity's projection mesh lies on no "
                       "face of the cavity");
    pieces[carrier].push_back(p);
  }
  CavitySplit split;
  for (const auto& [f, list] : pieces) {
    const Tri& t = faces[f];
    split.faces[corners_of(t)] = {t, list};
    std::set<Index> inner;
    for (const Tri& p : list)
      for (const Index v : p)
        if (v != t[0] && v != t[1] && v != t[2]) inner.insert(v);
    for (int e = 0; e < 3; ++e) {
      const Index a = std::min(t[e], t[(e + 1) % 3]), b = std::max(t[e], t[(e + 1) % 3]);
      const Q3 qa = q3(exact.points[a]), ab = minus(q3(exact.points[b]), qa);
      std::vector<std::pair<mpq_class, Index>> along;
      for (const Index v : inner) {
        const Q3 av = minus(q3(exact.points[v]), qa);
        if (is_zero(cross(ab, av))) along.emplace_back(dot(ab, av), v);
      }
      if (along.empty()) continue;
      std::sort(along.begin(), along.end());
      std::vector<Index>& on = split.edge_points[{a, b}];
      on.clear();
      for (const auto& [s, v] : along) on.push_back(v);
    }
  }
  return split;
}

}  // namespace volmesh::tet::front
