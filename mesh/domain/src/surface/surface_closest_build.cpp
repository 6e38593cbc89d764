// Building the closest-point hierarchy: binary splits of the triangles chosen by the binned
// surface-area heuristic down to single triangles, then every node takes its children's
// children (the largest first) until it has four, and gets their boxes and cylinders.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "surface_closest.hpp"

namespace volmesh::surface {

namespace {

constexpr int kBins = 16;
// Past this depth, median splits.
constexpr int kSahDepth = kMaxClosestDepth - 32;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Box {
  Vec3 lo = Vec3::Constant(kInfinity), hi = Vec3::Constant(-kInfinity);
  void grow(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void grow(const Box& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  double area() const {
    const Vec3 e = (hi - lo).cwiseMax(0.0);
    return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
  }
};

// A subtree: a binary node (code >= 0) or one triangle (~leaf slot), with its box and its
// triangles, order_[begin, end).
struct Subtree {
  std::int32_t code;
  Box box;
  Index begin, end;
};
struct BinaryNode {
  std::array<Subtree, 2> child;
};

class Builder {
 public:
  Builder(const SurfaceGeometry& g, const Vec3& centre) : geometry_(g), centre_(centre) {
    const Index n = g.num_triangles();
    boxes_.resize(n);
    centroids_.resize(n);
    for (Index t = 0; t < n; ++t) {
      for (int k = 0; k < 3; ++k) boxes_[t].grow(g.corner(t, k));
      centroids_[t] = 0.5 * (boxes_[t].lo + boxes_[t].hi);
    }
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0);
    binary_.reserve(n);
  }

  ClosestHierarchy run() {
    ClosestHierarchy h;
    const Subtree root = split(0, static_cast<Index>(order_.size()), 0);
    h.nodes.emplace_back();
    if (root.code < 0)
      fill(h, 0, {root});
    else
      collapse(h, 0, binary_[root.code]);
    h.triangles = std::move(order_);
    return h;
  }

 private:
  Subtree split(Index begin, Index end, int depth) {
    Box box, centroids;
    for (Index i = begin; i < end; ++i) {
      box.grow(boxes_[order_[i]]);
      centroids.grow(centroids_[order_[i]]);
    }
    if (end - begin == 1) return {~begin, box, begin, end};
    const Index mid = depth < kSahDepth ? sah_split(begin, end, centroids) : kNoIndex;
    const Index m = mid != kNoIndex ? mid : median_split(begin, end, centroids);
    const auto node = static_cast<std::int32_t>(binary_.size());
    binary_.emplace_back();
    const Subtree left = split(begin, m, depth + 1), right = split(m, end, depth + 1);
    binary_[node].child = {left, right};
    return {node, box, begin, end};
  }

  // The bin boundary of least area x count on both sides over the three axes; kNoIndex
  // when the centroids coincide.
  Index sah_split(Index begin, Index end, const Box& centroids) {
    const Vec3 extent = centroids.hi - centroids.lo;
    const auto bin_of = [&](Index t, int axis) {
      const double u = (centroids_[t][axis] - centroids.lo[axis]) / extent[axis];
      return std::min(kBins - 1, static_cast<int>(u * kBins));
    };
    double best_cost = kInfinity;
    int best_axis = -1, best_bin = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(extent[axis] > 0.0)) continue;
      std::array<Box, kBins> box;
      std::array<Index, kBins> count{};
      for (Index i = begin; i < end; ++i) {
        const int b = bin_of(order_[i], axis);
        box[b].grow(boxes_[order_[i]]);
        ++count[b];
      }
      std::array<double, kBins> right_cost{};
      Box right;
      Index right_count = 0;
      for (int b = kBins - 1; b > 0; --b) {
        right.grow(box[b]);
        right_count += count[b];
        right_cost[b] = right.area() * right_count;
      }
      Box left;
      Index left_count = 0;
      for (int b = 0; b + 1 < kBins; ++b) {
        left.grow(box[b]);
        left_count += count[b];
        const double cost = left.area() * left_count + right_cost[b + 1];
        if (left_count > 0 && left_count < end - begin && cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_bin = b;
        }
      }
    }
    if (best_axis < 0) return kNoIndex;
    return static_cast<Index>(
        std::partition(order_.begin() + begin, order_.begin() + end,
                       [&](Index t) { return bin_of(t, best_axis) <= best_bin; }) -
        order_.begin());
  }

