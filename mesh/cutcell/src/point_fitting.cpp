// The points M3C makes inside a cell (feature points, fan centres, the cell interface point)
// fitted onto the tangent planes of the interfaces at the edge points, and onto the true
// surfaces by a Newton step, while kept inside the cell.
#include <algorithm>
#include <cmath>
#include <limits>

#include "cell_planes.hpp"
#include "cell_split_state.hpp"

namespace volmesh::cutcell {
namespace {

// Alternating projections onto the planes and into the cell settle within a few passes
// where both can hold; this bounds the work where they cannot.
constexpr int kProjectionPasses = 8;
// The clamp leaves the point at the margin, the projection after it may move it back by
// rounding: a point at this fraction of the margin is in.
constexpr double kMarginSlack = 0.99;
// The surfaces are sought this fraction of the reach along themselves toward their points
// (planes_near_feature's shift): a surface ending at the feature lies on that side.
constexpr double kSurfaceShift = 0.4;
// A Newton step converges when every surface, found again beside the new point, lies within
// this fraction of the step from it (a converging step lands off the surfaces by the square
// of its length); the planes found are otherwise not those meeting at the start.
constexpr double kNewtonAgreement = 0.25;
// The same test's floor, relative to the cell's size, for a step of no length.
constexpr double kNewtonFloor = 1e-12;
// Boundary normals lie on planes when each direction other than an axis shows at two points
// or more (few_directions): a direction seen once may be one normal of a curved surface.
constexpr int kPlanePoints = 2;

}  // namespace

EdgeNormals fitted_points(const SplitState& s, const std::vector<int>& points) {
  EdgeNormals out;
  for (int p : points)
    if (p < static_cast<int>(s.in.points.size()) && s.in.points[p].kind == CellPointKind::edge &&
        !s.in.points[p].normal.isZero()) {
      out.points.push_back(s.in.points[p].position);
      out.normals.push_back(s.in.points[p].normal);
      out.level.push_back(s.on_boundary[p] ? 0 : 1);
    }
  return out;
}

std::pair<std::vector<Vec3>, std::vector<Vec3>> boundary_planes(const EdgeNormals& edges) {
  std::pair<std::vector<Vec3>, std::vector<Vec3>> out;
  for (std::size_t i = 0; i < edges.points.size(); ++i)
    if (edges.level[i] == 0) {
      out.first.push_back(edges.points[i]);
      out.second.push_back(edges.normals[i]);
    }
  return out;
}

bool on_octree_planes(std::span<const Vec3> s, std::span<const Vec3> n, const Vec3& p, double size) {
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!parallel_to_octree_faces(n[i]) || std::abs(n[i].dot(p - s[i])) > kSamePoint * size) return false;
  return !s.empty();
}

// Alternating projections: pushing a point on the domain's boundary off a face must not
// push it off a planar boundary, or the domain's volume changes. p itself when the normals
// take more than max_rank directions (a curved boundary: no plane to keep), or the point
// would leave the cell.
Vec3 onto_planes(const SplitState& st, std::span<const Vec3> s, std::span<const Vec3> n, Vec3 p, double margin,
                 int max_rank) {
  if (s.empty() || !few_directions(n, max_rank, kPlanePoints) ||
      !(st.materials_meet || std::all_of(n.begin(), n.end(), parallel_to_octree_faces)))
    return p;
  const Vec3 start = p;
  for (int pass = 0; pass < kProjectionPasses; ++pass) {
    p = tangent_intersection(s, n, p, max_rank);
    if (depth_inside_cell(st.in.corners, p) >= kMarginSlack * margin) break;
    p = *clamp_into_cell(st.in.corners, p, margin, std::numeric_limits<double>::infinity());
  }
  p = tangent_intersection(s, n, p, max_rank);
  // A boundary that crosses a face warped by vertex moves may run just outside the face's
  // mean plane: the point may follow it as far as the junction margin.
  return depth_inside_cell(st.in.corners, p) > -st.options.junction_margin * st.size ? p : start;
}

// On the domain's boundary the centre stays on the component's tangent planes (through its
// fitted points s with normals n, at most max_rank of them), unless that turns a fan
// triangle over: a centre moved onto a sharp edge beyond the loop's own point on it folds
// the fan.
std::optional<Vec3> clamp_component(const SplitState& st, const std::vector<int>& loop, std::span<const Vec3> s,
                                    std::span<const Vec3> n, bool on_boundary, const Vec3& p, double reach,
                                    int max_rank) {
  const std::optional<Vec3> q = clamp_into_cell(st.in.corners, p, st.options.margin * st.size, reach * st.size);
  if (!q || !on_boundary) return q;
  // A point on the boundary's planes parallel to the octree's faces (a box's corner or edge)
  // stays where it is in the cell: next to the domain's boundary only the outside piece,
  // which is dropped, lies between it and the faces it is near, and pushed in it would cut
  // the corner off. As in onto_planes, it may lie as far as the junction margin outside the
  // mean planes of faces warped by vertex moves.
  const Vec3 r = depth_inside_cell(st.in.corners, p) > -st.options.junction_margin * st.size &&
                         on_octree_planes(s, n, p, st.size)
                     ? p
                     : onto_planes(st, s, n, *q, st.options.margin * st.size, max_rank);
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3 &a = st.position[loop[k]], &b = st.position[loop[(k + 1) % loop.size()]];
    if (!((a - *q).cross(b - *q).dot((a - r).cross(b - r)) > 0.0)) return q;
  }
  return r;
}

// nullopt without surface_near, when a surface is not found again, or when the step does
// not converge (kNewtonAgreement).
std::optional<std::pair<Vec3, TangentPlanes>> onto_surfaces(const CellOptions& options, double size,
                                                            std::span<const Vec3> s, std::span<const Vec3> n,
                                                            const Vec3& x, int max_rank) {
  if (!options.exact_points || !options.surface_near) return std::nullopt;
  const double reach = options.newton_reach * size;
  std::optional<TangentPlanes> found = planes_near_feature(s, n, x, reach, kSurfaceShift * reach, options.surface_near);
  if (!found) return std::nullopt;
  const Vec3 p = tangent_intersection(found->points, found->normals, x, max_rank);
  const double step = (p - x).norm();
  if (!(step < reach)) return std::nullopt;
  const std::optional<TangentPlanes> again =
      planes_near_feature(found->points, found->normals, p, reach, kSurfaceShift * reach, options.surface_near);
  if (!again || again->points.size() != found->points.size()) return std::nullopt;
  for (std::size_t k = 0; k < again->points.size(); ++k)
    if (!(std::abs(again->normals[k].dot(p - again->points[k])) <= kNewtonAgreement * step + kNewtonFloor * size))
      return std::nullopt;
  return std::pair{p, std::move(*found)};
}

}  // namespace volmesh::cutcell
