#include "face_grid.hpp"

#include <algorithm>
#include <cmath>

namespace volmesh::tet::front {

namespace {

// The cell index range of [lo, hi] along each axis, clamped to the grid.
std::array<std::array<long long, 2>, 3> cells_of(const FaceGrid& g, const Vec3& lo, const Vec3& hi) {
  std::array<std::array<long long, 2>, 3> r{};
  for (int a = 0; a < 3; ++a) {
    const auto clamp = [&](double x) {
      return std::clamp<long long>(static_cast<long long>(std::floor((x - g.origin[a]) / g.cell)),
                                   0, g.n[a] - 1);
    };
    r[a] = {clamp(lo[a]), clamp(hi[a])};
  }
  return r;
}

}  // namespace

FaceGrid make_face_grid(const Vec3& lo, const Vec3& hi, double cell) {
  FaceGrid g;
  g.origin = lo;
  g.cell = cell;
  for (int a = 0; a < 3; ++a)
    g.n[a] = std::max<long long>(1, static_cast<long long>(std::ceil((hi[a] - lo[a]) / cell)));
  g.faces.resize(static_cast<std::size_t>(g.n[0] * g.n[1] * g.n[2]));
  return g;
}

void insert_face(FaceGrid& g, Index face, const Vec3& lo, const Vec3& hi) {
  const auto r = cells_of(g, lo, hi);
  for (long long k = r[2][0]; k <= r[2][1]; ++k)
    for (long long j = r[1][0]; j <= r[1][1]; ++j)
      for (long long i = r[0][0]; i <= r[0][1]; ++i)
        g.faces[static_cast<std::size_t>(i + g.n[0] * (j + g.n[1] * k))].push_back(face);
  if (static_cast<std::size_t>(face) >= g.stamp.size()) g.stamp.resize(face + 1, 0);
}

void faces_near(FaceGrid& g, const Vec3& lo, const Vec3& hi, const std::vector<char>& live,
                std::vector<Index>& out) {
  ++g.query;
  out.clear();
  const auto r = cells_of(g, lo, hi);
  for (long long k = r[2][0]; k <= r[2][1]; ++k)
    for (long long j = r[1][0]; j <= r[1][1]; ++j)
      for (long long i = r[0][0]; i <= r[0][1]; ++i) {
        auto& cell = g.faces[static_cast<std::size_t>(i + g.n[0] * (j + g.n[1] * k))];
        std::erase_if(cell, [&](Index f) { return !live[f]; });
        for (const Index f : cell)
          if (g.stamp[f] != g.query) {
            g.stamp[f] = g.query;
            out.push_back(f);
          }
      }
}

}  // namespace volmesh::tet::front
