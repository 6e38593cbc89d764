#pragma once
// The state of one MMCMS pass over an octree: the grid vertices (moved off interfaces where
// needed), the leaves that are cut, their fine edges with the edge interface points and
// their fine faces with the M3S contours. A fine face is a leaf face that is not a
// transition face: the face of the smaller leaf where sizes differ.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "cell_split.hpp"
#include "face_contour.hpp"
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/octree/octree.hpp"

namespace volmesh::cutcell {

// A point of the output before numbering: grid vertex v is v, the point of fine edge e is
// kEdgeKey + e, the point of fine face f is kFaceKey + f; points made inside leaves are
// numbered per leaf (LeafCut).
using PointKey = std::int64_t;
inline constexpr PointKey kEdgeKey = PointKey{1} << 32;
inline constexpr PointKey kFaceKey = PointKey{2} << 32;
inline constexpr PointKey kCellKey = PointKey{3} << 32;

struct EdgePoint {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::Zero();  // unit, from the lower vertex's region into the higher's
  // The edge's single crossing, between exactly its end regions, or its crossing with the
  // domain's boundary when an end lies outside: its normal is that of the interface the
  // point lies on. Otherwise (an edge still crossed several times at the deepest level) the
  // normal is left out of the least-squares points.
  bool exact = false;
  // An edge crossed twice whose one crossing stands for both (closer than the split gap,
  // or left whole for its faces' sake): the region between them, which pinches out beside
  // it; kNoIndex otherwise.
  Index pinched = kNoIndex;
};

struct FineFace {
  Index leaf = kNoIndex;  // the face is (leaf, face), its loop oriented out of leaf
  std::int8_t face = 0;
  Index other = kNoIndex;  // the leaf across it; kNoIndex on the root boundary
  std::int8_t other_face = 0;
  std::int8_t other_quarter = 0;  // the quarter of other's face it covers (0 when whole)
};

struct FaceResult {
  std::vector<PointKey> boundary;  // the contour's boundary points
  FaceContour contour;
};

struct GridSettings {
  bool exact = true;
  FaceContourOptions face;
  CellOptions cell;
};

// The key of edge a-b in Grid::edge_index (and its sort order): the lower vertex first.
inline std::uint64_t edge_key(Index a, Index b) {
  return a < b ? std::uint64_t(a) << 32 | std::uint64_t(b) : std::uint64_t(b) << 32 | std::uint64_t(a);
}

struct Grid {
  const Octree* tree = nullptr;
  const Domain* domain = nullptr;
  GridSettings settings;
  OctreeVertices vertices;      // coordinates and nominal regions
  std::vector<Vec3> position;   // moved where needed
  std::vector<Index> region;
  std::vector<std::uint8_t> cut;  // per leaf: its boundary vertices lie in several regions

  // Fine edges of the cut leaves, lower vertex first, sorted.
  std::vector<std::array<Index, 2>> edges;
  KeyMap edge_index;
  std::vector<std::uint8_t> edge_crossings;  // transversal crossings (touches left out)
  std::vector<EdgePoint> edge_point;         // meaningful where the end regions differ
  // Per fine edge: the vertex splitting it between its two crossings, kNoIndex if none
  // (split_doubly_crossed_edges). Such vertices are numbered after the octree's (in position
  // and region); split_edge[x - vertices.num_vertices()] is the edge vertex x splits.
  std::vector<Index> split_vertex;
  std::vector<Index> split_edge;

  // Fine faces of the cut leaves, sorted by leaf and face; contours of those whose vertices
  // lie in several regions.
  std::vector<FineFace> faces;
  std::vector<Index> first_face;   // per leaf, plus the end: its fine faces in `faces`
  std::vector<Index> face_result;  // per fine face: index into results, kNoIndex if uniform
  std::vector<FaceResult> results;

