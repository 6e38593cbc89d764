#include "aux_cells.hpp"

namespace volmesh::tet::front {

namespace {

// The offset of the grid from the box corner, in steps: generic, see aux_origin.
const Vec3 kOffset(0.3183098861837907, 0.2718281828459045, 0.1414213562373095);
// A leaf is split while its side exceeds the local size by more than this factor: its points
// are then between n / 2 and n per local size along each axis, never finer than n.
constexpr double kMaxSideRatio = 2.0;

struct Builder {
  AuxCells& c;
  const SizeField& field;
  double limit;

  bool full() const { return double(c.leaves.size()) * c.n * c.n * c.n > limit; }

  void split(int node, int level, const std::array<long long, 3>& block) {
    const double side = c.side(level);
    const AuxLeaf leaf{level, block};
    const Vec3 lo = c.leaf_lo(leaf), hi = lo + Vec3::Constant(side);
    if (level >= kMaxAuxLevel || full() || side <= kMaxSideRatio * field.min_in_box(lo, hi)) {
      c.nodes[node].leaf = static_cast<int>(c.leaves.size());
      c.leaves.push_back(leaf);
      c.finest = std::max(c.finest, level);
      return;
    }
    const int first = static_cast<int>(c.nodes.size());
    c.nodes[node].child = first;
    c.nodes.resize(c.nodes.size() + 8);
    for (int o = 0; o < 8; ++o)
      split(first + o, level + 1,
            {2 * block[0] + (o & 1), 2 * block[1] + ((o >> 1) & 1), 2 * block[2] + ((o >> 2) & 1)});
  }
};

}  // namespace

Vec3 aux_origin(const Vec3& lo, double step) { return lo - step * (Vec3::Ones() + kOffset); }

double aux_lines(double origin, double hi, double step) {
  return std::ceil((hi - origin) / step) + 2.0;
}

AuxCells make_aux_cells(const Vec3& lo, const Vec3& hi, const SizeField& field, int n,
                        double limit) {
  AuxCells c;
  c.n = n;
  c.step0 = field.cap() / n;
  c.origin = aux_origin(lo, c.step0);
  for (int a = 0; a < 3; ++a) {
    const double lines = aux_lines(c.origin[a], hi[a], c.step0);
    c.blocks[a] = static_cast<long long>(std::ceil(lines / n));
    c.last[a] = c.origin[a] + c.step0 * (lines - 1.0);
  }
  c.nodes.resize(static_cast<std::size_t>(c.blocks[0] * c.blocks[1] * c.blocks[2]));
  Builder b{c, field, limit};
  for (long long k = 0; k < c.blocks[2]; ++k)
    for (long long j = 0; j < c.blocks[1]; ++j)
      for (long long i = 0; i < c.blocks[0]; ++i)
        b.split(static_cast<int>(i + c.blocks[0] * (j + c.blocks[1] * k)), 0, {i, j, k});
  return c;
}

double aux_cell_points(const AuxCells& c) { return double(c.leaves.size()) * c.n * c.n * c.n; }

}  // namespace volmesh::tet::front