  Index median_split(Index begin, Index end, const Box& centroids) {
    int axis;
    (centroids.hi - centroids.lo).maxCoeff(&axis);
    const Index mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](Index x, Index y) {
                       const double cx = centroids_[x][axis], cy = centroids_[y][axis];
                       return cx != cy ? cx < cy : x < y;
                     });
    return mid;
  }

  // Node `index` of h gets up to four subtrees: b's children, opened largest first.
  void collapse(ClosestHierarchy& h, std::size_t index, const BinaryNode& b) {
    std::vector<Subtree> kids(b.child.begin(), b.child.end());
    while (kids.size() < 4) {
      int open = -1;
      for (int k = 0; k < static_cast<int>(kids.size()); ++k)
        if (kids[k].code >= 0 && (open < 0 || kids[k].box.area() > kids[open].box.area())) open = k;
      if (open < 0) break;
      const BinaryNode& inner = binary_[kids[open].code];
      kids[open] = inner.child[0];
      kids.push_back(inner.child[1]);
    }
    fill(h, index, kids);
  }

  void fill(ClosestHierarchy& h, std::size_t index, const std::vector<Subtree>& kids) {
    ClosestNode node;
    for (int k = 0; k < 4; ++k) {
      const bool used = k < static_cast<int>(kids.size());
      for (int axis = 0; axis < 3; ++axis) {
        node.lo[axis][k] = used ? round_down(kids[k].box.lo[axis] - centre_[axis])
                                : std::numeric_limits<float>::infinity();
        node.hi[axis][k] = used ? round_up(kids[k].box.hi[axis] - centre_[axis])
                                : -std::numeric_limits<float>::infinity();
        node.centre[axis][k] = node.axis[axis][k] = 0.0f;
      }
      node.half_height[k] = node.radius[k] = 0.0f;
      node.child[k] = used ? kids[k].code : ~0;
      if (used) set_cylinder(node, k, kids[k]);
    }
    for (int k = 0; k < static_cast<int>(kids.size()); ++k) {
      if (kids[k].code < 0) continue;
      const auto child = static_cast<std::int32_t>(h.nodes.size());
      h.nodes.emplace_back();
      node.child[k] = child;
      collapse(h, child, binary_[kids[k].code]);
    }
    h.nodes[index] = node;
  }

  // The cylinder of child k: a triangle's smallest enclosing disk; around the mean normal
  // of a patch whose normals mostly agree; else a ball around the box's centre. Its
  // extent is measured from the float centre and axis that the queries will use.
  void set_cylinder(ClosestNode& node, int k, const Subtree& kid) const {
    Vec3 centre = 0.5 * (kid.box.lo + kid.box.hi), axis = Vec3::Zero();
    if (kid.end - kid.begin == 1) {
      const Index t = order_[kid.begin];
      axis = (geometry_.corner(t, 1) - geometry_.corner(t, 0))
                 .cross(geometry_.corner(t, 2) - geometry_.corner(t, 0))
                 .normalized();
      centre = enclosing_disk_centre(geometry_.corner(t, 0), geometry_.corner(t, 1),
                                     geometry_.corner(t, 2));
    } else {
      Vec3 sum = Vec3::Zero();
      double area = 0.0;
      for (Index i = kid.begin; i < kid.end; ++i) {
        const Index t = order_[i];
        const Vec3 n = (geometry_.corner(t, 1) - geometry_.corner(t, 0))
                           .cross(geometry_.corner(t, 2) - geometry_.corner(t, 0));
        sum += n;
        area += n.norm();
      }
      if (sum.norm() > 0.5 * area) axis = sum.normalized();
    }
    Vec3 c, a;
    for (int m = 0; m < 3; ++m) {
      node.centre[m][k] = static_cast<float>(centre[m] - centre_[m]);
      node.axis[m][k] = static_cast<float>(axis[m]);
      c[m] = node.centre[m][k];
      a[m] = node.axis[m][k];
    }
    double height = 0.0, radius = 0.0;
    for (Index i = kid.begin; i < kid.end; ++i)
      for (int corner = 0; corner < 3; ++corner) {
        const Vec3 y = geometry_.corner(order_[i], corner) - centre_ - c;
        const double along = a.dot(y);
        height = std::max(height, std::abs(along));
        radius = std::max(radius, (y - along * a).norm());
      }
    node.half_height[k] = round_up(height);
    node.radius[k] = round_up(radius);
  }

  // A right or obtuse triangle's longest side's midpoint; else its circumcentre.
  static Vec3 enclosing_disk_centre(const Vec3& a, const Vec3& b, const Vec3& c) {
    const std::array<const Vec3*, 3> v{&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
      const Vec3 &x = *v[k], &y = *v[(k + 1) % 3], &z = *v[(k + 2) % 3];
      if ((y - x).dot(z - x) <= 0.0) return 0.5 * (y + z);
    }
    const Vec3 u = a - c, w = b - c, n = u.cross(w);
    return c + (u.squaredNorm() * w - w.squaredNorm() * u).cross(n) / (2.0 * n.squaredNorm());
  }

  static float round_down(double x) {
    const float f = static_cast<float>(x);
    return f > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
  }
  static float round_up(double x) {
    const float f = static_cast<float>(x);
    return f < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
  }

  const SurfaceGeometry& geometry_;
  Vec3 centre_;
  std::vector<Box> boxes_;
  std::vector<Vec3> centroids_;
  std::vector<Index> order_;
  std::vector<BinaryNode> binary_;
};

}  // namespace

ClosestHierarchy build_closest_hierarchy(const SurfaceGeometry& geometry, const Vec3& centre) {
  return Builder(geometry, centre).run();
}

}  // namespace volmesh::surface
