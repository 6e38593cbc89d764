// Leaf table, neighbour lookup and vertices against brute force over the leaf boxes.
#include <gtest/gtest.h>

#include <set>

#include "brute_force.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh {
namespace {

using test::contact_dimension;

// Leaves overlapping the half-open integer box [lo, hi).
std::vector<Index> leaves_overlapping(const Octree& tree, const GridPoint& lo,
                                      const GridPoint& hi) {
  std::vector<Index> result;
  for (Index i = 0; i < tree.num_leaves(); ++i) {
    const OctreeLeaf& d = tree.leaf(i);
    bool overlap = true;
    for (int k = 0; k < 3; ++k)
      overlap = overlap && d.anchor[k] < hi[k] && lo[k] < d.anchor[k] + d.size();
    if (overlap) result.push_back(i);
  }
  return result;
}

Octree balanced_random_tree(unsigned seed) {
  Octree tree = test::random_tree(seed, 4, 0.25, 6);
  balance(tree);
  return tree;
}

TEST(Octree, LeavesAreInMortonOrderAndFoundByCode) {
  const Octree tree = balanced_random_tree(1);
  for (Index i = 0; i < tree.num_leaves(); ++i) {
    const OctreeLeaf& l = tree.leaf(i);
    if (i > 0) {
      EXPECT_LT(morton_encode(tree.leaf(i - 1).anchor), morton_encode(l.anchor));
    }
    EXPECT_EQ(tree.find_leaf(l.anchor, l.level), i);
    const GridPoint inner{l.anchor[0] + l.size() - 1, l.anchor[1], l.anchor[2] + l.size() / 2};
    EXPECT_EQ(tree.leaf_containing(inner), i);
    const std::uint32_t last = l.size() - 1;
    EXPECT_EQ(tree.leaf_containing({l.anchor[0] + last, l.anchor[1] + last, l.anchor[2] + last}), i);
    // Same anchor, another level: a child or the parent, not a leaf.
    if (l.level < kOctreeMaxLevel) {
      EXPECT_EQ(tree.find_leaf(l.anchor, l.level + 1), kNoIndex);
    }
    if (l.level > 0 && (l.anchor[0] | l.anchor[1] | l.anchor[2]) % (2 * l.size()) == 0) {
      EXPECT_EQ(tree.find_leaf(l.anchor, l.level - 1), kNoIndex);
    }
  }
  EXPECT_EQ(tree.leaf_containing({kOctreeGrid, 0, 0}), kNoIndex);
  EXPECT_EQ(tree.find_leaf({1, 0, 0}, 3), kNoIndex);  // not aligned
}

TEST(Octree, FaceNeighboursMatchBruteForce) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Octree tree = balanced_random_tree(seed);
    int finer = 0, coarser = 0;
    for (Index i = 0; i < tree.num_leaves(); ++i) {
      const OctreeLeaf& c = tree.leaf(i);
      for (int f = 0; f < 6; ++f) {
        const int a = f / 2;
        const bool high = f & 1;
        // The layer one grid unit thick just across the face.
        GridPoint lo = c.anchor, hi = c.corner(7);
        if (high ? c.anchor[a] + c.size() == kOctreeGrid : c.anchor[a] == 0) {
          EXPECT_EQ(tree.face_neighbours(i, f).kind, FaceKind::Boundary);
          continue;
        }
        lo[a] = high ? c.anchor[a] + c.size() : c.anchor[a] - 1;
        hi[a] = lo[a] + 1;
        const std::vector<Index> expected = leaves_overlapping(tree, lo, hi);
        const FaceNeighbours nb = tree.face_neighbours(i, f);
        std::vector<Index> got(nb.leaves.begin(), nb.leaves.begin() + nb.count());
        std::sort(got.begin(), got.end());
        EXPECT_EQ(got, expected) << "leaf " << i << " face " << f;
        for (int k = 0; k < nb.count(); ++k) {
          const OctreeLeaf& d = tree.leaf(nb.leaves[k]);
          EXPECT_EQ(contact_dimension(c, d), 2);
          const int expected_level = nb.kind == FaceKind::Same      ? c.level
                                     : nb.kind == FaceKind::Coarser ? c.level - 1
                                                                    : c.level + 1;
          EXPECT_EQ(d.level, expected_level);
          if (nb.kind == FaceKind::Finer) {  // quarter (bu, bv) at bu + 2 bv
            const int u = a == 0 ? 1 : 0, v = a == 2 ? 1 : 2;
            EXPECT_EQ(d.anchor[u], c.anchor[u] + (k & 1) * d.size());
            EXPECT_EQ(d.anchor[v], c.anchor[v] + (k >> 1) * d.size());
          }
        }
        finer += nb.kind == FaceKind::Finer;
        coarser += nb.kind == FaceKind::Coarser;
      }
    }
    EXPECT_GT(finer, 0);
    EXPECT_EQ(finer, coarser / 4);  // each transition face seen from its four small sides
  }
}

