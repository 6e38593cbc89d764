#pragma once
// Linear octree over a cubic root, refined toward a domain's boundaries and interfaces and
// 2:1 balanced across faces and edges (the octree paper §1.1, §4; docs/methods.md, "The
// octree").
//
// Integer grid. Every position is an integer point on the finest grid: the root cube spans
// [0, 2^kOctreeMaxLevel] on each axis, a leaf of level l has edge 2^(kOctreeMaxLevel - l)
// grid units and its anchor (min corner) is a multiple of that. World coordinates are
// origin + root_size * p / 2^kOctreeMaxLevel (exact in double).
//
// Numbering inside a leaf (bitwise, x fastest; NOT the VTK hex order):
//   corner k (0..7)  offset (k & 1, k >> 1 & 1, k >> 2 & 1) times the leaf size
//   edge e (0..11)   axis a = e / 4; j = e % 4 gives the position on the two other axes
//                    (in increasing axis order) as bits (j & 1, j >> 1); kEdgeCorners
//   face f (0..5)    axis f / 2, on the low (f even) or high (f odd) side: -x +x -y +y -z +z
//
// Leaves are kept in Morton order of their anchors; a leaf's index is its position in that
// order. Any change to the tree (split, refine, balance) renumbers the leaves.
// Lookups (a leaf by anchor and level, the leaf containing a point) search the Morton order
// within a bucket of a table over the codes' leading bits, about one leaf per bucket (O(1)
// expected, the table rebuilt in O(n) after a change): the refinement passes change the tree
// often and look up little between changes, and the table is cheaper to rebuild than a hash
// map by locational code.
// Const member functions are thread-safe.
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "volmesh/core/types.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/octree/key_map.hpp"

namespace volmesh {

inline constexpr int kOctreeMaxLevel = 20;
inline constexpr std::uint32_t kOctreeGrid = 1u << kOctreeMaxLevel;  // root edge, grid units

// A point of the finest integer grid, coordinates in [0, kOctreeGrid].
using GridPoint = std::array<std::uint32_t, 3>;

// Morton (Z-order) code interleaving 21 bits per coordinate (x lowest), and back.
std::uint64_t morton_encode(const GridPoint& p);
GridPoint morton_decode(std::uint64_t code);

struct OctreeLeaf {
  GridPoint anchor{};  // min corner
  int level = 0;       // 0 = root
  std::uint32_t size() const { return kOctreeGrid >> level; }
  GridPoint corner(int k) const {
    const std::uint32_t s = size();
    return {anchor[0] + (k & 1) * s, anchor[1] + (k >> 1 & 1) * s, anchor[2] + (k >> 2 & 1) * s};
  }
  GridPoint centre() const {  // exact: size >= 1; the root's centre is 2^(max-1)
    const std::uint32_t h = size() / 2;
    return {anchor[0] + h, anchor[1] + h, anchor[2] + h};
  }
};

// The two corners of each edge, lower corner first.
inline constexpr std::array<std::array<int, 2>, 12> kEdgeCorners{{
    {0, 1}, {2, 3}, {4, 5}, {6, 7},  // along x: (y, z) bits 00 10 01 11
    {0, 2}, {1, 3}, {4, 6}, {5, 7},  // along y: (x, z)
    {0, 4}, {1, 5}, {2, 6}, {3, 7},  // along z: (x, y)
}};
// The four corners of each face, in a loop whose right-hand normal points out of the leaf.
inline constexpr std::array<std::array<int, 4>, 6> kFaceCorners{{
    {0, 4, 6, 2}, {1, 3, 7, 5},  // -x, +x
    {0, 1, 5, 4}, {2, 6, 7, 3},  // -y, +y
    {0, 2, 3, 1}, {4, 5, 7, 6},  // -z, +z
}};
// The four edges of each face, edge i joining kFaceCorners[f][i] and [i + 1].
inline constexpr std::array<std::array<int, 4>, 6> kFaceEdges{{
    {8, 6, 10, 4}, {5, 11, 7, 9},
    {0, 9, 2, 8}, {10, 3, 11, 1},
    {4, 1, 5, 0}, {2, 7, 3, 6},
}};
inline constexpr int opposite_face(int f) { return f ^ 1; }

// What lies across a leaf face.
enum class FaceKind : std::uint8_t {
  Boundary,  // the root cube's boundary: no neighbour
  Same,      // one leaf of the same size
  Coarser,   // one larger leaf (one level up on a balanced tree)
  Finer,     // four smaller leaves: a transition face
};
struct FaceNeighbours {
  FaceKind kind = FaceKind::Boundary;
  // Same/Coarser: leaves[0]. Finer: the four leaves touching the face's quarters, quarter
  // (bu, bv) at bu + 2 bv, u and v being the two other axes in increasing order; on a
  // balanced tree each is exactly one level finer.
  std::array<Index, 4> leaves{kNoIndex, kNoIndex, kNoIndex, kNoIndex};
  int count() const {
    return kind == FaceKind::Boundary ? 0 : kind == FaceKind::Finer ? 4 : 1;
  }
};
// What lies diagonally across a leaf edge (the leaf sharing the edge but no face with it).
struct EdgeNeighbours {
  FaceKind kind = FaceKind::Boundary;  // Boundary when the edge lies on the root boundary
  // Same/Coarser: leaves[0]. Finer: the two leaves along the edge's halves, lower first.
  std::array<Index, 2> leaves{kNoIndex, kNoIndex};
};

class Octree {
 public:
  // A single root leaf: the cube [origin, origin + root_size]^3.
  Octree(const Vec3& origin, double root_size);
  // The tree with these leaves (any order; they must tile the root exactly: throws
  // InputError otherwise).
  Octree(const Vec3& origin, double root_size, std::vector<OctreeLeaf> leaves);