  double leaf_size(Index leaf) const { return tree->cell_size(tree->leaf(leaf).level); }
  Index find_edge(Index a, Index b) const { return edge_index.find(edge_key(a, b)); }
  // The fine face (leaf, face), kNoIndex if there is none. An offset table, not a hash: the
  // assembly looks up every face of every leaf, and a hash lookup is a cache miss each.
  Index find_face(Index leaf, int face) const {
    for (Index k = first_face[leaf]; k < first_face[leaf + 1]; ++k)
      if (faces[k].face == face) return k;
    return kNoIndex;
  }
};

// find_edge_points' results for edges whose ends lie at their octree positions with their
// own regions, by the ends' Morton codes: the passes of the extra refinement share most
// edges, and the last pass after the vertex moves most of the rest.
struct EdgeMemo {
  using Key = std::pair<std::uint64_t, std::uint64_t>;
  struct Entry {
    Key key;
    Index point = kNoIndex;  // into points; kNoIndex for an edge with no point (EdgePoint{})
    std::uint8_t crossings = 0;
  };
  std::vector<Entry> entries;  // sorted by key
  // Most edges of the cut leaves join two vertices of one region and have no point: kept
  // apart, the points do not weigh down the memo that every pass rebuilds.
  std::vector<EdgePoint> points;
};

// Vertices with their regions (taken from `known` where it has them), the cut leaves.
Grid make_grid(const Octree& tree, const Domain& domain, const GridSettings& settings,
               const OctreeVertices& known = {});
// Every vertex on a leaf's boundary: corners, edge midpoints, centres of transition faces.
void leaf_boundary_vertices(const Grid& grid, Index leaf, std::vector<Index>& out);
void classify_leaves(Grid& grid);
// Fine edges of the cut leaves and their interface points (crossings or midpoints), taken
// from the memo where it has them; the memo then holds this pass's.
void find_edge_points(Grid& grid, EdgeMemo& memo);
// The rules below test the leaves `among` marks (per leaf; every leaf when empty): after a
// split only the leaves it made or touched can change their verdict (leaves_among).
using LeafMask = std::vector<std::uint8_t>;
inline bool marked(const LeafMask& among, Index leaf) { return among.empty() || among[leaf]; }

// The leaves below max_level that the first two extra rules select (extra_rules.hpp: an
// edge crossed more than once; with clearance > 0, an interface within clearance * size of
// a transition face's centre), sorted.
std::vector<Index> leaves_by_extra_rules(const Grid& grid, int max_level, double clearance,
                                         const LeafMask& among = {});

// Cut leaves below max_level whose edge points see one smooth sheet (their normals pairwise
// within cosine theta, the feature threshold) while a crossing of the two axis segments
// through the leaf's centre that run most nearly along the sheet faces elsewhere (its
// normal's cosine below theta with every edge point's): a sharp edge passing through the
// leaf without crossing its edges, which the leaf's fan would cut off (a CAD part's ridge
// between two of its leaf's grid planes). Normals oriented from the lower region into the
// higher.
std::vector<Index> leaves_hiding_features(const Grid& grid, int max_level, double theta,
                                          const LeafMask& among = {});

// Splits these leaves (selected by leaves_by_extra_rules on a grid of the tree, each below
// max_level) and then, round by round, the leaves the same rules select among those the
// splits created or touched, evaluated from the tree and the domain (and that grid's
// vertices and edge memo, for what they know) alone, until none is selected: the grid of
// the result has none to select. clearance as for leaves_by_extra_rules.
struct ExtraRuleSplits {
  int rounds = 0;
  // The leaves the splits made and those across their faces and edges, as nodes (later
  // splits leave some of them inside the tree): the only leaves of the result whose verdict
  // under any of the rules above can differ from the grid's before.
  std::vector<OctreeLeaf> touched;
};
ExtraRuleSplits split_by_extra_rules(Octree& tree, const Domain& domain, const OctreeVertices& vertices,
                                     const EdgeMemo& memo, std::vector<Index> leaves, int max_level,
                                     double clearance);
// Splits the leaves (and what the 2:1 balance needs): ExtraRuleSplits::touched of that split.
std::vector<OctreeLeaf> split_touching(Octree& tree, std::vector<Index> leaves);
// Per leaf of the tree, whether it is one of the nodes.
LeafMask leaves_among(const Octree& tree, const std::vector<OctreeLeaf>& nodes);

// Past the deepest level a leaf edge may still change region twice (a layer thinner than
// the cell): its midpoint vertex takes the region of the edge's lower corner, so that every
// side of a face holds at most one interface point. Returns the number of vertices relabelled.
Index relabel_midpoints(Grid& grid);

// Edges crossed exactly twice, from their lower end's region into a third and on into
// their higher end's, the crossings at least min_gap of the edge apart: a vertex of the
// third region between the crossings splits each into two edges crossed once (appended to
// edges).
void split_doubly_crossed_edges(Grid& grid, double min_gap);
// The vertex v when it is a grid vertex, else the ends of the edge it splits.
std::array<Index, 2> grid_vertex_ends(const Grid& grid, Index v);

// Moves grid vertices whose nearest crossing lies within clearance * edge of them off the
// interface: across it when that puts them outside the domain (the kept pieces grow),
// otherwise deeper into their own region. Updates positions and regions; returns
// {moved, unresolved}.
std::array<Index, 2> move_vertices(Grid& grid, double clearance);

// Fine faces of the cut leaves and the M3S contour of each cut one.
void contour_faces(Grid& grid);
// The paper's rules on face points: a transition face with more than one face interface
// point splits its leaf; a face interface point that left its face splits the leaves around
// the face when below max_level.
std::vector<Index> leaves_for_face_points(const Grid& grid, int max_level);

// The leaves of the unit cells around grid point p (up to eight inside the root), each once.
struct LeavesAround {
  std::array<Index, 8> leaf{};
  int count = 0;
};
LeavesAround leaves_around(const Octree& tree, const GridPoint& p);

// Quarter (bu + 2 bv) of big's face that the small leaf's face covers.
int quarter_of(const OctreeLeaf& small, const OctreeLeaf& big, int axis);

// The grid after the paper's extra refinement rules, the midpoints relabelled and the vertices
// moved, with the face contours: what M3C runs on.
Grid refined_grid(Octree& tree, const Domain& domain, const CutcellOptions& options,
                  CutcellStats& stats);

// One cut leaf split by M3C.
struct LeafCut {
  std::vector<PointKey> keys;             // of the CellInput points
  std::array<int, 24> slot_polygons{};    // first polygon of face slot 4 f + q; -1 if absent
  CellSplit split;
};
LeafCut cut_leaf(const Grid& grid, Index leaf);
// The M3C input of a cut leaf; fills cut.keys and cut.slot_polygons.
CellInput leaf_input(const Grid& grid, Index leaf, LeafCut& cut);

}  // namespace volmesh::cutcell
