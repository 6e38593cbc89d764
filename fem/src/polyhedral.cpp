#include "volmesh/fem/polyhedral.hpp"

#include <algorithm>
#include <cmath>

#include "volmesh/core/geometry.hpp"
#include "volmesh/core/tri_surface.hpp"
#include "volmesh/io/surface_check.hpp"

namespace volmesh::fem {
namespace {

// Sub-tetrahedron volume relative to the cube of its longest edge at or below which it counts
// as degenerate (a regular tet has 0.118).
constexpr double kDegenerateShape = 1e-12;

double shape_measure(const SubTetrahedron& t) {
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      longest = std::max(longest, (t.corners[i] - t.corners[j]).norm());
  const double volume = tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
  return longest > 0.0 ? volume / (longest * longest * longest) : 0.0;
}

// True when every triangle of the fan about the vertex average turns the same way as the
// face (their area vectors sum to the face's).
bool fan_is_proper(const PolyMesh& mesh, Index f) {
  const auto loop = mesh.face(f);
  const std::size_t n = loop.size();
  const Vec3 m = face_vertex_average(mesh, f);
  const auto area = [&](std::size_t k) {
    const Vec3& p = mesh.points[loop[k]];
    return Vec3((mesh.points[loop[(k + 1) % n]] - p).cross(m - p));
  };
  Vec3 total = Vec3::Zero();
  for (std::size_t k = 0; k < n; ++k) total += area(k);
  const double floor = 1e-10 * total.squaredNorm() / static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k)
    if (!(area(k).dot(total) > floor)) return false;
  return true;
}

// Ear clipping in the plane normal to the face's area vector; each step cuts the convex ear
// with the best shape (area over the sum of squared edges), so that no vertex of the
// remaining polygon lies in it. Empty when no ear is found (a degenerate polygon).
std::vector<std::array<int, 3>> ear_clip(const PolyMesh& mesh, Index f) {
  const auto loop = mesh.face(f);
  const int n = static_cast<int>(loop.size());
  const Vec3 normal = polygon_geometry(mesh.points, loop).area_vector;
  const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.normalized().cross(e1);
  std::vector<Eigen::Vector2d> p(n);
  for (int k = 0; k < n; ++k) p[k] = {mesh.points[loop[k]].dot(e1), mesh.points[loop[k]].dot(e2)};
  const auto cross = [&](int a, int b, int c) {
    const Eigen::Vector2d u = p[b] - p[a], v = p[c] - p[a];
    return u.x() * v.y() - u.y() * v.x();
  };
  std::vector<int> left(n);
  for (int k = 0; k < n; ++k) left[k] = k;
  std::vector<std::array<int, 3>> triangles;
  while (left.size() > 3) {
    const int m = static_cast<int>(left.size());
    int best = -1;
    double best_shape = 0.0;
    for (int i = 0; i < m; ++i) {
      const int a = left[(i + m - 1) % m], b = left[i], c = left[(i + 1) % m];
      const double area = cross(a, b, c);
      if (area <= 0.0) continue;
      bool empty = true;
      for (int v : left)
        if (v != a && v != b && v != c && cross(a, b, v) >= 0.0 && cross(b, c, v) >= 0.0 &&
            cross(c, a, v) >= 0.0)
          empty = false;
      const double shape = area / ((p[b] - p[a]).squaredNorm() + (p[c] - p[b]).squaredNorm() +
                                   (p[a] - p[c]).squaredNorm());
      if (empty && shape > best_shape) {
        best = i;
        best_shape = shape;
      }
    }
    if (best < 0) return {};
    triangles.push_back({left[(best + m - 1) % m], left[best], left[(best + 1) % m]});
    left.erase(left.begin() + best);
  }
  triangles.push_back({left[0], left[1], left[2]});
  return triangles;
}

// The fan about the vertex average as triangles of loop positions, n standing for the face
// node.
std::vector<std::array<int, 3>> fan_triangles(std::size_t n) {
  std::vector<std::array<int, 3>> out;
  for (std::size_t k = 0; k < n; ++k)
    out.push_back({static_cast<int>(k), static_cast<int>((k + 1) % n), static_cast<int>(n)});
  return out;
}

// True when two of the triangles (loop positions of face f; position size() is the vertex
// average) meet in more than a shared vertex or edge, by CGAL's exact predicates.
bool crosses_itself(const PolyMesh& mesh, Index f, const std::vector<std::array<int, 3>>& triangles) {
  const auto loop = mesh.face(f);
  TriSurface s;
  for (Index v : loop) s.points.push_back(mesh.points[v]);
  s.points.push_back(face_vertex_average(mesh, f));
  for (const auto& t : triangles) s.triangles.push_back({t[0], t[1], t[2]});
  return !find_self_intersections(s, 1).empty();
}

bool sees_every_face(const PolyMesh& mesh, const FaceSplits& splits, std::span<const Index> faces,
                     Index c, const Vec3& x) {
  bool ok = true;
  for_each_sub_tetrahedron(mesh, splits, faces, c, x, [&](const SubTetrahedron& t) {
    ok = ok && shape_measure(t) > kDegenerateShape;
  });
  return ok;
}

}  // namespace

