#include "volmesh/core/geometry.hpp"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace volmesh {
namespace {

// fan_is_proper's rounding floor, relative to an equal triangle's share of the polygon's
// area (|area|^2 / n): far above the rounding of a flat polygon's fan, far below any triangle
// that really faces the polygon's way.
constexpr double kFanFloor = 1e-10;

}  // namespace

double flatness(const std::vector<Vec3>& points, std::span<const Index> loop, double area) {
  double longest = 0.0;
  for (std::size_t k = 0; k < loop.size(); ++k)
    longest = std::max(longest, (points[loop[(k + 1) % loop.size()]] - points[loop[k]]).squaredNorm());
  return longest > 0.0 ? area / longest : 0.0;
}

FaceGeometry polygon_geometry(const std::vector<Vec3>& points, std::span<const Index> loop) {
  const std::size_t n = loop.size();
  if (n == 3) {
    const Vec3& a = points[loop[0]];
    const Vec3& b = points[loop[1]];
    const Vec3& c = points[loop[2]];
    return {0.5 * (b - a).cross(c - a), (a + b + c) / 3.0};
  }
  Vec3 mid = Vec3::Zero();
  for (Index v : loop) mid += points[v];
  mid /= static_cast<double>(n);
  // Triangles (p_i, p_i+1, mid); centroid weighted by each triangle's area projected on
  // the face normal, as OpenFOAM does, so that warped faces get a stable centre.
  Vec3 area = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = points[loop[i]];
    const Vec3& q = points[loop[(i + 1) % n]];
    area += 0.5 * (q - p).cross(mid - p);
  }
  const double mag = area.norm();
  if (mag == 0.0) return {area, mid};
  const Vec3 normal = area / mag;
  Vec3 centre = Vec3::Zero();
  double weight = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = points[loop[i]];
    const Vec3& q = points[loop[(i + 1) % n]];
    const double w = std::abs(0.5 * (q - p).cross(mid - p).dot(normal));
    centre += w * (p + q + mid) / 3.0;
    weight += w;
  }
  return {area, weight > 0.0 ? Vec3(centre / weight) : mid};
}

bool fan_is_proper(const std::vector<Vec3>& points, std::span<const Index> loop) {
  const std::size_t n = loop.size();
  Vec3 m = Vec3::Zero();
  for (Index v : loop) m += points[v];
  m /= static_cast<double>(n);
  const auto area = [&](std::size_t k) {
    const Vec3& p = points[loop[k]];
    return Vec3((points[loop[(k + 1) % n]] - p).cross(m - p));
  };
  Vec3 total = Vec3::Zero();
  for (std::size_t k = 0; k < n; ++k) total += area(k);
  const double floor = kFanFloor * total.squaredNorm() / static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k)
    if (!(area(k).dot(total) > floor)) return false;
  return true;
}

FaceGeometry face_geometry(const PolyMesh& mesh, Index f) {
  return polygon_geometry(mesh.points, mesh.face(f));
}

CellGeometry cell_geometry(const PolyMesh& mesh, std::span<const Index> faces, Index c,
                           const std::vector<FaceGeometry>& face_geom) {
  Vec3 estimate = Vec3::Zero();
  for (Index f : faces) estimate += face_geom[f].centre;
  if (!faces.empty()) estimate /= static_cast<double>(faces.size());
  // Tets (estimate, face centre, p_i, p_i+1) over the same face triangulation that
  // polygon_geometry uses: exact for the piecewise-planar cell, shared with the neighbour.
  double volume = 0.0;
  Vec3 moment = Vec3::Zero();
  for (Index f : faces) {
    const auto loop = mesh.face(f);
    const std::size_t n = loop.size();
    const bool outward = mesh.owner[f] == c;
    if (n == 3) {
      const Vec3& a = mesh.points[loop[0]];
      const Vec3& b = mesh.points[loop[outward ? 1 : 2]];
      const Vec3& d = mesh.points[loop[outward ? 2 : 1]];
      const double v = tet_volume(estimate, a, b, d);
      volume += v;
      moment += v * (estimate + a + b + d) / 4.0;
      continue;
    }
    Vec3 mid = Vec3::Zero();
    for (Index p : loop) mid += mesh.points[p];
    mid /= static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& p = mesh.points[loop[i]];
      const Vec3& q = mesh.points[loop[(i + 1) % n]];
      const double v = outward ? tet_volume(estimate, p, q, mid) : tet_volume(estimate, q, p, mid);
      volume += v;
      moment += v * (estimate + p + q + mid) / 4.0;
    }
  }
  const Vec3 centre = volume != 0.0 ? Vec3(moment / volume) : estimate;
  return {volume, centre};
}

// In parallel; each face and cell on its own, so the result does not depend on the split.
MeshGeometry mesh_geometry(const PolyMesh& mesh, const CellFaces& cell_faces) {
  std::vector<FaceGeometry> faces(mesh.num_faces());
  tbb::parallel_for(Index{0}, mesh.num_faces(), [&](Index f) { faces[f] = face_geometry(mesh, f); });
  return mesh_geometry(mesh, cell_faces, std::move(faces));
}

MeshGeometry mesh_geometry(const PolyMesh& mesh, const CellFaces& cell_faces, std::vector<FaceGeometry> faces) {
  MeshGeometry g;
  g.faces = std::move(faces);
  g.cells.resize(mesh.num_cells());
  tbb::parallel_for(Index{0}, mesh.num_cells(),
                    [&](Index c) { g.cells[c] = cell_geometry(mesh, cell_faces.of(c), c, g.faces); });
  return g;
}

}  // namespace volmesh
