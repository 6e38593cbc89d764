#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

#include "volmesh/octree/key_map.hpp"
#include "volmesh/octree/octree.hpp"

namespace volmesh {
namespace {

TEST(Morton, RoundTripsOverTheWholeVertexGrid) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> coord(0, kOctreeGrid);
  for (int i = 0; i < 100000; ++i) {
    const GridPoint p{coord(rng), coord(rng), coord(rng)};
    EXPECT_EQ(morton_decode(morton_encode(p)), p);
  }
  const GridPoint corner{kOctreeGrid, kOctreeGrid, kOctreeGrid};
  EXPECT_EQ(morton_decode(morton_encode(corner)), corner);
}

TEST(Morton, InterleavesBitsXLowest) {
  EXPECT_EQ(morton_encode({1, 0, 0}), 1u);
  EXPECT_EQ(morton_encode({0, 1, 0}), 2u);
  EXPECT_EQ(morton_encode({0, 0, 1}), 4u);
  EXPECT_EQ(morton_encode({2, 0, 0}), 8u);
  EXPECT_EQ(morton_encode({3, 3, 3}), 63u);
}

TEST(Morton, LocationalCodesAreUniqueAcrossLevels) {
  // The same anchor at every level it is aligned to gives distinct codes.
  std::vector<std::uint64_t> codes;
  for (int level = 0; level <= kOctreeMaxLevel; ++level)
    codes.push_back(octree_code({0, 0, 0}, level));
  std::sort(codes.begin(), codes.end());
  EXPECT_EQ(std::unique(codes.begin(), codes.end()), codes.end());
  EXPECT_EQ(octree_code({0, 0, 0}, 0), 1u);
  EXPECT_EQ(octree_code({kOctreeGrid / 2, 0, 0}, 1), 0b1001u);
}

TEST(KeyMap, AgreesWithStdUnorderedMapUnderInsertAndErase) {
  std::mt19937_64 rng(3);
  KeyMap map;
  std::unordered_map<std::uint64_t, Index> reference;
  for (int step = 0; step < 200000; ++step) {
    const std::uint64_t key = rng() % 5000;  // few keys: many collisions and re-inserts
    if (rng() % 3 == 0) {
      map.erase(key);
      reference.erase(key);
    } else {
      const Index value = static_cast<Index>(rng() % 1000);
      map.insert(key, value);
      reference[key] = value;
    }
  }
  EXPECT_EQ(map.size(), reference.size());
  for (std::uint64_t key = 0; key < 5000; ++key) {
    const auto it = reference.find(key);
    EXPECT_EQ(map.find(key), it == reference.end() ? kNoIndex : it->second) << key;
  }
}

}  // namespace
}  // namespace volmesh
