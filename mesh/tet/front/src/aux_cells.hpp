#pragma once
// The cells of the auxiliary points: an octree over a grid of level-0 blocks, each leaf of
// level L a cube of n × n × n points at step s0 / 2^L (n the auxiliary ratio, s0 = the
// field's largest size / n), split while its side exceeds twice the local size below it
// (size_field.hpp).
// So a leaf is about one target edge wide, and the points follow the local size: their count
// grows with the number of tets, not with (box / smallest size)^3. With a uniform size every
// leaf is of level 0 and the points are one grid of step h / n. The face grid (face_grid.hpp)
// lists the front's faces by these leaves.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "size_field.hpp"
#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

// No leaf is deeper than this: sizes 2^-30 of the largest.
inline constexpr int kMaxAuxLevel = 30;

struct AuxLeaf {
  int level = 0;
  std::array<long long, 3> block{0, 0, 0};  // its position in cubes of its side
};

struct AuxCells {
  Vec3 origin = Vec3::Zero();
  double step0 = 0.0;  // the points' step at level 0
  int n = 1;           // points along a leaf's side
  std::array<long long, 3> blocks{0, 0, 0};  // level-0 blocks along each axis
  Vec3 last = Vec3::Zero();  // the last level-0 grid line along each axis that the box needs
  // The octree: each node a leaf (leaf >= 0) or the parent of nodes child .. child + 7, the
  // child of octant c at child + c (bit a of c set: the upper half along axis a).
  struct Node {
    int child = -1, leaf = -1;
  };
  std::vector<Node> nodes;  // the level-0 blocks first, x fastest
  std::vector<AuxLeaf> leaves;
  int finest = 0;  // the deepest leaf level

  double step(int level) const { return std::ldexp(step0, -level); }
  double side(int level) const { return n * step(level); }
  Vec3 leaf_lo(const AuxLeaf& l) const {
    return origin + side(l.level) * Vec3(double(l.block[0]), double(l.block[1]), double(l.block[2]));
  }
};

// The grid's origin for the box corner lo at `step`: a step and a generic fraction of one
// below lo, so that grid points and lines miss the faces and edges of axis-aligned and
// symmetric models.
Vec3 aux_origin(const Vec3& lo, double step);
// The grid lines along one axis from `origin` that cover up to hi: two steps beyond it.
double aux_lines(double origin, double hi, double step);

// The cells over the box [lo, hi] for the field's sizes, n points along a leaf's side; stops
// (returning the cells made so far) once they hold more than `limit` points.
AuxCells make_aux_cells(const Vec3& lo, const Vec3& hi, const SizeField& field, int n,
                        double limit);

// The auxiliary points the cells hold: n^3 per leaf.
double aux_cell_points(const AuxCells& cells);

// Calls f(leaf index) for every leaf whose closed box meets [lo, hi] (and, at the grid's
// border, the blocks the box is clamped to), in a fixed order: a descent from the level-0
// blocks the box meets.
template <class F>
void for_each_leaf(const AuxCells& c, const Vec3& lo, const Vec3& hi, F&& f) {
  std::array<long long, 3> b0{}, b1{};
  const double side0 = c.side(0);
  for (int a = 0; a < 3; ++a) {
    const auto block = [&](double x) {
      return std::clamp<long long>(static_cast<long long>(std::floor((x - c.origin[a]) / side0)),
                                   0, c.blocks[a] - 1);
    };
    b0[a] = block(lo[a]);
    b1[a] = block(hi[a]);
  }
  struct Item {
    int node;
    Vec3 lo;
    int level;
  };
  // A depth-first descent holds at most 7 siblings per level and 8 children at the bottom.
  std::array<Item, 7 * kMaxAuxLevel + 8> stack;
  std::size_t top = 0;
  for (long long k = b0[2]; k <= b1[2]; ++k)
    for (long long j = b0[1]; j <= b1[1]; ++j)
      for (long long i = b0[0]; i <= b1[0]; ++i) {
        stack[top++] = {static_cast<int>(i + c.blocks[0] * (j + c.blocks[1] * k)),
                        c.origin + side0 * Vec3(double(i), double(j), double(k)), 0};
        while (top > 0) {
          const Item item = stack[--top];
          const AuxCells::Node& node = c.nodes[item.node];
          if (node.leaf >= 0) {
            f(node.leaf);
            continue;
          }
          const double half = c.side(item.level + 1);
          // Pushed in reverse, so that the octants are visited in order.
          for (int o = 7; o >= 0; --o) {
            const Vec3 clo = item.lo + half * Vec3(double(o & 1), double((o >> 1) & 1),
                                                   double((o >> 2) & 1));
            bool meets = true;
            for (int a = 0; a < 3; ++a) meets = meets && clo[a] <= hi[a] && clo[a] + half >= lo[a];
            if (meets) stack[top++] = {node.child + o, clo, item.level + 1};
          }
        }
      }
}


}  // namespace volmesh::tet::front

