// Which region a point on surfaces belongs to: the highest label among the regions around
// it. Without coincident surfaces every inside/outside combination of the surfaces through
// the point occurs next to it; surfaces that coincide there (parallel normals) are crossed
// together, which rules out the combinations that split them the wrong way.
#include <array>
#include <bit>

#include "analytic_shapes.hpp"

namespace volmesh {
namespace {

// Two surfaces through a point coincide there when their unit normals are parallel to within
// this (|n_i x n_j|): rounding, not a real angle.
constexpr double kParallel = 1e-9;

using Mask = AnalyticDomain::Mask;

struct Tie {
  Mask pair;  // two surfaces coinciding at the point
  bool same;  // equally oriented: inside both or neither; else inside exactly one
};

bool respects(Mask candidate, const Tie& tie) {
  const Mask inside = candidate & tie.pair;
  return (inside == 0 || inside == tie.pair) == tie.same;
}

}  // namespace

AnalyticDomain::Mask AnalyticDomain::winner(Masks m, const Vec3& p) const {
  if (m.on == 0) return m.in;
  std::array<Tie, 2 * kMaxPrimitives> ties;
  int n_ties = 0;
  if (std::popcount(m.on) >= 2) {
    std::array<Vec3, kMaxPrimitives> normal;
    for (std::size_t i = 0; i < primitives_.size(); ++i)
      if (m.on >> i & 1)
        normal[i] = primitives_[i].frame.rotation *
                    analytic::gradient(primitives_[i].shape,
                                       analytic::to_local(primitives_[i].frame, p));
    for (std::size_t i = 0; i < primitives_.size(); ++i)
      for (std::size_t j = i + 1; j < primitives_.size(); ++j)
        if ((m.on >> i & 1) && (m.on >> j & 1) && n_ties < int(ties.size()) &&
            normal[i].cross(normal[j]).norm() < kParallel)
          ties[n_ties++] = {Mask{1} << i | Mask{1} << j, normal[i].dot(normal[j]) > 0.0};
  }
  Mask best = m.in;
  bool found = false;
  for (Mask s = m.on;; s = (s - 1) & m.on) {  // every subset of the on-bits
    const Mask c = m.in | s;
    bool ok = occurs_[c];
    for (int k = 0; ok && k < n_ties; ++k) ok = respects(c, ties[k]);
    if (ok && (!found || table_[c] > table_[best])) best = c, found = true;
    if (s == 0) break;
  }
  return best;
}

}  // namespace volmesh
