#pragma once
// The state of M3C on one cell (split_cell), shared by its stages, and the stages:
//   cell_loops.cpp          the contour segments joined into closed components
//   cell_point.cpp          whether the cell needs a cell interface point, and where
//   point_fitting.cpp       points fitted onto the interfaces' tangent planes and surfaces
//   loop_candidates.cpp     the ways to triangulate a component, the paper's first
//   cell_pieces.cpp         the polygons grouped into pieces, and the pieces' centres
//   triangulation_score.cpp checkMesh's verdict on a triangulation
//   sliver_flips.cpp        a repair: diagonals of coplanar triangles flipped
//   cell_split.cpp          the choice among the candidates, the last repair (skewed faces
//                           merged into polygons), the output
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "cell_split.hpp"

namespace volmesh::cutcell {

// Points closer than this fraction of the cell's size are one point, and a point this near
// a plane lies on it: positions computed along different routes agree to rounding.
inline constexpr double kSamePoint = 1e-9;

// The ranks of the least-squares fits (tangent_intersection's max_rank): a point where
// surfaces meet is fixed in all three directions, a point on a sharp edge in the two across
// it, a point on a smooth sheet only across the sheet.
inline constexpr int kPointRank = 3;
inline constexpr int kEdgeRank = 2;
inline constexpr int kSheetRank = 1;

// A closed contour component between two regions: a cycle of contour segments, or a path
// between two face interface points closed through their link or through the cell point.
struct Loop {
  std::vector<int> points;
  std::vector<int> segments;  // surface segments, normalised (lower label on the left)
  Index lower = 0, higher = 0;
  bool through_cell_point = false;
};

// One way to triangulate a component.
struct Candidate {
  LoopMethod method;
  std::vector<Triangle> triangles;
};

// Edge points with known normals, as the least-squares fits take them.
struct EdgeNormals {
  std::vector<Vec3> points, normals;
  std::vector<std::uint8_t> level;  // 0: on the domain's boundary (fitted first)
};

struct SplitState {
  SplitState(const CellInput& in, const CellOptions& options);

  const CellInput& in;
  const CellOptions& options;
  double size;                  // the cell's edge
  bool materials_meet = false;  // two regions of the domain, not just one and the outside
  // Per input point: an edge point with a normal on the domain's boundary (an end of a
  // contour segment beside region 0).
  std::vector<std::uint8_t> on_boundary;
  std::vector<Vec3> position;        // the input points, then the new ones
  std::vector<std::uint8_t> faces;   // per point: CellPoint::faces (0 for new points)
  std::vector<CellSegment> segments;  // normalised: lower label on the left
  std::vector<Loop> loops;
  CellSplit out;

  int add_point(const Vec3& p);
  // A fan's centre at p: the loop's own point there when one lies there (a feature point
  // on a grid edge, where a corner of the domain meets it), else a new point. A new point
  // on a loop point would leave two triangles of no area.
  int fan_centre(std::span<const int> loop, const Vec3& p);
  // The pieces on the lower and the higher label's side of a component.
  std::pair<int, int> loop_pieces(const Loop& loop) const {
    const CellSegment& s = segments[loop.segments[0]];
    return {out.polygon_piece[s.left_polygon], out.polygon_piece[s.right_polygon]};
  }
};

// The triangles of each component (by SplitState::loops).
using LoopTriangles = std::vector<std::vector<Triangle>>;

// cell_loops.cpp: normalises the segments and joins them into SplitState::loops, paths
// closed through the cell interface point when the cell has one.
void build_loops(SplitState& s);

// cell_point.cpp: the cell interface point of a cell with these face interface points (a
// new point), or -1 where their link is the junction.
int cell_interface_point(SplitState& s, const std::vector<int>& face_points);

// point_fitting.cpp.
// The edge points among `points` with known normals, level 0 those on the domain's boundary.
EdgeNormals fitted_points(const SplitState& s, const std::vector<int>& points);
// The planes of the domain's boundary at these edge points.
std::pair<std::vector<Vec3>, std::vector<Vec3>> boundary_planes(const EdgeNormals& edges);
// Whether p lies on every plane through points s with normals n, all parallel to the
// octree's faces (to kSamePoint of size).
bool on_octree_planes(std::span<const Vec3> s, std::span<const Vec3> n, const Vec3& p, double size);
// p moved onto the planes through points s with normals n (at most max_rank of them), while
// keeping `margin` from the cell's faces where both can hold.
Vec3 onto_planes(const SplitState& st, std::span<const Vec3> s, std::span<const Vec3> n, Vec3 p, double margin,
                 int max_rank);
// p pushed into the cell (nullopt beyond reach * size), a fan centre over a component on
// the domain's boundary kept on the component's tangent planes.
std::optional<Vec3> clamp_component(const SplitState& st, const std::vector<int>& loop, std::span<const Vec3> s,
                                    std::span<const Vec3> n, bool on_boundary, const Vec3& p, double reach,
                                    int max_rank);
// x, where the tangent planes through s with normals n meet, moved by one Newton step onto
// the true surfaces, with their new tangent planes.
std::optional<std::pair<Vec3, TangentPlanes>> onto_surfaces(const CellOptions& options, double size,
                                                            std::span<const Vec3> s, std::span<const Vec3> n,
                                                            const Vec3& x, int max_rank);

// loop_candidates.cpp: the ways to triangulate a component, the paper's choice first.
std::vector<Candidate> loop_candidates(SplitState& s, const Loop& loop);

// cell_pieces.cpp: the input polygons grouped into pieces (SplitState::out.pieces and
// polygon_piece); their volume-weighted centres with the components so triangulated.
void build_pieces(SplitState& s);
std::vector<Vec3> piece_centres(const SplitState& s, const LoopTriangles& triangles);

// triangulation_score.cpp: checkMesh's verdict on a face between the pieces with these
// centres (checkmesh_badness against CellOptions::limits, every inverted face kInvertedFace),
// above 1 where it is rejected; `outside` when the lower side is region 0 (a boundary face).
double badness(const SplitState& s, std::span<const int> face, const Vec3& owner, const Vec3& neighbour,
               bool outside);
// The worst badness of the triangles, from the pieces' centres.
double worst_badness(const SplitState& s, const LoopTriangles& triangles);

// sliver_flips.cpp: flips the diagonal of two coplanar triangles of a component where that
// lowers the worse badness of the two.
void flip_slivers(const SplitState& s, LoopTriangles& triangles);

}  // namespace volmesh::cutcell
