// Checking a surface for the distance and inside queries, and its pseudo-normals.
#include "surface_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "volmesh/core/errors.hpp"

namespace volmesh::surface {

namespace {

// One side of a triangle, keyed by its undirected edge.
struct Side {
  std::uint64_t key;  // lower vertex << 32 | higher vertex
  Index triangle;
  int side;
  bool forward;  // the triangle runs from the lower vertex to the higher
};

std::string edge_name(std::uint64_t key) {
  return "edge " + std::to_string(key >> 32) + "-" + std::to_string(key & 0xffffffffu);
}

void check_indices(const TriSurface& s, const std::string& name) {
  if (s.triangles.empty()) throw InputError(name + ": no triangles");
  for (Index v = 0; v < s.num_points(); ++v)
    if (!s.points[v].allFinite())
      throw InputError(name + ": vertex " + std::to_string(v) + ": coordinate is not finite");
  for (Index t = 0; t < s.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index v = s.triangles[t][k];
      if (v < 0 || v >= s.num_points())
        throw InputError(name + ": triangle " + std::to_string(t) + ": vertex index " +
                         std::to_string(v) + " out of range (" + std::to_string(s.num_points()) +
                         " vertices)");
    }
}

double enclosed_volume(const TriSurface& s) {
  double six_v = 0.0;
  for (const auto& t : s.triangles)
    six_v += s.points[t[0]].dot(s.points[t[1]].cross(s.points[t[2]]));
  return six_v / 6.0;
}

// The triangle across each side of each triangle (local numbering).
std::vector<std::array<Index, 3>> neighbours(const TriSurface& s, const std::string& name) {
  std::vector<Side> sides;
  sides.reserve(3 * s.triangles.size());
  for (Index t = 0; t < s.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = s.triangles[t][k], b = s.triangles[t][(k + 1) % 3];
      const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
      sides.push_back({lo << 32 | hi, t, k, a < b});
    }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
  });
  std::vector<std::array<Index, 3>> across(s.triangles.size());
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].key == sides[i].key) ++j;
    const Side& x = sides[i];
    const auto fail = [&](const std::string& what) {
      throw InputError(name + ": " + edge_name(x.key) + " of triangle " +
                       std::to_string(x.triangle) + ": " + what);
    };
    if (j - i == 1) fail("boundary edge, the surface has a hole");
    if (j - i > 2) fail("non-manifold, shared by " + std::to_string(j - i) + " triangles");
    const Side& y = sides[i + 1];
    if (x.forward == y.forward)
      fail("orientation inconsistent with triangle " + std::to_string(y.triangle));
    across[x.triangle][x.side] = y.triangle;
    across[y.triangle][y.side] = x.triangle;
    i = j;
  }
  return across;
}

}  // namespace

const Vec3& SurfaceGeometry::normal(Index t, Feature f) const {
  const int k = static_cast<int>(f);
  if (k == 0) return face_normals[t];
  if (k < 4) return edge_normals[t][k - 1];
  return vertex_normals[triangles[t][k - 4]];
}

void add_surface(SurfaceGeometry& g, TriSurface s, const std::string& name) {
  check_indices(s, name);
  if (static_cast<std::int64_t>(g.points.size()) + s.num_points() > kMaxIndex ||
      static_cast<std::int64_t>(g.triangles.size()) + s.num_triangles() > kMaxIndex)
    throw InputError(name + ": too many points or triangles in all (32-bit indices)");
  if (enclosed_volume(s) < 0.0)
    for (auto& t : s.triangles) std::swap(t[1], t[2]);

  const Index offset = static_cast<Index>(g.points.size());
  const Index first = g.num_triangles();
  std::vector<Vec3> area_normals(s.triangles.size());
  for (Index t = 0; t < s.num_triangles(); ++t) {
    const auto& c = s.triangles[t];
    const Vec3 u = s.points[c[1]] - s.points[c[0]], v = s.points[c[2]] - s.points[c[0]];
    area_normals[t] = u.cross(v);
    // Far above the rounding of the cross product: the corners are not collinear, exactly.
    constexpr double kCollinear = 1e-14;
    if (!(area_normals[t].norm() > kCollinear * u.norm() * v.norm()))
      throw InputError(name + ": triangle " + std::to_string(t) + ": degenerate, its vertices " +
                       std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " +
                       std::to_string(c[2]) + " are collinear (to rounding)");
  }
  const auto across = neighbours(s, name);

  g.points.insert(g.points.end(), s.points.begin(), s.points.end());
  g.vertex_normals.resize(g.points.size(), Vec3::Zero());
  for (Index t = 0; t < s.num_triangles(); ++t) {
    const auto& c = s.triangles[t];
    g.triangles.push_back({c[0] + offset, c[1] + offset, c[2] + offset});
    g.triangle_surface.push_back(g.num_surfaces());
    g.face_normals.push_back(area_normals[t].normalized());
  }
  for (Index t = 0; t < s.num_triangles(); ++t) {
    const Vec3& n = g.face_normals[first + t];
    std::array<Vec3, 3> edges;
    for (int k = 0; k < 3; ++k) {
      edges[k] = (n + g.face_normals[first + across[t][k]]).normalized();
      // The angle at corner k, from the two sides that meet there.
      const auto& c = s.triangles[t];
      const Vec3 u = s.points[c[(k + 1) % 3]] - s.points[c[k]];
      const Vec3 v = s.points[c[(k + 2) % 3]] - s.points[c[k]];
      g.vertex_normals[c[k] + offset] += std::atan2(u.cross(v).norm(), u.dot(v)) * n;
    }
    g.edge_normals.push_back(edges);
  }
  for (std::size_t v = offset; v < g.points.size(); ++v) g.vertex_normals[v].normalize();
  g.first_triangle.push_back(g.num_triangles());
}

Box3 bounding_box(const SurfaceGeometry& g) {
  Box3 box{g.corner(0, 0), g.corner(0, 0)};
  for (const auto& t : g.triangles)
    for (Index v : t) {
      box.lo = box.lo.cwiseMin(g.points[v]);
      box.hi = box.hi.cwiseMax(g.points[v]);
    }
  return box;
}

}  // namespace volmesh::surface
