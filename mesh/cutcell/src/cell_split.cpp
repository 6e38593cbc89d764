#include "volmesh/cutcell/cell_split.hpp"

#include "volmesh/core/geometry.hpp"
#include "volmesh/geometry/polygon_split.hpp"
#include "volmesh/quality/face_metrics.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <cmath>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>

namespace volmesh::cutcell {
namespace {

// Corners of cell face k (axis k / 2, side k % 2) in a cyclic order.
std::array<int, 4> face_corners(int k) {
  const int axis = k / 2, side = k % 2;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  std::array<int, 4> out{};
  const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) out[i] = side << axis | uv[i][0] << u | uv[i][1] << v;
  return out;
}

double cell_size(const std::array<Vec3, 8>& corners) { return (corners[7] - corners[0]).norm() / std::sqrt(3.0); }

std::pair<int, int> edge_key(int a, int b) { return a < b ? std::pair{a, b} : std::pair{b, a}; }

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

struct Candidate {
  LoopMethod method;
  std::vector<Triangle> triangles;
};

struct Loop {
  std::vector<int> points;
  std::vector<int> segments;  // surface segments, normalised (lower label on the left)
  Index lower = 0, higher = 0;
  bool through_cell_point = false;
};

class Splitter {
 public:
  Splitter(const CellInput& in, const CellOptions& options) : in_(in), options_(options) {
    for (const CellPoint& p : in.points) {
      position_.push_back(p.position);
      faces_.push_back(p.faces);
    }
    size_ = cell_size(in.corners);
    on_boundary_ = boundary_edge_points();
    Index material = 0;
    for (const CellPolygon& p : in.polygons) {
      if (p.region == 0) continue;
      materials_meet_ = materials_meet_ || (material != 0 && p.region != material);
      material = p.region;
    }
  }
  CellSplit run();

 private:
  int add_point(const Vec3& p) {
    out_.new_points.push_back(p);
    position_.push_back(p);
    faces_.push_back(0);
    return static_cast<int>(position_.size()) - 1;
  }
  // A fan's centre at p: the loop's own point there when one lies there (a feature point
  // on a grid edge, where a corner of the domain meets it), else a new point. A new point
  // on a loop point would leave two triangles of no area.
  int fan_centre(std::span<const int> loop, const Vec3& p) {
    for (const int k : loop)
      if ((position_[k] - p).norm() <= 1e-9 * size_) return k;
    return add_point(p);
  }
  std::optional<Vec3> clamp(const Vec3& p, double reach) const {
    return clamp_into_cell(in_.corners, p, options_.margin * size_, reach * size_);
  }
  void build_loops();
  std::vector<std::uint8_t> boundary_edge_points() const;
  struct EdgeNormals {
    std::vector<Vec3> points, normals;
    std::vector<std::uint8_t> level;  // 0: on the domain's boundary
  };
  EdgeNormals edge_normals() const;
  static std::pair<std::vector<Vec3>, std::vector<Vec3>> boundary_planes(const EdgeNormals& edges);
  Vec3 onto_planes(std::span<const Vec3> s, std::span<const Vec3> n, Vec3 p, double margin,
                   int max_rank) const;
  std::optional<Vec3> clamp_component(const std::vector<int>& loop, std::span<const Vec3> s,
                                      std::span<const Vec3> n, bool on_boundary, const Vec3& p,
                                      double reach, int max_rank) const;
  std::optional<std::pair<Vec3, TangentPlanes>> onto_surfaces(std::span<const Vec3> s, std::span<const Vec3> n,
                                                              const Vec3& x, int max_rank) const;
  std::optional<Vec3> fitted_cell_point(const EdgeNormals& edges, const Vec3& fit) const;
  int cell_point(const std::vector<int>& face_points, const std::optional<Vec3>& fitted,
                 const EdgeNormals& edges);
  bool normals_are_sharp(std::span<const Vec3> normals) const;
  bool junction_may_bend(const EdgeNormals& edges, const Vec3& junction) const;
  bool junction_bends(const std::vector<int>& face_points, const Vec3& fitted) const;
  bool junction_along_link(const EdgeNormals& edges, const std::vector<int>& face_points) const;
  std::vector<Candidate> candidates(const Loop& loop);
  double worst_badness(const std::vector<std::vector<Triangle>>& triangles) const;
  // Puts back the first candidates moved into `triangles`.
  static void options_copy_back(std::vector<std::vector<Candidate>>& options,
                                const std::vector<std::vector<Triangle>>& triangles) {
    for (std::size_t l = 0; l < options.size(); ++l) options[l][0].triangles = triangles[l];
  }
  // The edge points of a loop with known normals.
  EdgeNormals fitted_points(const std::vector<int>& loop) const;
  void split_along_feature(const std::vector<int>& loop, bool on_boundary, std::vector<Candidate>& out);
  void smooth_candidates(const std::vector<int>& loop, bool on_boundary, std::vector<Candidate>& out);
  int face_point_near(const Loop& loop, const Vec3& p) const;
  bool on_octree_planes(std::span<const Vec3> s, std::span<const Vec3> n, const Vec3& p) const;
  void build_pieces();
  // The pieces on the lower and the higher label's side of a component.
  std::pair<int, int> loop_pieces(const Loop& loop) const {
    const CellSegment& s = segments_[loop.segments[0]];
    return {out_.polygon_piece[s.left_polygon], out_.polygon_piece[s.right_polygon]};
  }
  std::vector<Vec3> piece_centres(const std::vector<std::vector<Triangle>>& triangles) const;
  double badness(std::span<const int> face, const Vec3& owner, const Vec3& neighbour, bool outside) const;
  // methods: how each component was triangulated.
  void merge_skewed(std::vector<std::vector<Triangle>>& triangles, const std::vector<LoopMethod>& methods);
  void flip_slivers(std::vector<std::vector<Triangle>>& triangles);
  void emit_triangles(const std::vector<std::vector<Triangle>>& triangles);

