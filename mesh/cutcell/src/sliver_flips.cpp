// A repair of a triangulation checkMesh would reject: two coplanar triangles of a component
// swap their diagonal (the surface does not move) where that lowers the worse badness of
// the two. A fan around a feature point running next to a cell face leaves slivers on the
// flat facets beside it.
#include <algorithm>
#include <cmath>

#include "cell_split_state.hpp"

namespace volmesh::cutcell {
namespace {

// A flip changes the pairs around it; a few passes over a component settle its facets.
constexpr int kFlipPasses = 4;
// A flip must lower the worse badness by more than rounding, or two triangulations equal
// to rounding would flip back and forth.
constexpr double kFlipGain = 1e-9;

}  // namespace

void flip_slivers(const SplitState& st, LoopTriangles& triangles) {
  const std::vector<Vec3> centre = piece_centres(st, triangles);
  const double flat = st.options.flat * st.size;
  const std::vector<Vec3>& x = st.position;
  for (std::size_t l = 0; l < st.loops.size(); ++l) {
    std::vector<Triangle>& tris = triangles[l];
    const auto [lower, higher] = st.loop_pieces(st.loops[l]);
    const bool outside = st.out.pieces[lower].region == 0;
    const auto skew = [&](const Triangle& t) { return badness(st, t, centre[higher], centre[lower], outside); };
    for (int pass = 0; pass < kFlipPasses; ++pass) {
      bool flipped = false;
      for (std::size_t i = 0; i < tris.size(); ++i)
        for (std::size_t j = i + 1; j < tris.size(); ++j)
          for (int e = 0; e < 3; ++e) {
            // t1 = (u, v, a) and t2 holding v -> u with third point b.
            const int u = tris[i][e], v = tris[i][(e + 1) % 3], a = tris[i][(e + 2) % 3];
            int f = 0;
            while (f < 3 && !(tris[j][f] == v && tris[j][(f + 1) % 3] == u)) ++f;
            if (f == 3) continue;
            const int b = tris[j][(f + 2) % 3];
            if ((st.faces[a] & st.faces[b]) != 0 || a == b) continue;
            const Vec3 n1 = (x[v] - x[u]).cross(x[a] - x[u]);
            const Vec3 n2 = (x[u] - x[v]).cross(x[b] - x[v]);
            if (std::abs(n1.normalized().dot(x[b] - x[u])) > flat || std::abs(n2.normalized().dot(x[a] - x[u])) > flat)
              continue;
            const Triangle s1{u, b, a}, s2{v, a, b};
            const Vec3 m1 = (x[b] - x[u]).cross(x[a] - x[u]);
            const Vec3 m2 = (x[a] - x[v]).cross(x[b] - x[v]);
            if (m1.dot(n1) <= 0.0 || m2.dot(n1) <= 0.0) continue;  // the quad is not convex
            if (std::max(skew(s1), skew(s2)) + kFlipGain >= std::max(skew(tris[i]), skew(tris[j]))) continue;
            tris[i] = s1;
            tris[j] = s2;
            flipped = true;
            e = 3;
          }
      if (!flipped) break;
    }
  }
}

}  // namespace volmesh::cutcell