TEST(Octree, EdgeNeighboursMatchBruteForce) {
  for (unsigned seed : {4u, 5u}) {
    const Octree tree = balanced_random_tree(seed);
    int kinds[4] = {0, 0, 0, 0};
    for (Index i = 0; i < tree.num_leaves(); ++i) {
      const OctreeLeaf& c = tree.leaf(i);
      for (int e = 0; e < 12; ++e) {
        const int a = e / 4, u = a == 0 ? 1 : 0, v = a == 2 ? 1 : 2;
        const bool high_u = e & 1, high_v = e >> 1 & 1;
        const EdgeNeighbours nb = tree.edge_neighbours(i, e);
        ++kinds[static_cast<int>(nb.kind)];
        if ((high_u ? c.anchor[u] + c.size() == kOctreeGrid : c.anchor[u] == 0) ||
            (high_v ? c.anchor[v] + c.size() == kOctreeGrid : c.anchor[v] == 0)) {
          EXPECT_EQ(nb.kind, FaceKind::Boundary);
          continue;
        }
        // The tube one grid unit thick diagonally across the edge.
        GridPoint lo = c.anchor, hi = c.corner(7);
        lo[u] = high_u ? c.anchor[u] + c.size() : c.anchor[u] - 1;
        lo[v] = high_v ? c.anchor[v] + c.size() : c.anchor[v] - 1;
        hi[u] = lo[u] + 1;
        hi[v] = lo[v] + 1;
        const std::vector<Index> expected = leaves_overlapping(tree, lo, hi);
        const int count = nb.kind == FaceKind::Finer ? 2 : 1;
        std::vector<Index> got(nb.leaves.begin(), nb.leaves.begin() + count);
        EXPECT_EQ(got, expected) << "leaf " << i << " edge " << e;  // lower half first
      }
    }
    EXPECT_GT(kinds[static_cast<int>(FaceKind::Finer)], 0);
    EXPECT_GT(kinds[static_cast<int>(FaceKind::Coarser)], 0);
  }
}

TEST(Octree, BigLeafNextToEightSmallOnesSeesATransitionFace) {
  Octree tree(Vec3::Zero(), 1.0);
  tree.split(std::vector<Index>{0});
  tree.split(std::vector<Index>{0});  // the child at the origin
  ASSERT_EQ(tree.num_leaves(), 15);
  const Index big = tree.find_leaf({kOctreeGrid / 2, 0, 0}, 1);
  ASSERT_NE(big, kNoIndex);
  const FaceNeighbours nb = tree.face_neighbours(big, 0);  // -x
  ASSERT_EQ(nb.kind, FaceKind::Finer);
  for (int q = 0; q < 4; ++q) {
    EXPECT_EQ(tree.leaf(nb.leaves[q]).level, 2);
    EXPECT_EQ(tree.face_neighbours(nb.leaves[q], 1).kind, FaceKind::Coarser);
    EXPECT_EQ(tree.face_neighbours(nb.leaves[q], 1).leaves[0], big);
  }
}

TEST(Octree, ConstructorRefusesLeavesThatDoNotTileTheRoot) {
  const std::uint32_t half = kOctreeGrid / 2;
  std::vector<OctreeLeaf> leaves;
  for (int k = 0; k < 7; ++k)
    leaves.push_back({{(k & 1) * half, (k >> 1 & 1) * half, (k >> 2 & 1) * half}, 1});
  EXPECT_THROW(Octree(Vec3::Zero(), 1.0, leaves), InputError);  // seven of eight
  leaves.push_back({{half, half, half}, 1});
  EXPECT_NO_THROW(Octree(Vec3::Zero(), 1.0, leaves));
  leaves.push_back({{0, 0, 0}, 2});
  EXPECT_THROW(Octree(Vec3::Zero(), 1.0, leaves), InputError);  // overlap
  leaves.pop_back();
  leaves.back().anchor[0] = 1;
  EXPECT_THROW(Octree(Vec3::Zero(), 1.0, leaves), InputError);  // not aligned
}

