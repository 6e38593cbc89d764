// Triangulated box surfaces for the built-ins whose boundary is made of boxes.
#include <array>

#include "builtin_entries.hpp"

namespace volmesh {

TriSurface box_surface(const Vec3& lo, const Vec3& hi, int squares, const Rigid& frame) {
  const int n = squares, side = n + 1;
  TriSurface s;
  // Lattice point (i, j, k) of the box's surface -> its vertex, made on first use.
  std::vector<Index> vertex(static_cast<std::size_t>(side) * side * side, -1);
  const auto corner = [&](std::array<int, 3> ijk) {
    Index& v = vertex[(static_cast<std::size_t>(ijk[0]) * side + ijk[1]) * side + ijk[2]];
    if (v < 0) {
      Vec3 local;
      // Multiplied before dividing: exact wherever (hi - lo) * i / n is representable.
      for (int a = 0; a < 3; ++a) local[a] = lo[a] + (hi[a] - lo[a]) * ijk[a] / n;
      v = s.num_points();
      s.points.push_back(frame.rotation * local + frame.translation);
    }
    return v;
  };
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, w = (a + 2) % 3;  // e_u x e_w = e_a
    for (int high = 0; high < 2; ++high)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const auto at = [&](int di, int dj) {
            std::array<int, 3> ijk{};
            ijk[a] = high * n;
            ijk[u] = i + di;
            ijk[w] = j + dj;
            return corner(ijk);
          };
          const Index p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
          if (high) {
            s.triangles.push_back({p00, p10, p11});
            s.triangles.push_back({p00, p11, p01});
          } else {
            s.triangles.push_back({p00, p11, p10});
            s.triangles.push_back({p00, p01, p11});
          }
        }
  }
  return s;
}

}  // namespace volmesh