  const CellInput& in_;
  const CellOptions& options_;
  double size_;
  bool materials_meet_ = false;  // two regions of the domain, not just one and the outside
  std::vector<std::uint8_t> on_boundary_;  // per input point: boundary_edge_points()
  std::vector<Vec3> position_;
  std::vector<std::uint8_t> faces_;
  std::vector<CellSegment> segments_;  // normalised
  std::vector<Loop> loops_;
  CellSplit out_;
};

// Per input point: an edge point with a normal on the domain's boundary (an end of a contour
// segment beside region 0).
std::vector<std::uint8_t> Splitter::boundary_edge_points() const {
  std::vector<std::uint8_t> out(in_.points.size(), 0);
  for (const CellSegment& g : in_.segments)
    if (g.left == 0 || g.right == 0)
      for (const int i : {g.a, g.b})
        out[i] = in_.points[i].kind == CellPointKind::edge && !in_.points[i].normal.isZero();
  return out;
}

// The cell's edge points with known normals, level 0 those on the domain's boundary.
Splitter::EdgeNormals Splitter::edge_normals() const {
  std::vector<int> all(in_.points.size());
  std::iota(all.begin(), all.end(), 0);
  return fitted_points(all);
}

// p moved onto the planes through points s with normals n (at most max_rank of them), while
// keeping `margin` from the cell's faces where both can hold (alternating projections):
// pushing a point on the domain's boundary off a face must not push it off a planar
// boundary, or the domain's volume changes. p itself when the normals take more than
// max_rank directions (a curved boundary: no plane to keep), or the point would leave the cell.
Vec3 Splitter::onto_planes(std::span<const Vec3> s, std::span<const Vec3> n, Vec3 p, double margin,
                           int max_rank) const {
  if (s.empty() || !few_directions(n, max_rank, 2) ||
      !(materials_meet_ || std::all_of(n.begin(), n.end(), parallel_to_octree_faces)))
    return p;
  const Vec3 start = p;
  for (int pass = 0; pass < 8; ++pass) {
    p = tangent_intersection(s, n, p, max_rank);
    if (depth_inside_cell(in_.corners, p) >= 0.99 * margin) break;
    p = *clamp_into_cell(in_.corners, p, margin, std::numeric_limits<double>::infinity());
  }
  p = tangent_intersection(s, n, p, max_rank);
  // A boundary that crosses a face warped by vertex moves may run just outside the face's
  // mean plane: the point may follow it as far as the junction margin.
  return depth_inside_cell(in_.corners, p) > -options_.junction_margin * size_ ? p : start;
}

// The planes of the domain's boundary at the cell's edge points.
std::pair<std::vector<Vec3>, std::vector<Vec3>> Splitter::boundary_planes(const EdgeNormals& edges) {
  std::pair<std::vector<Vec3>, std::vector<Vec3>> out;
  for (std::size_t i = 0; i < edges.points.size(); ++i)
    if (edges.level[i] == 0) {
      out.first.push_back(edges.points[i]);
      out.second.push_back(edges.normals[i]);
    }
  return out;
}

// Whether p lies on every plane through s with normal n, all parallel to the octree's faces.
bool Splitter::on_octree_planes(std::span<const Vec3> s, std::span<const Vec3> n, const Vec3& p) const {
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!parallel_to_octree_faces(n[i]) || std::abs(n[i].dot(p - s[i])) > 1e-9 * size_) return false;
  return !s.empty();
}

// clamp() keeping the centre of a fan over a component on the domain's boundary on the
// component's tangent planes (through its fitted points s with normals n, at most max_rank
// of them), unless that turns a fan triangle over: a centre moved onto a sharp edge beyond
// the loop's own point on it folds the fan.
std::optional<Vec3> Splitter::clamp_component(const std::vector<int>& loop, std::span<const Vec3> s,
                                              std::span<const Vec3> n, bool on_boundary,
                                              const Vec3& p, double reach, int max_rank) const {
  const std::optional<Vec3> q = clamp(p, reach);
  if (!q || !on_boundary) return q;
  // A point on the boundary's planes parallel to the octree's faces (a box's corner or edge)
  // stays where it is in the cell: next to the domain's boundary only the outside piece,
  // which is dropped, lies between it and the faces it is near, and pushed in it would cut
  // the corner off. As in onto_planes, it may lie as far as the junction margin outside the
  // mean planes of faces warped by vertex moves.
  const Vec3 r = depth_inside_cell(in_.corners, p) > -options_.junction_margin * size_ && on_octree_planes(s, n, p)
                     ? p
                     : onto_planes(s, n, *q, options_.margin * size_, max_rank);
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3 &a = position_[loop[k]], &b = position_[loop[(k + 1) % loop.size()]];
    if (!((a - *q).cross(b - *q).dot((a - r).cross(b - r)) > 0.0)) return q;
  }
  return r;
}

