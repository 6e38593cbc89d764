// Rounding an exact tet mesh to doubles (rounding.hpp): two interior points closer than a
// double can tell apart flatten the tets between them whatever their prism centres do; the
// repair in doubles removes them, the surface and the volume kept.
#include <gtest/gtest.h>

#include <set>

#include "exact_checks.hpp"
#include "volmesh/tet/rounding.hpp"

namespace volmesh::tet {
namespace {

mpq_class six_volume(const TetMesh& m, const std::array<Index, 4>& t) {
  const auto r = [&](int k) { return testing::rational(m.points[t[k]]); };
  return testing::six_volume(r(0), r(1), r(2), r(3));
}

// The unit tetrahedron, outward.
ProjectionSurface tetrahedron() {
  ProjectionSurface s;
  s.surface.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.surface.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return s;
}

// The tetrahedron split at two interior points P and Q a rational 2^-70 apart (both round to
// the same double): P coned to three faces, Q to the fourth, and the tets between them
// around the segment PQ. Rounding puts P and Q at one place, so the tets holding both flatten
// whatever the prism centres do.
ProjectionMesh two_close_points() {
  ProjectionMesh m;
  for (const Vec3& p : tetrahedron().surface.points) m.points.push_back(testing::rational(p));
  const mpq_class third(1, 3), tiny = mpq_class(1) / (mpz_class(1) << 70);
  m.points.push_back({mpq_class(1, 5), mpq_class(1, 5), third - mpq_class(1, 7)});  // P = 4
  m.points.push_back({m.points[4].x + tiny, m.points[4].y + tiny, m.points[4].z - 2 * tiny});
  const Index P = 4, Q = 5;
  // Faces 0-2 coned to P, face 3 (1, 2, 3) to Q; the three tets (Q, P, edge of face 3)
  // close the gap between the two cones.
  m.tets = {{0, 1, 2, P}, {0, 3, 1, P}, {0, 2, 3, P}, {1, 3, 2, Q},
            {1, 2, P, Q}, {2, 3, P, Q}, {3, 1, P, Q}};
  for (auto& t : m.tets) {
    const mpq_class v = testing::six_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]],
                                            m.points[t[3]]);
    if (sgn(v) < 0) std::swap(t[0], t[1]);
  }
  m.tet_region.assign(m.tets.size(), 1);
  for (const auto& t : tetrahedron().surface.triangles) {
    m.boundary_faces.push_back(t);
    m.boundary_surface.push_back(0);
    m.boundary_carrier.push_back(t);
  }
  return m;
}

TEST(Rounding, FlattenedTetsAreRepairedInDoubles) {
  const std::vector<ProjectionSurface> surfaces{tetrahedron()};
  const ProjectionMesh exact = two_close_points();
  for (const auto& t : exact.tets)
    ASSERT_GT(sgn(testing::six_volume(exact.points[t[0]], exact.points[t[1]], exact.points[t[2]],
                                      exact.points[t[3]])), 0);
  Rounding rounding;
  TetMesh mesh = round_to_doubles(exact, surfaces, rounding);
  EXPECT_GT(rounding.repaired_tets, 0);
  drop_unused_points(mesh);
  mpq_class six_total = 0;
  for (const auto& t : mesh.cells) {
    const mpq_class v = six_volume(mesh, t);
    ASSERT_GT(sgn(v), 0);
    six_total += v;
  }
  EXPECT_EQ(six_total, 1);  // the unit tetrahedron: volume 1/6, exactly
  for (std::size_t p = 0; p < 4; ++p) EXPECT_EQ(mesh.points[p], surfaces[0].surface.points[p]);
  std::map<std::array<Index, 3>, int> uses;
  for (const auto& t : mesh.cells)
    for (const auto& f : kTetFaces) {
      std::array<Index, 3> key{t[f[0]], t[f[1]], t[f[2]]};
      std::sort(key.begin(), key.end());
      ++uses[key];
    }
  std::set<std::array<Index, 3>> boundary;
  for (auto f : mesh.boundary_faces) {
    std::sort(f.begin(), f.end());
    boundary.insert(f);
  }
  EXPECT_EQ(boundary.size(), 4u);
  for (const auto& [face, n] : uses) {
    ASSERT_LE(n, 2);
    EXPECT_EQ(n == 1, boundary.count(face) == 1);
  }
}

}  // namespace
}  // namespace volmesh::tet
