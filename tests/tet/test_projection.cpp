#include <gtest/gtest.h>
#include <cmath>
#include <map>
#include <numbers>


#include "exact_checks.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh::tet {
namespace {

using testing::expect_exact_tetrahedralization;

TriSurface box_surface(const Vec3& lo, const Vec3& hi) {
  TriSurface s;
  for (int k = 0; k < 8; ++k)
    s.points.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  // Outward quads (corner bits x=1, y=2, z=4), each split in two.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  return s;
}

// A K-gon of radius 1 at height z, counter-clockwise, and its centre last.
std::vector<Vec3> polygon(int k, double z) {
  std::vector<Vec3> p;
  for (int i = 0; i < k; ++i)
    p.emplace_back(std::cos(2.0 * std::numbers::pi * i / k), std::sin(2.0 * std::numbers::pi * i / k), z);
  p.emplace_back(0.0, 0.0, z);
  return p;
}

// A K-gon prism of height 1 standing on z = 0: 2K vertical WALL triangles along z.
TriSurface cylinder(int k) {
  TriSurface s;
  s.points = polygon(k, 0.0);
  const std::vector<Vec3> top = polygon(k, 1.0);
  s.points.insert(s.points.end(), top.begin(), top.end());
  const Index c0 = k, c1 = 2 * k + 1, t = k + 1;  // centres, first top vertex
  for (Index i = 0; i < k; ++i) {
    const Index j = (i + 1) % k;
    s.triangles.push_back({c0, j, i});
    s.triangles.push_back({c1, t + i, t + j});
    s.triangles.push_back({i, j, t + j});
    s.triangles.push_back({i, t + j, t + i});
  }
  return s;
}

// The paper's worst case: a cone whose BOT triangles all share the base's centre and whose
// TOP triangles all share the apex, put off-centre so that the two fans' projections cross.
TriSurface cone(int k) {
  TriSurface s;
  s.points = polygon(k, 0.0);
  s.points.emplace_back(0.3, 0.2, 1.0);
  const Index centre = k, apex = k + 1;
  for (Index i = 0; i < k; ++i) {
    const Index j = (i + 1) % k;
    s.triangles.push_back({centre, j, i});
    s.triangles.push_back({apex, i, j});
  }
  return s;
}

TriSurface octahedron(double r) {
  TriSurface s;
  s.points = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
  s.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return s;
}

// The octahedron subdivided `levels` times and pushed onto the unit sphere.
TriSurface sphere(int levels) {
  TriSurface s = octahedron(1.0);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<Index, Index>, Index> middle;
    const auto mid = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      const auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      s.points.push_back((s.points[a] + s.points[b]).normalized());
      return middle[key] = s.num_points() - 1;
    };
    std::vector<std::array<Index, 3>> finer;
    for (const auto& t : s.triangles) {
      const Index ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({ab, t[1], bc});
      finer.push_back({ca, bc, t[2]});
      finer.push_back({ab, bc, ca});
    }
    s.triangles = finer;
  }
  return s;
}

ProjectionMesh mesh_of(const std::vector<ProjectionSurface>& surfaces, ProjectionOptions o = {}) {
  ProjectionMesh m = tetrahedralize_by_projection(surfaces, o);
  expect_exact_tetrahedralization(surfaces, m);
  return m;
}

// The builtins made of triangles, as the mesher takes them from a surface domain.
std::vector<ProjectionSurface> builtin(const std::string& name) {
  const SurfaceDomain domain(builtin_surfaces(name));
  std::vector<ProjectionSurface> out;
  for (Index s = 0; s < static_cast<Index>(domain.labels().size()); ++s)
    out.push_back({domain.surface(s), domain.labels()[s], domain.depths()[s] == 0});
  return out;
}

TEST(Projection, BoxAlongEachAxis) {
  const std::vector<ProjectionSurface> box{{box_surface(Vec3(0, 0, 0), Vec3(1, 2, 3))}};
  for (const Axis a : {Axis::x, Axis::y, Axis::z}) {
    const ProjectionMesh m = mesh_of(box, {.auto_axis = false, .axis = a});
    EXPECT_TRUE(m.stats.enclosed_volume == 6);
    EXPECT_EQ(m.stats.wall, 8);
    EXPECT_EQ(m.stats.top, 2);
  }
}

TEST(Projection, TiltedDirections) {
  const std::vector<ProjectionSurface> box{{box_surface(Vec3(0, 0, 0), Vec3(1, 2, 3))}};
  for (int tilt = 1; tilt <= kTilts; ++tilt) {
    SCOPED_TRACE(tilt);
    const ProjectionMesh m = mesh_of(box, {.auto_axis = false, .axis = Axis::y, .tilt = tilt});
    EXPECT_EQ(m.stats.wall, 0);  // no face is parallel to a tilted direction
  }
  {
    SCOPED_TRACE("sphere");
    mesh_of({{sphere(2)}}, {.auto_axis = false, .axis = Axis::x, .tilt = 2});
  }
  SCOPED_TRACE("cube-inclusion");
  mesh_of(builtin("cube-inclusion"), {.auto_axis = false, .axis = Axis::z, .tilt = 1});
}