// x, where the tangent planes through s with normals n meet, moved by one Newton step onto
// the surfaces (at most max_rank of them), with their new tangent planes; nullopt without
// surface_near, when a surface is not found again, or when the step does not converge:
// found again beside the new point, a surface lies farther than a quarter of the step from
// it (the planes found are not those meeting at x; on builtin:primitives at level 3 such
// steps cost 2e-2 of a region's volume).
std::optional<std::pair<Vec3, TangentPlanes>> Splitter::onto_surfaces(std::span<const Vec3> s,
                                                                       std::span<const Vec3> n,
                                                                       const Vec3& x, int max_rank) const {
  if (!options_.exact_points || !options_.surface_near) return std::nullopt;
  const double reach = options_.newton_reach * size_;
  std::optional<TangentPlanes> found = planes_near_feature(s, n, x, reach, 0.4 * reach, options_.surface_near);
  if (!found) return std::nullopt;
  const Vec3 p = tangent_intersection(found->points, found->normals, x, max_rank);
  const double step = (p - x).norm();
  if (!(step < reach)) return std::nullopt;
  const std::optional<TangentPlanes> again =
      planes_near_feature(found->points, found->normals, p, reach, 0.4 * reach, options_.surface_near);
  if (!again || again->points.size() != found->points.size()) return std::nullopt;
  for (std::size_t k = 0; k < again->points.size(); ++k)
    if (!(std::abs(again->normals[k].dot(p - again->points[k])) <= 0.25 * step + 1e-12 * size_))
      return std::nullopt;
  return std::pair{p, std::move(*found)};
}

// The least-squares junction point of the cell's edge points (those on the domain's boundary
// fitted first: `fit`), on the true surfaces and moved inside the cell; nullopt when it
// lies beyond reach.
std::optional<Vec3> Splitter::fitted_cell_point(const EdgeNormals& edges, const Vec3& fit) const {
  const double margin = options_.junction_margin * size_, reach = options_.reach * size_;
  const auto stepped = onto_surfaces(edges.points, edges.normals, fit, 3);
  const Vec3 junction = stepped ? stepped->first : fit;
  std::optional<Vec3> p;
  // On a junction line (a sphere meeting a plane) the point slides along the line into the
  // cell, keeping down to a quarter of the margin where the line passes by a cell edge;
  // pushed in across the faces it would leave the line by up to the margin.
  if (depth_inside_cell(in_.corners, junction) < margin)
    if (const std::optional<Vec3> line = free_direction(edges.normals))
      for (double m = margin; !p && m >= 0.25 * margin; m *= 0.5)
        p = slide_into_cell(in_.corners, junction, *line, m, reach);
  if (!p) p = clamp_into_cell(in_.corners, junction, margin, reach);
  if (!p) return p;
  const auto [s, n] = boundary_planes(edges);
  return onto_planes(s, n, *p, margin, 3);
}

// `fitted`: fitted_cell_point() with exact points.
int Splitter::cell_point(const std::vector<int>& face_points, const std::optional<Vec3>& fitted,
                         const EdgeNormals& edges) {
  Vec3 p;
  if (!options_.exact_points) {
    p = Vec3::Zero();
    for (const Vec3& c : in_.corners) p += c / 8.0;
  } else if (fitted) {
    p = *fitted;
  } else {
    out_.cell_point_left_cell = true;
    p = Vec3::Zero();
    for (int f : face_points) p += position_[f] / static_cast<double>(face_points.size());
    const auto [s, n] = boundary_planes(edges);
    p = onto_planes(s, n, p, options_.margin * size_, 3);
  }
  return add_point(p);
}

// Whether the normals at these edge points show a sharp edge.
bool Splitter::normals_are_sharp(std::span<const Vec3> normals) const {
  for (std::size_t i = 0; i < normals.size(); ++i)
    for (std::size_t j = i + 1; j < normals.size(); ++j)
      if (normals[i].dot(normals[j]) < options_.feature.theta) return true;
  return false;
}

// Where two face interface points are all the cell has, the link between them is the
// junction unless it bends inside the cell: at a sharp edge of the domain's boundary (a
// layer ending on the box's edge), or of an interface where regions meet inside (a box's
// edge in a ball, meeting a cylinder's end). Inside, only where the least-squares junction
// point lies clear of the cell's faces: pushed in from near them it bends the interfaces
// more than the link does.
bool Splitter::junction_may_bend(const EdgeNormals& edges, const Vec3& junction) const {
  std::vector<Vec3> boundary;
  for (std::size_t i = 0; i < edges.points.size(); ++i)
    if (edges.level[i] == 0) boundary.push_back(edges.normals[i]);
  if (normals_are_sharp(boundary)) return true;
  if (!normals_are_sharp(edges.normals)) return false;
  return depth_inside_cell(in_.corners, junction) >= options_.junction_margin * size_;
}

// Whether the junction point lies farther than bend * size from the link between the two
// face interface points: the link would cut the edge off.
bool Splitter::junction_bends(const std::vector<int>& face_points, const Vec3& fitted) const {
  return distance_to_segment(fitted, position_[face_points[0]], position_[face_points[1]]) > options_.bend * size_;
}

// Whether the edge points' normals leave free only the direction of the link between the
// two face interface points: surfaces crossing along a line through both (a cylinder
// through a plane), which the link follows to O(h^2). Their least-squares point
// extrapolates the tangent planes of far edge points across the cell and may lie well off
// the line.
bool Splitter::junction_along_link(const EdgeNormals& edges, const std::vector<int>& face_points) const {
  const std::optional<Vec3> line = free_direction(edges.normals);
  if (!line) return false;
  const Vec3 link = position_[face_points[1]] - position_[face_points[0]];
  return std::abs(line->dot(link)) > 0.9 * link.norm();
}

