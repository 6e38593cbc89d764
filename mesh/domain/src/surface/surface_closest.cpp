// Closest-point queries: descend into the nearer children first and skip boxes farther than
// the best distance so far. Boxes are floats (half the memory traffic, four distances in one
// vector operation); the skip test allows for the rounding of the query point and of the
// box distance, so no triangle that could be closer is ever skipped.
#include "surface_closest.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace volmesh::surface {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Four square roots in one instruction where the target has it (x86-64 always does); a
// loop of std::sqrt is not vectorized, as it may set errno.
inline Float4 sqrt4(Float4 x) {
#if defined(__SSE__)
  return __builtin_ia32_sqrtps(x);
#else
  for (int k = 0; k < 4; ++k) x[k] = std::sqrt(x[k]);
  return x;
#endif
}

// Ericson's regions, in the order he tests them; inlined into the tree's leaf loop.
inline ClosestPoint closest_point(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto at = [&](const Vec3& x, Feature f) {
    return ClosestPoint{x, (p - x).squaredNorm(), kNoIndex, f};
  };
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return at(a, Feature::vertex0);
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return at(b, Feature::vertex1);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return at(a + d1 / (d1 - d3) * ab, Feature::edge0);
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return at(c, Feature::vertex2);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return at(a + d2 / (d2 - d6) * ac, Feature::edge2);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return at(b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b), Feature::edge1);
  const double denom = 1.0 / (va + vb + vc);
  return at(a + (vb * denom) * ab + (vc * denom) * ac, Feature::face);
}

}  // namespace

ClosestPoint closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return closest_point(p, a, b, c);
}

ClosestTree::ClosestTree(const SurfaceGeometry& geometry)
    : centre_(bounding_box(geometry).centre()), tree_(build_closest_hierarchy(geometry, centre_)) {
  const Index n = geometry.num_triangles();
  slot_.resize(n);
  corners_.resize(n);
  scale_ = 0.0;
  for (Index s = 0; s < n; ++s) {
    const Index t = tree_.triangles[s];
    slot_[t] = s;
    for (int k = 0; k < 3; ++k) {
      corners_[s][k] = geometry.corner(t, k);
      scale_ = std::max(scale_, (corners_[s][k] - centre_).lpNorm<Eigen::Infinity>());
    }
  }
}

void ClosestTree::visit(const Vec3& p, Index slot, ClosestPoint& best) const {
  const auto& c = corners_[slot];
  const ClosestPoint candidate = closest_point(p, c[0], c[1], c[2]);
  if (candidate.squared_distance < best.squared_distance) {
    best = candidate;
    best.triangle = tree_.triangles[slot];
  }
}

ClosestPoint ClosestTree::closest(const Vec3& p, Index hint) const {
  ClosestPoint best;
  best.squared_distance = kInfinity;
  visit(p, hint != kNoIndex ? slot_[hint] : 0, best);

  // A box is skipped when its float distance to the rounded point exceeds the best distance
  // by more than the point's rounding, with a relative margin far above float rounding.
  const Vec3 q = p - centre_;
  const Vec3 qr(static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()));
  const std::array<Float4, 3> qf{Float4{} + static_cast<float>(qr.x()),
                                 Float4{} + static_cast<float>(qr.y()),
                                 Float4{} + static_cast<float>(qr.z())};
  const double slack = (qr - q).norm();
  // Far above the rounding of the float operations of the cylinder distance (a few float
  // epsilons of the coordinates involved).
  constexpr double kFloatSlack = 1e-5;
  const Float4 eps =
      Float4{} + static_cast<float>(kFloatSlack * (q.lpNorm<Eigen::Infinity>() + scale_));
  float limit = 0.0f;
  const auto update_limit = [&] {
    const double r = std::sqrt(best.squared_distance) + slack;
    limit = static_cast<float>(r * r * (1.0 + 1e-5));
  };
  update_limit();

  struct Pending {
    std::int32_t node;
    float squared_distance;
  };
  std::array<Pending, 4 * kMaxClosestDepth> stack;  // depth-first: at most 3 pending per level
  int top = 0;
  std::int32_t node = 0;
  while (true) {
    const ClosestNode& n = tree_.nodes[node];
    // Written so that the compiler measures the four children in one vector operation.
    Float4 d{};
    for (int axis = 0; axis < 3; ++axis) {
      const Float4 below = n.lo[axis] - qf[axis], above = qf[axis] - n.hi[axis];
      Float4 gap = below > above ? below : above;
      gap = gap > 0.0f ? gap : Float4{};
      d += gap * gap;
    }
    std::array<Float4, 3> v;
    for (int axis = 0; axis < 3; ++axis) v[axis] = qf[axis] - n.centre[axis];
    const Float4 along = n.axis[0] * v[0] + n.axis[1] * v[1] + n.axis[2] * v[2];
    Float4 across2{};
    for (int axis = 0; axis < 3; ++axis) {
      const Float4 l = v[axis] - along * n.axis[axis];
      across2 += l * l;
    }
    const Float4 across = sqrt4(across2);
    Float4 height = (along < 0.0f ? -along : along) - n.half_height - eps;
    height = height > 0.0f ? height : Float4{};
    Float4 radial = across - n.radius - eps;
    radial = radial > 0.0f ? radial : Float4{};
    const Float4 cylinder = height * height + radial * radial;
    d = d > cylinder ? d : cylinder;
    // The children within reach, nearest first (usually one or two): triangles are measured
    // at once, the nearest node is descended into, the others pushed nearest on top.
    std::array<int, 4> near;
    int count = 0;
    for (int k = 0; k < 4; ++k)
      if (d[k] < limit) {
        int i = count++;
        for (; i > 0 && d[near[i - 1]] > d[k]; --i) near[i] = near[i - 1];
        near[i] = k;
      }
    int next = -1;
    for (int i = count - 1; i >= 0; --i) {
      const int k = near[i];
      if (n.child[k] >= 0) {
        if (next >= 0) stack[top++] = {n.child[next], d[next]};
        next = k;
      }
    }
    for (int i = 0; i < count; ++i) {
      const int k = near[i];
      if (n.child[k] >= 0) continue;
      const double before = best.squared_distance;
      visit(p, ~n.child[k], best);
      if (best.squared_distance < before) update_limit();
    }
    if (next >= 0 && d[next] < limit) {
      node = n.child[next];
      continue;
    }
    while (top > 0 && stack[top - 1].squared_distance >= limit) --top;
    if (top == 0) break;
    node = stack[--top].node;
  }
  return best;
}

double signed_distance(const SurfaceGeometry& geometry, const Vec3& p, const ClosestPoint& c) {
  const double d = std::sqrt(c.squared_distance);
  return (p - c.point).dot(geometry.normal(c.triangle, c.feature)) > 0.0 ? -d : d;
}

}  // namespace volmesh::surface