TEST(Octree, VerticesMatchBruteForce) {
  const Octree tree = balanced_random_tree(6);
  const auto domain = make_builtin_domain("ball");
  const OctreeVertices v = octree_vertices(tree, *domain);
  std::set<std::uint64_t> corners;
  for (const OctreeLeaf& l : tree.leaves())
    for (int k = 0; k < 8; ++k) corners.insert(morton_encode(l.corner(k)));
  ASSERT_EQ(static_cast<std::size_t>(v.num_vertices()), corners.size());
  for (Index id = 0; id < v.num_vertices(); ++id) {
    EXPECT_EQ(v.find(v.coords[id]), id);
    EXPECT_EQ(v.region[id], domain->region(v.points[id]));
    EXPECT_TRUE(v.points[id].isApprox(tree.world(v.coords[id])));
    // Hanging: inside a face or an edge of a leaf whose closed box contains it.
    bool hanging = false;
    for (const OctreeLeaf& l : tree.leaves()) {
      int on_boundary = 0, inside = 0;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t x = v.coords[id][k];
        if (x < l.anchor[k] || x > l.anchor[k] + l.size()) inside = -10;
        on_boundary += x == l.anchor[k] || x == l.anchor[k] + l.size();
        inside += 1;
      }
      if (inside == 3 && on_boundary < 3) hanging = true;
    }
    EXPECT_EQ(v.hanging[id] != 0, hanging) << id;
  }
  int mids = 0;
  for (Index i = 0; i < tree.num_leaves(); ++i) {
    const OctreeLeaf& l = tree.leaf(i);
    for (int k = 0; k < 8; ++k) EXPECT_EQ(v.coords[v.leaf_corners[i][k]], l.corner(k));
    for (int e = 0; e < 12; ++e) {
      GridPoint mid = l.corner(kEdgeCorners[e][0]);
      mid[e / 4] += l.size() / 2;
      const bool exists = corners.count(morton_encode(mid)) > 0;
      EXPECT_EQ(v.leaf_edge_mid[i][e] != kNoIndex, exists);
      if (exists) {
        EXPECT_EQ(v.coords[v.leaf_edge_mid[i][e]], mid);
      }
      mids += exists;
    }
  }
  EXPECT_GT(mids, 0);
  int centres = 0;
  for (Index i = 0; i < tree.num_leaves(); ++i) {
    const OctreeLeaf& l = tree.leaf(i);
    for (int f = 0; f < 6; ++f) {
      GridPoint centre = l.centre();
      centre[f / 2] = l.anchor[f / 2] + (f & 1) * l.size();
      const bool exists = l.size() > 1 && corners.count(morton_encode(centre)) > 0;
      EXPECT_EQ(v.leaf_face_centre[i][f], exists ? v.find(centre) : kNoIndex) << i << " " << f;
      centres += exists;
    }
  }
  EXPECT_GT(centres, 0);
}

// The refinement passes of the cut cells update the vertex table of a refined tree from the
// coarser tree's: the same table as a rebuild, over several refinements (balance included).
TEST(Octree, VerticesOfARefinedTreeUpdateFromTheCoarserTree) {
  for (const unsigned seed : {3u, 4u}) {
    Octree tree = balanced_random_tree(seed);
    const auto domain = make_builtin_domain("primitives");
    OctreeVertices updated = octree_vertices(tree, *domain);
    for (int round = 0; round < 3; ++round) {
      const Index before = updated.num_vertices();
      const auto some = [round](const Octree& t, Index i) {
        return (i + round) % 7 == 0 && t.leaf(i).level < 6;
      };
      refine(tree, some, 6);
      updated = octree_vertices(tree, *domain, updated);
      const OctreeVertices rebuilt = octree_vertices(tree, *domain);
      ASSERT_GT(updated.num_vertices(), before);
      EXPECT_EQ(updated.codes, rebuilt.codes);
      EXPECT_EQ(updated.coords, rebuilt.coords);
      EXPECT_EQ(updated.points, rebuilt.points);
      EXPECT_EQ(updated.region, rebuilt.region);
      EXPECT_EQ(updated.hanging, rebuilt.hanging);
      EXPECT_EQ(updated.leaf_corners, rebuilt.leaf_corners);
      EXPECT_EQ(updated.leaf_edge_mid, rebuilt.leaf_edge_mid);
      EXPECT_EQ(updated.leaf_face_centre, rebuilt.leaf_face_centre);
    }
  }
}

TEST(Octree, FaceLoopsPointOutOfTheLeafAndListMidEdgeVertices) {
  const Octree tree = balanced_random_tree(7);
  const auto domain = make_builtin_domain("ball");
  const OctreeVertices v = octree_vertices(tree, *domain);
  std::vector<Index> loop;
  for (Index i = 0; i < tree.num_leaves(); ++i) {
    const double h = tree.cell_size(tree.leaf(i).level);
    for (int f = 0; f < 6; ++f) {
      loop.clear();
      leaf_face_loop(v, i, f, loop);
      int mids = 0;
      for (int e : kFaceEdges[f]) mids += v.leaf_edge_mid[i][e] != kNoIndex;
      ASSERT_EQ(loop.size(), 4u + mids);
      Vec3 area = Vec3::Zero();  // Newell
      for (std::size_t k = 0; k < loop.size(); ++k)
        area += v.points[loop[k]].cross(v.points[loop[(k + 1) % loop.size()]]);
      Vec3 outward = Vec3::Zero();
      outward[f / 2] = (f & 1) ? 1.0 : -1.0;
      EXPECT_TRUE((0.5 * area).isApprox(h * h * outward, 1e-9)) << i << " " << f;
    }
  }
}

}  // namespace
}  // namespace volmesh