// Components per pair of regions: cycles of surface segments, and paths between face
// interface points closed through the link between two of them or through the cell point.
void Splitter::build_loops() {
  for (CellSegment s : in_.segments) {
    if (s.left > s.right) {
      std::swap(s.a, s.b);
      std::swap(s.left, s.right);
      std::swap(s.left_polygon, s.right_polygon);
    }
    segments_.push_back(s);
  }
  std::vector<int> face_points;
  for (int i = 0; i < static_cast<int>(in_.points.size()); ++i)
    if (in_.points[i].is_face_interface()) face_points.push_back(i);
  const int nif = static_cast<int>(face_points.size());
  int centre = -1;
  if (nif > 2 && !options_.exact_points) {
    centre = cell_point(face_points, std::nullopt, {});
  } else if (nif >= 2 && options_.exact_points) {
    const EdgeNormals edges = edge_normals();
    // The least-squares junction of the edge points, those on the domain's boundary first.
    const std::optional<Vec3> junction =
        edges.points.empty() ? std::nullopt
                             : std::optional(tangent_intersection_ranked(edges.points, edges.normals, edges.level, 3));
    if (nif > 2 || (junction && junction_may_bend(edges, *junction) && !junction_along_link(edges, face_points))) {
      const std::optional<Vec3> fitted = junction ? fitted_cell_point(edges, *junction) : std::nullopt;
      if (nif > 2 || (fitted && junction_bends(face_points, *fitted)))
        centre = cell_point(face_points, fitted, edges);
    }
  }

  // Segments by (pair, start point), sorted for lookup.
  using Key = std::tuple<Index, Index, int>;
  std::map<Key, int> from;
  std::map<Key, int> into;
  for (int i = 0; i < static_cast<int>(segments_.size()); ++i) {
    const CellSegment& s = segments_[i];
    if (!from.emplace(Key{s.left, s.right, s.a}, i).second ||
        !into.emplace(Key{s.left, s.right, s.b}, i).second)
      throw std::logic_error("split_cell: two contour segments of one pair leave one point");
  }
  std::vector<char> used(segments_.size(), 0);
  const auto walk = [&](int first, Loop& loop) {
    int i = first;
    while (true) {
      used[i] = 1;
      const CellSegment& s = segments_[i];
      loop.points.push_back(s.a);
      loop.segments.push_back(i);
      const auto next = from.find(Key{s.left, s.right, s.b});
      if (next == from.end()) return s.b;  // an open end
      if (next->second == first) return -1;
      i = next->second;
    }
  };
  // Paths first: they start at a point no segment of the pair enters.
  for (int i = 0; i < static_cast<int>(segments_.size()); ++i) {
    const CellSegment& s = segments_[i];
    if (used[i] || into.count(Key{s.left, s.right, s.a})) continue;
    Loop loop{{}, {}, s.left, s.right, false};
    const int end = walk(i, loop);
    if (end < 0 || nif < 2 || !in_.points[s.a].is_face_interface() ||
        !in_.points[end].is_face_interface() || end == s.a)
      throw std::logic_error("split_cell: a contour component does not close");
    loop.points.push_back(end);
    if (centre >= 0) {
      loop.points.push_back(centre);
      loop.through_cell_point = true;
    }
    loops_.push_back(std::move(loop));
  }
  for (int i = 0; i < static_cast<int>(segments_.size()); ++i) {
    if (used[i]) continue;
    Loop loop{{}, {}, segments_[i].left, segments_[i].right, false};
    if (walk(i, loop) >= 0) throw std::logic_error("split_cell: a contour component does not close");
    loops_.push_back(std::move(loop));
  }
}

Splitter::EdgeNormals Splitter::fitted_points(const std::vector<int>& loop) const {
  EdgeNormals out;
  for (int p : loop)
    if (p < static_cast<int>(in_.points.size()) && in_.points[p].kind == CellPointKind::edge &&
        !in_.points[p].normal.isZero()) {
      out.points.push_back(in_.points[p].position);
      out.normals.push_back(in_.points[p].normal);
      out.level.push_back(on_boundary_[p] ? 0 : 1);
    }
  return out;
}

// A face point of the loop within snap * size of p that can be a fan centre (no fan
// triangle would lie in a cell face), or -1.
int Splitter::face_point_near(const Loop& loop, const Vec3& p) const {
  const int n = static_cast<int>(loop.points.size());
  for (int k = 0; k < n; ++k) {
    const int c = loop.points[k];
    if (c >= static_cast<int>(in_.points.size()) || in_.points[c].kind == CellPointKind::edge ||
        in_.points[c].kind == CellPointKind::grid || (position_[c] - p).norm() > options_.snap * size_)
      continue;
    bool ok = true;
    for (int j = 0; j < n && ok; ++j)
      if (j != k && j != (k + 1) % n && j != (k + n - 1) % n) ok = (faces_[loop.points[j]] & faces_[c]) == 0;
    if (ok) return c;
  }
  return -1;
}