  const Vec3& origin() const { return origin_; }
  double root_size() const { return root_size_; }
  double cell_size(int level) const;
  Vec3 world(const GridPoint& p) const;

  Index num_leaves() const { return static_cast<Index>(leaves_.size()); }
  std::span<const OctreeLeaf> leaves() const { return leaves_; }
  const OctreeLeaf& leaf(Index i) const { return leaves_[i]; }
  int max_leaf_level() const;

  // The leaf with this anchor and level, or kNoIndex.
  Index find_leaf(const GridPoint& anchor, int level) const;
  // The leaf whose half-open box [anchor, anchor + size) contains p; kNoIndex outside the
  // root (p on the root's high faces is outside).
  Index leaf_containing(const GridPoint& p) const;
  FaceNeighbours face_neighbours(Index leaf, int face) const;
  EdgeNeighbours edge_neighbours(Index leaf, int edge) const;

  // Replaces each listed leaf by its eight children (leaves at kOctreeMaxLevel are refused
  // with InputError). Renumbers the leaves. Does not rebalance.
  void split(std::span<const Index> leaves);

 private:
  void leaves_changed();  // recomputes morton_, then index_buckets()
  void index_buckets();

  Vec3 origin_;
  double root_size_;
  std::vector<OctreeLeaf> leaves_;     // Morton order of anchors
  std::vector<std::uint64_t> morton_;  // morton_encode(anchor) per leaf, ascending
  int bucket_shift_ = 63;              // a code's bucket: code >> bucket_shift_
  std::vector<Index> bucket_first_;    // first leaf with code >= the bucket's; one past the end
};

// Locational code of a node: a 1 bit above the Morton code of anchor / size (unique over
// all levels).
std::uint64_t octree_code(const GridPoint& anchor, int level);

// Restores 2:1 balance across faces and edges (|level difference| <= 1 for every two leaves
// sharing part of a face or of an edge) by splitting the coarser side, with a queue per
// level (each leaf is visited once). The result is the coarsest balanced refinement.
void balance(Octree& tree);

// Splits the listed leaves of a balanced tree (each below kOctreeMaxLevel) and restores the
// balance around them only: each split leaf's 18 face and edge neighbours of its size must
// exist, which may split coarser leaves, whose neighbours are checked in turn. Cheaper than
// balance() when the splits are a fraction of the tree. Returns every leaf it split (the
// listed ones and those the balance took), as they were.
std::vector<OctreeLeaf> split_balanced(Octree& tree, std::vector<Index> leaves);

// A leaf is selected by `select(tree, leaf)`; refine() splits every selected leaf below
// max_level, rebalances, and evaluates `select` again on the whole new tree, until no leaf
// below max_level is selected. `select` runs concurrently on several threads and must be
// thread-safe; it may look at neighbours. Returns the number of passes that split something.
// The tree must be balanced on entry (build_octree, balance and refine leave it so): the
// balance is restored around the splits only.
using LeafPredicate = std::function<bool(const Octree&, Index leaf)>;
int refine(Octree& tree, const LeafPredicate& select, int max_level);

// Splits leaves below `level` while their eight corners do not all lie in the same region of
// `domain` or one of their twelve edges is crossed by an interface (Domain::crossings, which
// also catches an edge crossed twice between equal end regions), keeping the tree balanced
// (it must be balanced on entry); leaves that balancing creates are checked too. Region and
// crossing queries are batched and run in parallel.
void refine_toward(Octree& tree, const Domain& domain, int level);

// Buffer layers between levels (snappyHexMesh's nCellsBetweenLevels): from the finest level
// down, the leaves within cells_between_levels - 1 cells of level l of a leaf of level l or
// finer are refined to level l, then the tree is rebalanced, so that each level spans at least
// that many of its cells before the next coarser one. 1: the 2:1 balance alone (no change).
// Throws InputError below 1. The tree must be balanced on entry.
void grade(Octree& tree, int cells_between_levels);

// Extra refinement fronts with their own depth.
struct BoxFront {
  Box3 box;   // leaves overlapping the box (with positive volume) are refined to `level`
  int level = 0;
};
struct SurfaceFront {
  const Domain* surface = nullptr;  // refined toward its interfaces like the domain's
  int level = 0;
};

struct OctreeOptions {
  int level = 4;         // depth at the domain's boundaries and interfaces
  int base_level = 3;    // uniform depth (capped at `level`) before the interface criterion
                         // starts, so that features between coarse grid edges are seen
  int cells_between_levels = 1;  // grade(): cells of each level before the next coarser one
  // Root = the bounding box's largest side * (1 + 2 margin), centred on the box. Unset: 0.05,
  // except for a domain that fills its bounding box, whose root then starts at the box's
  // lower corner with the box's largest side: its box faces are the root's (all of them
  // for a cube) and are not cut.
  std::optional<double> margin;
  std::vector<BoxFront> boxes;
  std::vector<SurfaceFront> surfaces;
};

// The root cube of build_octree: its lower corner and side (see OctreeOptions::margin).
struct RootCube {
  Vec3 origin;
  double side;
};
RootCube octree_root(const Domain& domain, const OctreeOptions& options);

// The root cube around domain.bounds(), refined toward the boundaries and interfaces (and the
// fronts), balanced. Throws InputError for a level beyond kOctreeMaxLevel ("--level 25
// exceeds the maximum 20"), level 0 (the root cell is larger than the domain), an empty or
// non-finite bounding box, or a leaf count beyond Index. Features that cross no edge of the
// leaves at `base_level` (e.g. a closed surface inside one such leaf) are not seen.
Octree build_octree(const Domain& domain, const OctreeOptions& options);

// The mesh vertices of a 2:1 balanced tree (as build_octree, balance and refine leave it):
// every leaf corner, once. `hanging`, `leaf_edge_mid` and `leaf_face_centre` rely on the
// balance.
struct OctreeVertices {
  std::vector<GridPoint> coords;    // Morton order
  std::vector<Vec3> points;         // world coordinates
  std::vector<Index> region;        // Domain::region at each vertex
  std::vector<std::uint8_t> hanging;  // 1: inside a face or an edge of some leaf
  std::vector<std::array<Index, 8>> leaf_corners;    // per leaf, corner numbering above
  std::vector<std::array<Index, 12>> leaf_edge_mid;  // the vertex at an edge's midpoint, or
                                                     // kNoIndex (at most one: 2:1 balance)
  std::vector<std::array<Index, 6>> leaf_face_centre;  // the vertex at a face's centre (a
                                                       // finer neighbour), or kNoIndex
  std::vector<std::uint64_t> codes;  // morton_encode(coords), increasing

  Index num_vertices() const { return static_cast<Index>(coords.size()); }
  Index find(const GridPoint& p) const {
    const std::uint64_t code = morton_encode(p);
    const auto it = std::lower_bound(codes.begin(), codes.end(), code);
    return it != codes.end() && *it == code ? static_cast<Index>(it - codes.begin()) : kNoIndex;
  }
};
// Throws InputError when the vertex count exceeds Index. With `known`, the vertices of this
// tree before a refinement (leaves split, none merged), the table is updated around the new
// leaves instead of rebuilt, and only the new vertices' regions are queried.
OctreeVertices octree_vertices(const Octree& tree, const Domain& domain,
                               const OctreeVertices& known = {});

// The vertex loop of a leaf face, oriented out of the leaf: its four corners with the
// mid-edge vertex inserted on each edge that has one, so the loop lists every mesh vertex on
// the face's boundary (no T-junction). Appends to `out`.
void leaf_face_loop(const OctreeVertices& vertices, Index leaf, int face, std::vector<Index>& out);

}  // namespace volmesh
