// The cell interface point (the octree paper, §3.3): where more than two face interface
// points occur, the junction of the interfaces inside the cell, which every path between
// them goes through; where two occur, only when the junction bends away from their link.
#include <cmath>
#include <numeric>
#include <optional>

#include "cell_planes.hpp"
#include "cell_split_state.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh::cutcell {
namespace {

// A junction point slides along its line into the cell keeping the junction margin, or
// down to this fraction of it, halving, where the line passes by a cell edge.
constexpr double kLeastSlideMargin = 0.25;
// The free direction of the normals runs along the link between two face interface points
// when the cosine of their angle exceeds this (within about 26 degrees).
constexpr double kAlongLinkCosine = 0.9;

// Whether the normals at these edge points show a sharp edge.
bool normals_are_sharp(const SplitState& s, std::span<const Vec3> normals) {
  for (std::size_t i = 0; i < normals.size(); ++i)
    for (std::size_t j = i + 1; j < normals.size(); ++j)
      if (normals[i].dot(normals[j]) < s.options.feature.theta) return true;
  return false;
}

// Where two face interface points are all the cell has, the link between them is the
// junction unless it bends inside the cell: at a sharp edge of the domain's boundary (a
// layer ending on the box's edge), or of an interface where regions meet inside (a box's
// edge in a ball, meeting a cylinder's end). Inside, only where the least-squares junction
// point lies clear of the cell's faces: pushed in from near them it bends the interfaces
// more than the link does.
bool junction_may_bend(const SplitState& s, const EdgeNormals& edges, const Vec3& junction) {
  std::vector<Vec3> boundary;
  for (std::size_t i = 0; i < edges.points.size(); ++i)
    if (edges.level[i] == 0) boundary.push_back(edges.normals[i]);
  if (normals_are_sharp(s, boundary)) return true;
  if (!normals_are_sharp(s, edges.normals)) return false;
  return depth_inside_cell(s.in.corners, junction) >= s.options.junction_margin * s.size;
}

// Whether the junction point lies farther than bend * size from the link between the two
// face interface points: the link would cut the edge off.
bool junction_bends(const SplitState& s, const std::vector<int>& face_points, const Vec3& fitted) {
  return distance_to_segment(fitted, s.position[face_points[0]], s.position[face_points[1]]) >
         s.options.bend * s.size;
}

// Whether the edge points' normals leave free only the direction of the link between the
// two face interface points: surfaces crossing along a line through both (a cylinder
// through a plane), which the link follows to O(h^2). Their least-squares point
// extrapolates the tangent planes of far edge points across the cell and may lie well off
// the line.
bool junction_along_link(const SplitState& s, const EdgeNormals& edges, const std::vector<int>& face_points) {
  const std::optional<Vec3> line = free_direction(edges.normals);
  if (!line) return false;
  const Vec3 link = s.position[face_points[1]] - s.position[face_points[0]];
  return std::abs(line->dot(link)) > kAlongLinkCosine * link.norm();
}

// The least-squares junction point of the cell's edge points (those on the domain's boundary
// fitted first: `fit`), on the true surfaces and moved inside the cell; nullopt when it
// lies beyond reach.
std::optional<Vec3> fitted_cell_point(const SplitState& s, const EdgeNormals& edges, const Vec3& fit) {
  const double margin = s.options.junction_margin * s.size, reach = s.options.reach * s.size;
  const auto stepped = onto_surfaces(s.options, s.size, edges.points, edges.normals, fit, kPointRank);
  const Vec3 junction = stepped ? stepped->first : fit;
  std::optional<Vec3> p;
  // On a junction line (a sphere meeting a plane) the point slides along the line into the
  // cell; pushed in across the faces it would leave the line by up to the margin.
  if (depth_inside_cell(s.in.corners, junction) < margin)
    if (const std::optional<Vec3> line = free_direction(edges.normals))
      for (double m = margin; !p && m >= kLeastSlideMargin * margin; m *= 0.5)
        p = slide_into_cell(s.in.corners, junction, *line, m, reach);
  if (!p) p = clamp_into_cell(s.in.corners, junction, margin, reach);
  if (!p) return p;
  const auto [planes, normals] = boundary_planes(edges);
  return onto_planes(s, planes, normals, *p, margin, kPointRank);
}

// The point with exact points: `fitted` (fitted_cell_point), else the centroid of the face
// interface points on the boundary's planes.
int exact_cell_point(SplitState& s, const std::vector<int>& face_points, const std::optional<Vec3>& fitted,
                     const EdgeNormals& edges) {
  if (fitted) return s.add_point(*fitted);
  s.out.cell_point_left_cell = true;
  Vec3 p = Vec3::Zero();
  for (int f : face_points) p += s.position[f] / static_cast<double>(face_points.size());
  const auto [planes, normals] = boundary_planes(edges);
  return s.add_point(onto_planes(s, planes, normals, p, s.options.margin * s.size, kPointRank));
}

}  // namespace

int cell_interface_point(SplitState& s, const std::vector<int>& face_points) {
  const std::size_t count = face_points.size();
  if (!s.options.exact_points) {
    // M3C as published: the cell's centre.
    if (count <= 2) return -1;
    Vec3 p = Vec3::Zero();
    for (const Vec3& c : s.in.corners) p += c / 8.0;
    return s.add_point(p);
  }
  if (count < 2) return -1;
  std::vector<int> all(s.in.points.size());
  std::iota(all.begin(), all.end(), 0);
  const EdgeNormals edges = fitted_points(s, all);
  // The least-squares junction of the edge points, those on the domain's boundary first.
  const std::optional<Vec3> junction =
      edges.points.empty() ? std::nullopt
                           : std::optional(tangent_intersection_ranked(edges.points, edges.normals, edges.level, kPointRank));
  if (count == 2 && !(junction && junction_may_bend(s, edges, *junction) && !junction_along_link(s, edges, face_points)))
    return -1;
  const std::optional<Vec3> fitted = junction ? fitted_cell_point(s, edges, *junction) : std::nullopt;
  if (count == 2 && !(fitted && junction_bends(s, face_points, *fitted))) return -1;
  return exact_cell_point(s, face_points, fitted, edges);
}

}  // namespace volmesh::cutcell