// The ways to triangulate a component, the paper's choice first. Loops through the cell
// interface point are fans around it; a sharp feature keeps its feature point or edge.
std::vector<Candidate> Splitter::candidates(const Loop& loop) {
  if (loop.points.size() < 3) {
    // A path joining the two face interface points along a face: the link between them is
    // that segment (the paper's Fig. 10b), the component encloses nothing.
    return {{LoopMethod::degenerate, {}}};
  }
  if (loop.through_cell_point)
    return {{LoopMethod::interface_fan, triangulate_fan(loop.points, loop.points.back())}};
  std::vector<Candidate> out;
  const bool on_boundary = loop.lower == 0;
  if (options_.exact_points) {
    const EdgeNormals fit = fitted_points(loop.points);
    const std::vector<Vec3>& s = fit.points;
    const std::vector<Vec3>& n = fit.normals;
    // A junction with the domain's boundary lies on the boundary: its points fitted first.
    if (s.size() >= 2)
      if (const auto feature = sharp_feature(s, n, options_.feature, fit.level)) {
        if (!feature->corner) split_along_feature(loop.points, on_boundary, out);
        const int rank = feature->corner ? 3 : 2;
        const auto stepped = onto_surfaces(s, n, feature->point, rank);
        const Vec3 point = stepped ? stepped->first : feature->point;
        const std::span<const Vec3> ps = stepped ? stepped->second.points : s, pn = stepped ? stepped->second.normals : n;
        // Where the feature runs along a cell face, the face's own point on it (CMS feature
        // point or interface point) is the fan centre: a point beside it would make slivers.
        // Not a box's corner, which the face's point on one of its edges would cut off.
        const bool box_corner = feature->corner && on_boundary && on_octree_planes(s, n, point);
        if (const int on_face = box_corner ? -1 : face_point_near(loop, point); on_face >= 0)
          out.push_back({LoopMethod::feature_fan, triangulate_fan(loop.points, on_face)});
        else if (const auto p = clamp_component(loop.points, ps, pn, on_boundary, point, options_.feature_reach, rank))
          out.push_back({LoopMethod::feature_fan, triangulate_fan(loop.points, fan_centre(loop.points, *p))});
        if (!out.empty()) return out;
      }
  }
  smooth_candidates(loop.points, on_boundary, out);
  return out;
}

// A sharp edge crossing the cell enters and leaves it through two faces, at their CMS feature
// points: the segment between them is the edge (exact when straight, O(h^2) off a curved one).
// The component is split along it and each flat side triangulated on its own.
void Splitter::split_along_feature(const std::vector<int>& loop, bool on_boundary,
                                   std::vector<Candidate>& out) {
  const int n = static_cast<int>(loop.size());
  std::vector<int> at;
  for (int k = 0; k < n; ++k)
    if (loop[k] < static_cast<int>(in_.points.size()) && in_.points[loop[k]].kind == CellPointKind::face_feature)
      at.push_back(k);
  if (at.size() != 2) return;
  const int k1 = at[0], k2 = at[1];
  if (k2 - k1 < 2 || n - (k2 - k1) < 2 || (faces_[loop[k1]] & faces_[loop[k2]]) != 0) return;
  const std::vector<int> first(loop.begin() + k1, loop.begin() + k2 + 1);
  std::vector<int> second(loop.begin() + k2, loop.end());
  second.insert(second.end(), loop.begin(), loop.begin() + k1 + 1);
  std::vector<Candidate> a, b;
  smooth_candidates(first, on_boundary, a);
  smooth_candidates(second, on_boundary, b);
  const auto join = [&](std::size_t i, std::size_t j) {
    Candidate c{LoopMethod::feature_split, a[i].triangles};
    c.triangles.insert(c.triangles.end(), b[j].triangles.begin(), b[j].triangles.end());
    out.push_back(std::move(c));
  };
  join(0, 0);
  for (std::size_t i = 1; i < a.size(); ++i) join(i, 0);
  for (std::size_t j = 1; j < b.size(); ++j) join(0, j);
}

// A component without feature: the fan around its least-squares surface point when it has
// many points (divide and conquer cuts ears off them, small triangles far from the pieces'
// centres that checkMesh finds skewed; rank 1: the mass point moved onto the mean tangent
// plane, O(h^2) off the interface), otherwise divide and conquer (Algorithm 1); then the
// other of the two, §4.1's construction and the fan around the centroid.
void Splitter::smooth_candidates(const std::vector<int>& loop, bool on_boundary,
                                 std::vector<Candidate>& out) {
  if (loop.size() == 3) {
    out.push_back({LoopMethod::divide_and_conquer, {{loop[0], loop[1], loop[2]}}});
    return;
  }
  Vec3 mass = Vec3::Zero();
  for (int p : loop) mass += position_[p] / static_cast<double>(loop.size());
  std::optional<Candidate> surface;
  const EdgeNormals fit = fitted_points(loop);
  const std::vector<Vec3>& s = fit.points;
  const std::vector<Vec3>& n = fit.normals;
  if (!s.empty())
    if (const auto p = clamp_component(loop, s, n, on_boundary, tangent_intersection(s, n, mass, 1), options_.reach, 1))
      surface = Candidate{LoopMethod::surface_fan, triangulate_fan(loop, fan_centre(loop, *p))};
  const bool large = static_cast<int>(loop.size()) >= options_.fan_points;
  // After add_point: the spans must see the vectors as they are now.
  const LoopPoints points{position_, faces_};
  if (surface && large) out.push_back(*surface);
  if (auto t = triangulate_divide_and_conquer(points, loop)) out.push_back({LoopMethod::divide_and_conquer, std::move(*t)});
  if (surface && !large) out.push_back(*surface);
  if (auto t = triangulate_across_faces(points, loop)) out.push_back({LoopMethod::across_faces, std::move(*t)});
  if (const auto p = clamp_component(loop, s, n, on_boundary, mass, options_.reach, 1))
    out.push_back({LoopMethod::centroid_fan, triangulate_fan(loop, fan_centre(loop, *p))});
  if (out.empty()) out.push_back({LoopMethod::centroid_fan, triangulate_fan(loop, fan_centre(loop, mass))});
}