TEST(Projection, SchoenhardtNeedsInteriorSteinerPoints) {
  const ProjectionMesh m = mesh_of(builtin("schoenhardt"));
  EXPECT_EQ(m.stats.triangles, 8);
  EXPECT_GT(m.stats.interior_steiner, 0);
}

// K-gon prisms twisted by a little, by half their limit 180 (K - 2) / K, and by just below it.
TEST(Projection, TwistedPrisms) {
  for (int k = 3; k <= 8; ++k) {
    const double limit = 180.0 * (k - 2) / k;
    for (const double twist : {5.0, limit / 2, limit - 0.5}) {
      const std::string name = "twisted-prism:" + std::to_string(k) + ":" + std::to_string(twist);
      SCOPED_TRACE(name);
      mesh_of(builtin(name));
    }
  }
}

TEST(Projection, CylinderWithVerticalWalls) {
  const ProjectionMesh m = mesh_of({{cylinder(12)}}, {.auto_axis = false, .axis = Axis::z});
  EXPECT_EQ(m.stats.wall, 24);
}

// Every TOP edge crosses every BOT edge in projection: M grows as N^2.
TEST(Projection, PapersWorstCaseCone) {
  const ProjectionMesh m = mesh_of({{cone(16)}}, {.auto_axis = false, .axis = Axis::z});
  EXPECT_EQ(m.stats.top, 16);
  EXPECT_GT(m.stats.prisms, 16 * 16 / 8);
}

// The plane triangulation's faces and vertices live wherever the heap puts them, and its flips
// follow their addresses; the tets must not: the same input gives the same tets whatever the
// heap held before.
TEST(Projection, SameTetsWhateverTheHeapHolds) {
  const std::vector<ProjectionSurface> surfaces{{sphere(3)}, {cone(24)}};
  std::vector<ProjectionMesh> meshes;
  std::vector<std::vector<char>> clutter;
  for (int run = 0; run < 3; ++run) {
    for (int k = 0; k < 1000 * run; ++k) clutter.emplace_back(std::size_t(16 + (k * 37) % 200));
    meshes.push_back(tetrahedralize_by_projection({surfaces[0]}, {}));
    meshes.push_back(tetrahedralize_by_projection({surfaces[1]}, {}));
  }
  for (std::size_t m = 2; m < meshes.size(); ++m) {
    EXPECT_EQ(meshes[m].tets, meshes[m % 2].tets);
    EXPECT_EQ(meshes[m].boundary_faces, meshes[m % 2].boundary_faces);
  }
}

TEST(Projection, SphereHasNoWalls) {
  const ProjectionMesh m = mesh_of({{sphere(2)}});
  EXPECT_EQ(m.stats.triangles, 128);
  EXPECT_GT(m.stats.prisms, 0);
}

TEST(Projection, NestedSurfacesGiveTwoRegions) {
  const std::vector<ProjectionSurface> nested{
      {box_surface(Vec3(0, 0, 0), Vec3(8, 8, 8)), 1, true, "outer"},
      {octahedron(1.5), 2, false, "inner"}};
  // The octahedron centred in the box.
  std::vector<ProjectionSurface> moved = nested;
  for (Vec3& p : moved[1].surface.points) p += Vec3(4, 4, 4);
  const ProjectionMesh m = mesh_of(moved);
  mpq_class inner = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    if (m.tet_region[t] == 2)
      inner += testing::six_volume(m.points[m.tets[t][0]], m.points[m.tets[t][1]],
                                   m.points[m.tets[t][2]], m.points[m.tets[t][3]]);
  EXPECT_TRUE(inner / 6 == mpq_class(9, 2));  // (4/3) 1.5^3
}

TEST(Projection, CubeInclusionGivesTwoRegions) {
  const std::vector<ProjectionSurface> surfaces = builtin("cube-inclusion");
  for (const Axis a : {Axis::z, Axis::x, Axis::y}) {
    SCOPED_TRACE(axis_name(a));
    const ProjectionMesh m = mesh_of(surfaces, {.auto_axis = false, .axis = a});
    mpq_class inclusion = 0;
    for (std::size_t t = 0; t < m.tets.size(); ++t)
      if (m.tet_region[t] == 2)
        inclusion += testing::six_volume(m.points[m.tets[t][0]], m.points[m.tets[t][1]],
                                         m.points[m.tets[t][2]], m.points[m.tets[t][3]]);
    EXPECT_NEAR(mpq_class(inclusion / 6).get_d(), 27.0, 1e-12);
  }
}

TEST(Projection, InwardSurfaceIsRefused) {
  TriSurface s = box_surface(Vec3(0, 0, 0), Vec3(1, 1, 1));
  for (auto& t : s.triangles) std::swap(t[1], t[2]);
  EXPECT_THROW(tetrahedralize_by_projection({{s}}), InputError);
}

}  // namespace
}  // namespace volmesh::tet