FaceSplits split_faces(const PolyMesh& mesh) {
  FaceSplits splits;
  splits.offsets.assign(mesh.num_faces() + 1, 0);
  splits.folded.assign(mesh.num_faces(), 0);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.face(f).size() > 3 && !fan_is_proper(mesh, f)) {
      // A warped face whose projection folds may still have a fan or an ear clipping that
      // does not cross itself in space: the first of those that does not is the face's.
      const auto triangles = ear_clip(mesh, f);
      if (!triangles.empty() && !crosses_itself(mesh, f, triangles))
        splits.triangles.insert(splits.triangles.end(), triangles.begin(), triangles.end());
      else
        splits.folded[f] = crosses_itself(mesh, f, fan_triangles(mesh.face(f).size()));
    }
    splits.offsets[f + 1] = static_cast<Index>(splits.triangles.size());
  }
  return splits;
}

std::optional<Vec3> star_centre(const PolyMesh& mesh, const FaceSplits& splits,
                                std::span<const Index> faces, Index c) {
  std::vector<Index> vertices;
  for (Index f : faces) {
    const auto loop = mesh.face(f);
    vertices.insert(vertices.end(), loop.begin(), loop.end());
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  if (vertices.empty()) return std::nullopt;
  Vec3 average = Vec3::Zero();
  for (Index v : vertices) average += mesh.points[v];
  average /= static_cast<double>(vertices.size());
  if (sees_every_face(mesh, splits, faces, c, average)) return average;

  // The face triangles' planes, outward normals unit: the kernel is where n·x < n·p for all.
  std::vector<std::pair<Vec3, double>> planes;
  double volume = 0.0, area = 0.0;
  Vec3 moment = Vec3::Zero();
  for_each_sub_tetrahedron(mesh, splits, faces, c, average, [&](const SubTetrahedron& t) {
    const double v = tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
    volume += v;
    moment += v * (t.corners[0] + t.corners[1] + t.corners[2] + t.corners[3]) / 4.0;
    const Vec3 n = (t.corners[2] - t.corners[1]).cross(t.corners[3] - t.corners[1]);
    area += 0.5 * n.norm();
    if (n.norm() > 0.0) planes.emplace_back(n.normalized(), n.normalized().dot(t.corners[1]));
  });
  if (!(volume > 0.0) || !(area > 0.0)) return std::nullopt;
  Vec3 x = moment / volume;
  if (sees_every_face(mesh, splits, faces, c, x)) return x;

  // Cyclic over-relaxed projections onto the planes shifted inward by a margin, which end
  // after finitely many steps when the shifted kernel is not empty; the margin starts at a
  // tenth of the cell's volume-to-area length and shrinks.
  double margin = 0.1 * volume / area;
  for (int attempt = 0; attempt < 6; ++attempt, margin *= 0.25) {
    for (int sweep = 0; sweep < 500; ++sweep) {
      bool moved = false;
      for (const auto& [n, b] : planes) {
        const double excess = n.dot(x) - (b - margin);
        if (excess > 0.0) {
          x -= 1.5 * excess * n;
          moved = true;
        }
      }
      if (!moved) break;
    }
    if (sees_every_face(mesh, splits, faces, c, x)) return x;
  }
  return std::nullopt;
}

}  // namespace volmesh::fem
