// Morton codes and locational codes of the octree's integer grid.
#include "volmesh/octree/octree.hpp"

namespace volmesh {

namespace {

// Spreads the low 21 bits of x to every third bit.
std::uint64_t spread3(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

std::uint32_t compact3(std::uint64_t x) {
  x &= 0x1249249249249249ULL;
  x = (x ^ (x >> 2)) & 0x10c30c30c30c30c3ULL;
  x = (x ^ (x >> 4)) & 0x100f00f00f00f00fULL;
  x = (x ^ (x >> 8)) & 0x1f0000ff0000ffULL;
  x = (x ^ (x >> 16)) & 0x1f00000000ffffULL;
  x = (x ^ (x >> 32)) & 0x1fffffULL;
  return static_cast<std::uint32_t>(x);
}

}  // namespace

std::uint64_t morton_encode(const GridPoint& p) {
  return spread3(p[0]) | spread3(p[1]) << 1 | spread3(p[2]) << 2;
}

GridPoint morton_decode(std::uint64_t code) {
  return {compact3(code), compact3(code >> 1), compact3(code >> 2)};
}

std::uint64_t octree_code(const GridPoint& anchor, int level) {
  const int shift = kOctreeMaxLevel - level;
  return std::uint64_t{1} << (3 * level) |
         morton_encode({anchor[0] >> shift, anchor[1] >> shift, anchor[2] >> shift});
}

}  // namespace volmesh
