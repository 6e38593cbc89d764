// The ways to triangulate one closed component, the paper's choice first: loops through the
// cell interface point are fans around it; a sharp feature keeps its feature point or edge
// (Kobbelt's EMC test); a smooth component is fanned around its surface point or split by
// divide and conquer, then §4.1's construction and the fan around its centroid.
#include "cell_split_state.hpp"

namespace volmesh::cutcell {
namespace {

// A face point of the loop within snap * size of p that can be a fan centre (no fan
// triangle would lie in a cell face), or -1.
int face_point_near(const SplitState& s, const Loop& loop, const Vec3& p) {
  const int n = static_cast<int>(loop.points.size());
  for (int k = 0; k < n; ++k) {
    const int c = loop.points[k];
    if (c >= static_cast<int>(s.in.points.size()) || s.in.points[c].kind == CellPointKind::edge ||
        s.in.points[c].kind == CellPointKind::grid || (s.position[c] - p).norm() > s.options.snap * s.size)
      continue;
    bool ok = true;
    for (int j = 0; j < n && ok; ++j)
      if (j != k && j != (k + 1) % n && j != (k + n - 1) % n) ok = (s.faces[loop.points[j]] & s.faces[c]) == 0;
    if (ok) return c;
  }
  return -1;
}

// A component without feature: the fan around its least-squares surface point when it has
// many points (divide and conquer cuts ears off them, small triangles far from the pieces'
// centres that checkMesh finds skewed; kSheetRank: the mass point moved onto the mean tangent
// plane, O(h^2) off the interface), otherwise divide and conquer (Algorithm 1); then the
// other of the two, §4.1's construction and the fan around the centroid.
void smooth_candidates(SplitState& st, const std::vector<int>& loop, bool on_boundary, std::vector<Candidate>& out) {
  if (loop.size() == 3) {
    out.push_back({LoopMethod::divide_and_conquer, {{loop[0], loop[1], loop[2]}}});
    return;
  }
  Vec3 mass = Vec3::Zero();
  for (int p : loop) mass += st.position[p] / static_cast<double>(loop.size());
  std::optional<Candidate> surface;
  const EdgeNormals fit = fitted_points(st, loop);
  const std::vector<Vec3>& s = fit.points;
  const std::vector<Vec3>& n = fit.normals;
  if (!s.empty()) {
    const Vec3 on_sheet = tangent_intersection(s, n, mass, kSheetRank);
    if (const auto p = clamp_component(st, loop, s, n, on_boundary, on_sheet, st.options.reach, kSheetRank))
      surface = Candidate{LoopMethod::surface_fan, triangulate_fan(loop, st.fan_centre(loop, *p))};
  }
  const bool large = static_cast<int>(loop.size()) >= st.options.fan_points;
  // After add_point: the spans must see the vectors as they are now.
  const LoopPoints points{st.position, st.faces};
  if (surface && large) out.push_back(*surface);
  if (auto t = triangulate_divide_and_conquer(points, loop)) out.push_back({LoopMethod::divide_and_conquer, std::move(*t)});
  if (surface && !large) out.push_back(*surface);
  if (auto t = triangulate_across_faces(points, loop)) out.push_back({LoopMethod::across_faces, std::move(*t)});
  if (const auto p = clamp_component(st, loop, s, n, on_boundary, mass, st.options.reach, kSheetRank))
    out.push_back({LoopMethod::centroid_fan, triangulate_fan(loop, st.fan_centre(loop, *p))});
  if (out.empty()) out.push_back({LoopMethod::centroid_fan, triangulate_fan(loop, st.fan_centre(loop, mass))});
}

// A sharp edge crossing the cell enters and leaves it through two faces, at their CMS feature
// points: the segment between them is the edge (exact when straight, O(h^2) off a curved one).
// The component is split along it and each flat side triangulated on its own.
void split_along_feature(SplitState& st, const std::vector<int>& loop, bool on_boundary, std::vector<Candidate>& out) {
  const int n = static_cast<int>(loop.size());
  std::vector<int> at;
  for (int k = 0; k < n; ++k)
    if (loop[k] < static_cast<int>(st.in.points.size()) && st.in.points[loop[k]].kind == CellPointKind::face_feature)
      at.push_back(k);
  if (at.size() != 2) return;
  const int k1 = at[0], k2 = at[1];
  if (k2 - k1 < 2 || n - (k2 - k1) < 2 || (st.faces[loop[k1]] & st.faces[loop[k2]]) != 0) return;
  const std::vector<int> first(loop.begin() + k1, loop.begin() + k2 + 1);
  std::vector<int> second(loop.begin() + k2, loop.end());
  second.insert(second.end(), loop.begin(), loop.begin() + k1 + 1);
  std::vector<Candidate> a, b;
  smooth_candidates(st, first, on_boundary, a);
  smooth_candidates(st, second, on_boundary, b);
  const auto join = [&](std::size_t i, std::size_t j) {
    Candidate c{LoopMethod::feature_split, a[i].triangles};
    c.triangles.insert(c.triangles.end(), b[j].triangles.begin(), b[j].triangles.end());
    out.push_back(std::move(c));
  };
  join(0, 0);
  for (std::size_t i = 1; i < a.size(); ++i) join(i, 0);
  for (std::size_t j = 1; j < b.size(); ++j) join(0, j);
}

}  // namespace

std::vector<Candidate> loop_candidates(SplitState& st, const Loop& loop) {
  if (loop.points.size() < 3) {
    // A path joining the two face interface points along a face: the link between them is
    // that segment (the paper's Fig. 10b), the component encloses nothing.
    return {{LoopMethod::degenerate, {}}};
  }
  if (loop.through_cell_point)
    return {{LoopMethod::interface_fan, triangulate_fan(loop.points, loop.points.back())}};
  std::vector<Candidate> out;
  const bool on_boundary = loop.lower == 0;
  if (st.options.exact_points) {
    const EdgeNormals fit = fitted_points(st, loop.points);
    const std::vector<Vec3>& s = fit.points;
    const std::vector<Vec3>& n = fit.normals;
    // A junction with the domain's boundary lies on the boundary: its points fitted first.
    if (s.size() >= 2)
      if (const auto feature = sharp_feature(s, n, st.options.feature, fit.level)) {
        if (!feature->corner) split_along_feature(st, loop.points, on_boundary, out);
        const int rank = feature->corner ? kPointRank : kEdgeRank;
        const auto stepped = onto_surfaces(st.options, st.size, s, n, feature->point, rank);
        const Vec3 point = stepped ? stepped->first : feature->point;
        const std::span<const Vec3> ps = stepped ? stepped->second.points : s, pn = stepped ? stepped->second.normals : n;
        // Where the feature runs along a cell face, the face's own point on it (CMS feature
        // point or interface point) is the fan centre: a point beside it would make slivers.
        // Not a box's corner, which the face's point on one of its edges would cut off.
        const bool box_corner = feature->corner && on_boundary && on_octree_planes(s, n, point, st.size);
        if (const int on_face = box_corner ? -1 : face_point_near(st, loop, point); on_face >= 0)
          out.push_back({LoopMethod::feature_fan, triangulate_fan(loop.points, on_face)});
        else if (const auto p = clamp_component(st, loop.points, ps, pn, on_boundary, point,
                                                st.options.feature_reach, rank))
          out.push_back({LoopMethod::feature_fan, triangulate_fan(loop.points, st.fan_centre(loop.points, *p))});
        if (!out.empty()) return out;
      }
  }
  smooth_candidates(st, loop.points, on_boundary, out);
  return out;
}

}  // namespace volmesh::cutcell