void Splitter::build_pieces() {
  const int np = static_cast<int>(in_.polygons.size());
  UnionFind sets(np);
  // Polygons sharing a piece of a cell edge (or of a line inside a transition face) that no
  // contour segment runs along.
  std::map<std::pair<int, int>, int> edge_polygon;
  std::vector<std::pair<int, int>> contour;
  for (const CellSegment& s : segments_) contour.push_back(edge_key(s.a, s.b));
  std::sort(contour.begin(), contour.end());
  for (int p = 0; p < np; ++p) {
    const std::vector<int>& loop = in_.polygons[p].points;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::pair<int, int> e = edge_key(loop[i], loop[(i + 1) % loop.size()]);
      if (std::binary_search(contour.begin(), contour.end(), e)) continue;
      const auto [it, fresh] = edge_polygon.emplace(e, p);
      if (!fresh) sets.unite(it->second, p);
    }
  }
  // Each component has one piece on either side.
  for (const Loop& loop : loops_)
    for (int s : loop.segments) {
      sets.unite(segments_[loop.segments[0]].left_polygon, segments_[s].left_polygon);
      sets.unite(segments_[loop.segments[0]].right_polygon, segments_[s].right_polygon);
    }
  std::vector<int> piece_of_root(np, -1);
  out_.polygon_piece.assign(np, -1);
  for (int p = 0; p < np; ++p) {
    const int root = sets.find(p);
    if (piece_of_root[root] < 0) {
      piece_of_root[root] = static_cast<int>(out_.pieces.size());
      out_.pieces.push_back({in_.polygons[p].region, {}});
    }
    CellPiece& piece = out_.pieces[piece_of_root[root]];
    if (piece.region != in_.polygons[p].region)
      throw std::logic_error("split_cell: a piece joins two regions");
    piece.polygons.push_back(p);
    out_.polygon_piece[p] = piece_of_root[root];
  }
}

// Triangles follow the loop, whose lower label lies on the left seen from outside: their
// normals point into the lower label's piece.
void Splitter::emit_triangles(const std::vector<std::vector<Triangle>>& triangles) {
  for (std::size_t l = 0; l < loops_.size(); ++l) {
    const auto [lower, higher] = loop_pieces(loops_[l]);
    for (const Triangle& t : triangles[l]) out_.triangles.push_back({t, lower, higher, static_cast<int>(l)});
  }
}

// Volume-weighted centres of the pieces, from their polygons (split around their vertex
// average) and the triangles.
std::vector<Vec3> Splitter::piece_centres(const std::vector<std::vector<Triangle>>& triangles) const {
  const std::size_t n = out_.pieces.size();
  std::vector<double> volume(n, 0.0);
  std::vector<Vec3> moment(n, Vec3::Zero());
  const Vec3 o = in_.corners[0];
  const auto add = [&](int piece, const Vec3& a, const Vec3& b, const Vec3& c) {
    const double v = tet_volume(o, a, b, c);
    volume[piece] += v;
    moment[piece] += v * (o + a + b + c) / 4.0;
  };
  for (std::size_t p = 0; p < in_.polygons.size(); ++p) {
    const std::vector<int>& loop = in_.polygons[p].points;
    Vec3 mid = Vec3::Zero();
    for (int v : loop) mid += position_[v] / static_cast<double>(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i)
      add(out_.polygon_piece[p], position_[loop[i]], position_[loop[(i + 1) % loop.size()]], mid);
  }
  for (std::size_t l = 0; l < loops_.size(); ++l) {
    const auto [lower, higher] = loop_pieces(loops_[l]);
    for (const Triangle& t : triangles[l]) {
      add(higher, position_[t[0]], position_[t[1]], position_[t[2]]);
      add(lower, position_[t[0]], position_[t[2]], position_[t[1]]);
    }
  }
  std::vector<Vec3> centre(n);
  for (std::size_t p = 0; p < n; ++p) centre[p] = volume[p] != 0.0 ? Vec3(moment[p] / volume[p]) : o;
  return centre;
}

// A triangle this flat (area / longest side squared) is as bad as an inverted one: its
// corners lie in a line up to rounding, it has no normal to orient it (`volmesh check`
// rejects it at 1e-12).
constexpr double kFlatTriangle = 1e-9;

// checkMesh's verdict on a face between the pieces with these centres (face_metrics.hpp):
// above 1 it is rejected. `outside` when the lower side is region 0: a boundary face.
double Splitter::badness(std::span<const int> face, const Vec3& owner, const Vec3& neighbour,
                         bool outside) const {
  FaceGeometry g;
  if (face.size() == 3) {
    const Vec3 &a = position_[face[0]], &b = position_[face[1]], &c = position_[face[2]];
    g.centre = (a + b + c) / 3.0;
    g.area_vector = 0.5 * (b - a).cross(c - a);
    if (flatness(position_, face, g.area_vector.norm()) <= kFlatTriangle) return kInvertedFace;
  } else {
    g = polygon_geometry(position_, std::vector<Index>(face.begin(), face.end()));
  }
  // Every inverted face counts alike here (the merging grades them): the choice among
  // triangulations stays as it was tuned.
  return std::min(kInvertedFace,
                  checkmesh_badness(g, position_, face, owner, outside ? nullptr : &neighbour,
                                    {options_.skewness_limit, options_.max_non_orthogonality}));
}

// The last resort for a face still rejected: merged with a neighbouring face of its
// component (sharing one edge, nearly coplanar unless it is a sliver) into a polygon, as
// long as that lowers its badness. The interface does not move; the trace is no longer a
// triangulation there.
void Splitter::merge_skewed(std::vector<std::vector<Triangle>>& triangles,
                            const std::vector<LoopMethod>& methods) {
  const std::vector<Vec3> centre = piece_centres(triangles);
  const double cos_limit = std::cos(options_.merge_angle * std::acos(-1.0) / 180.0);
  for (std::size_t l = 0; l < loops_.size(); ++l) {
    const auto [lower, higher] = loop_pieces(loops_[l]);
    const bool outside = out_.pieces[lower].region == 0;
    const bool sharp = methods[l] == LoopMethod::feature_split || methods[l] == LoopMethod::feature_fan ||
                       methods[l] == LoopMethod::interface_fan;
    const auto skew = [&](const std::vector<int>& f) { return badness(f, centre[higher], centre[lower], outside); };
    std::vector<std::vector<int>> faces;
    for (const Triangle& t : triangles[l]) faces.push_back({t[0], t[1], t[2]});
    for (std::size_t f = 0; f < faces.size(); ++f) {
      while (!faces[f].empty() && skew(faces[f]) > 1.0) {
        double best = skew(faces[f]);
        std::size_t best_g = faces.size();
        std::vector<int> best_union;
        const Vec3 af = polygon_geometry(position_, std::vector<Index>(faces[f].begin(), faces[f].end())).area_vector;
        const Vec3 nf = af.normalized();
        for (std::size_t g = 0; g < faces.size(); ++g) {
          if (g == f || faces[g].empty()) continue;
          const std::vector<int> merged = merge_along_edge(faces[f], faces[g]);
          // A polygon folded over itself would fold the pieces on it.
          if (merged.empty() || split_polygon(position_, std::vector<Index>(merged.begin(), merged.end())).folded) continue;
          const Vec3 ag = polygon_geometry(position_, std::vector<Index>(faces[g].begin(), faces[g].end())).area_vector;
          // A sliver's normal means little: it may join a face four times its size at any
          // angle, but not across a sharp edge the component keeps (a feature split or fan,
          // or a fan around a junction), which the polygon would cut off or fill in;
          // reflex_split splits such a piece.
          if (nf.dot(ag.normalized()) < cos_limit && (sharp || af.norm() > 0.25 * ag.norm())) continue;
          if (const double w = skew(merged); w < best) {
            best = w;
            best_g = g;
            best_union = merged;
          }
        }
        if (best_g == faces.size()) break;
        faces[f] = std::move(best_union);
        faces[best_g].clear();
      }
    }
    triangles[l].clear();
    for (std::vector<int>& f : faces) {
      if (f.size() == 3) triangles[l].push_back({f[0], f[1], f[2]});
      else if (!f.empty()) out_.polygons.push_back({std::move(f), lower, higher, static_cast<int>(l)});
    }
  }
}

// Flips the diagonal of two coplanar triangles of a component (the surface does not move)
// where that lowers the larger skewness of the two: a fan around a feature point running
// next to a cell face leaves slivers on the flat facets beside it.
void Splitter::flip_slivers(std::vector<std::vector<Triangle>>& triangles) {
  const std::vector<Vec3> centre = piece_centres(triangles);
  const double flat = options_.flat * size_;
  for (std::size_t l = 0; l < loops_.size(); ++l) {
    std::vector<Triangle>& tris = triangles[l];
    const auto [lower, higher] = loop_pieces(loops_[l]);
    const bool outside = out_.pieces[lower].region == 0;
    const auto skew = [&](const Triangle& t) { return badness(t, centre[higher], centre[lower], outside); };
    for (int pass = 0; pass < 4; ++pass) {
      bool flipped = false;
      for (std::size_t i = 0; i < tris.size(); ++i)
        for (std::size_t j = i + 1; j < tris.size(); ++j)
          for (int e = 0; e < 3; ++e) {
            // t1 = (u, v, a) and t2 holding v -> u with third point b.
            const int u = tris[i][e], v = tris[i][(e + 1) % 3], a = tris[i][(e + 2) % 3];
            int f = 0;
            while (f < 3 && !(tris[j][f] == v && tris[j][(f + 1) % 3] == u)) ++f;
            if (f == 3) continue;
            const int b = tris[j][(f + 2) % 3];
            if ((faces_[a] & faces_[b]) != 0 || a == b) continue;
            const Vec3 n1 = (position_[v] - position_[u]).cross(position_[a] - position_[u]);
            const Vec3 n2 = (position_[u] - position_[v]).cross(position_[b] - position_[v]);
            if (std::abs(n1.normalized().dot(position_[b] - position_[u])) > flat ||
                std::abs(n2.normalized().dot(position_[a] - position_[u])) > flat)
              continue;
            const Triangle s1{u, b, a}, s2{v, a, b};
            const Vec3 m1 = (position_[b] - position_[u]).cross(position_[a] - position_[u]);
            const Vec3 m2 = (position_[a] - position_[v]).cross(position_[b] - position_[v]);
            if (m1.dot(n1) <= 0.0 || m2.dot(n1) <= 0.0) continue;  // the quad is not convex
            if (std::max(skew(s1), skew(s2)) + 1e-9 >= std::max(skew(tris[i]), skew(tris[j]))) continue;
            tris[i] = s1;
            tris[j] = s2;
            flipped = true;
            e = 3;
          }
      if (!flipped) break;
    }
  }
}

// The worst badness of the triangles, from the pieces' centres.
double Splitter::worst_badness(const std::vector<std::vector<Triangle>>& triangles) const {
  const std::vector<Vec3> centre = piece_centres(triangles);
  double worst = 0.0;
  for (std::size_t l = 0; l < loops_.size(); ++l) {
    const auto [lower, higher] = loop_pieces(loops_[l]);
    for (const Triangle& t : triangles[l])
      worst = std::max(worst, badness(t, centre[higher], centre[lower], out_.pieces[lower].region == 0));
  }
  return worst;
}

CellSplit Splitter::run() {
  build_loops();
  std::vector<std::vector<Candidate>> options;
  for (const Loop& loop : loops_) options.push_back(candidates(loop));
  build_pieces();
  std::vector<std::size_t> choice(loops_.size(), 0);
  std::vector<std::vector<Triangle>> triangles;
  for (std::size_t l = 0; l < loops_.size(); ++l) triangles.push_back(std::move(options[l][0].triangles));
  double worst = worst_badness(triangles);
  if (worst > 1.0) {
    // A face checkMesh would reject: flip slivers on flat facets, then try the
    // other triangulations, component by component, keeping any that lowers the worst.
    options_copy_back(options, triangles);
    const auto chosen = [&] {
      std::vector<std::vector<Triangle>> t;
      for (std::size_t l = 0; l < loops_.size(); ++l) t.push_back(options[l][choice[l]].triangles);
      flip_slivers(t);
      return t;
    };
    triangles = chosen();
    worst = worst_badness(triangles);
    for (std::size_t l = 0; l < loops_.size() && worst > 1.0; ++l)
      for (std::size_t c = 0; c < options[l].size(); ++c) {
        if (c == choice[l]) continue;
        const std::size_t kept = choice[l];
        choice[l] = c;
        std::vector<std::vector<Triangle>> t = chosen();
        if (const double w = worst_badness(t); w < worst) {
          worst = w;
          triangles = std::move(t);
        } else {
          choice[l] = kept;
        }
      }
    if (worst > 1.0 && options_.merge_angle > 0.0) {
      std::vector<LoopMethod> methods;
      for (std::size_t l = 0; l < loops_.size(); ++l) methods.push_back(options[l][choice[l]].method);
      merge_skewed(triangles, methods);
      const std::vector<Vec3> centre = piece_centres(triangles);
      worst = worst_badness(triangles);
      for (const PiecePolygon& p : out_.polygons)
        worst = std::max(worst, badness(p.points, centre[p.higher], centre[p.lower],
                                         out_.pieces[p.lower].region == 0));
    }
  }
  for (std::size_t l = 0; l < loops_.size(); ++l) out_.loops.push_back(options[l][choice[l]].method);
  emit_triangles(triangles);
  out_.max_badness = worst;
  return std::move(out_);
}

}  // namespace

namespace {

// The planes of the six faces: centre and outward unit normal.
std::array<std::pair<Vec3, Vec3>, 6> face_planes(const std::array<Vec3, 8>& corners) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& c : corners) centre += c / 8.0;
  std::array<std::pair<Vec3, Vec3>, 6> planes;
  for (int k = 0; k < 6; ++k) {
    const std::array<int, 4> f = face_corners(k);
    const Vec3 face_centre = 0.25 * (corners[f[0]] + corners[f[1]] + corners[f[2]] + corners[f[3]]);
    Vec3 normal = (corners[f[2]] - corners[f[0]]).cross(corners[f[3]] - corners[f[1]]).normalized();
    if (normal.dot(face_centre - centre) < 0) normal = -normal;
    planes[k] = {face_centre, normal};
  }
  return planes;
}

}  // namespace

double depth_inside_cell(const std::array<Vec3, 8>& corners, const Vec3& p) {
  double depth = std::numeric_limits<double>::infinity();
  for (const auto& [centre, normal] : face_planes(corners)) depth = std::min(depth, normal.dot(centre - p));
  return depth;
}

std::optional<Vec3> clamp_into_cell(const std::array<Vec3, 8>& corners, Vec3 p, double margin,
                                    double reach) {
  const auto planes = face_planes(corners);
  double depth = std::numeric_limits<double>::infinity();
  for (const auto& [centre, normal] : planes) depth = std::min(depth, normal.dot(centre - p));
  if (depth < -reach) return std::nullopt;
  for (int pass = 0; pass < 3; ++pass)
    for (const auto& [centre, normal] : planes)
      if (const double d = normal.dot(centre - p); d < margin) p -= (margin - d) * normal;
  return p;
}

std::optional<Vec3> slide_into_cell(const std::array<Vec3, 8>& corners, const Vec3& p, const Vec3& direction,
                                    double margin, double reach) {
  // Each face plane bounds the move s: normal . (centre - p - s direction) >= margin.
  double lo = -reach, hi = reach;
  for (const auto& [centre, normal] : face_planes(corners)) {
    const double room = normal.dot(centre - p) - margin, rate = normal.dot(direction);
    if (rate > 0.0) hi = std::min(hi, room / rate);
    else if (rate < 0.0) lo = std::max(lo, room / rate);
    else if (room < 0.0) return std::nullopt;
  }
  if (lo > hi) return std::nullopt;
  const double s = lo > 0.0 ? lo : (hi < 0.0 ? hi : 0.0);
  return p + s * direction;
}

CellSplit split_cell(const CellInput& cell, const CellOptions& options) {
  return Splitter(cell, options).run();
}

// The union of two faces sharing exactly one edge (u -> v in a, v -> u in b), or empty when
// they share none or more, or the union would touch itself.
std::vector<int> merge_along_edge(const std::vector<int>& a, const std::vector<int>& b) {
  const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());
  int shared = 0, ia = -1, ib = -1;
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j)
      if (a[i] == b[(j + 1) % nb] && a[(i + 1) % na] == b[j]) {
        ++shared;
        ia = i;
        ib = j;
      }
  if (shared != 1) return {};
  // a from v around to u, then b from u (exclusive) around to v (exclusive).
  std::vector<int> out;
  for (int k = 1; k <= na; ++k) out.push_back(a[(ia + k) % na]);
  for (int k = 2; k < nb; ++k) out.push_back(b[(ib + k) % nb]);
  std::vector<int> sorted = out;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return {};
  return out;
}

}  // namespace volmesh::cutcell
