// The Delaunay interior: the core alone (congruent lattice tets, clear of the surface and
// inside it, bounded by a closed oriented 2-manifold, the same whatever the triangles' order),
// and tet-front with Interior::delaunay (valid, the enclosed volume, every input triangle kept,
// a third of a sphere's volume in the core).
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "delaunay_core.hpp"
#include "front_checks.hpp"
#include "front_surfaces.hpp"
#include "nesting.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/quality/tet_metrics.hpp"

namespace volmesh::tet {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Tri = std::array<Index, 3>;
using Tet = std::array<Index, 4>;
using Edge = std::pair<Index, Index>;

const std::string kSphere = VOLMESH_CGAL_DATA "/meshes/sphere.off";  // radius 0.5
constexpr double kSize = 0.1;
// The lattice tet's dihedral angles are 60° and 90°: these bounds leave rounding only.
constexpr double kMinLatticeDihedral = 59.0, kMaxLatticeDihedral = 91.0;

double volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

K::Point_3 point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

// Each directed edge of the faces once and its reverse once (closed, oriented, no edge of
// more than two faces), and the faces at each vertex one fan (no pinched vertex).
void expect_closed_manifold(const std::vector<Tri>& faces) {
  std::map<Edge, int> directed;
  std::map<Index, std::map<Index, Index>> fan;  // vertex -> (link edge start -> end)
  for (const Tri& t : faces)
    for (int c = 0; c < 3; ++c) {
      ++directed[{t[c], t[(c + 1) % 3]}];
      fan[t[(c + 2) % 3]][t[c]] = t[(c + 1) % 3];
    }
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u);
  }
  for (const auto& [v, link] : fan) {
    std::size_t length = 1;
    for (Index at = link.begin()->second; at != link.begin()->first && length <= link.size();
         at = link.at(at))
      ++length;
    EXPECT_EQ(length, link.size()) << "vertex " << v << " pinched";
  }
}

TEST(DelaunayCore, CongruentLatticeTetsInsideAndClearOfTheSurface) {
  const TriSurface s = read_surface(kSphere);
  const front::Core core = front::delaunay_core(s.points, s.triangles, kSize, {});
  ASSERT_GT(core.tets.size(), 1000u);
  const double step = front::kLatticeStep * kSize;
  double tets_volume = 0.0;
  for (const Tet& t : core.tets) {
    const auto& p = core.points;
    const TetMetrics q = tet_metrics(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
    EXPECT_GE(q.min_dihedral_deg, kMinLatticeDihedral);
    EXPECT_LE(q.max_dihedral_deg, kMaxLatticeDihedral);
    // A twelfth of a lattice cube: the regular tet's volume for edge h.
    const double v = volume(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
    EXPECT_NEAR(v, step * step * step / 12.0, 1e-9 * v);
    tets_volume += v;
  }
  for (const Vec3& x : core.points) {
    EXPECT_NEAR(front::winding_number(s.points, s.triangles, x), 1.0, 1e-9);
    double nearest = INFINITY;
    for (const auto& t : s.triangles)
      nearest = std::min(nearest, CGAL::squared_distance(
                                      point(x), K::Triangle_3(point(s.points[t[0]]),
                                                              point(s.points[t[1]]),
                                                              point(s.points[t[2]]))));
    EXPECT_GE(std::sqrt(nearest), front::kCoreClearance * kSize);
  }
  expect_closed_manifold(core.faces);
  // The faces face out of the core: they enclose its tets' volume.
  double enclosed = 0.0;
  for (const Tri& t : core.faces)
    enclosed += core.points[t[0]].dot(core.points[t[1]].cross(core.points[t[2]])) / 6.0;
  EXPECT_NEAR(enclosed, tets_volume, 1e-12 * tets_volume);
}

TEST(DelaunayCore, TheSameForTheTrianglesInAnyOrder) {
  const TriSurface s = read_surface(kSphere);
  std::vector<Tri> shuffled(s.triangles.rbegin(), s.triangles.rend());
  for (Tri& t : shuffled) std::rotate(t.begin(), t.begin() + 1, t.end());
  const front::Core a = front::delaunay_core(s.points, s.triangles, kSize, {});
  const front::Core b = front::delaunay_core(s.points, shuffled, kSize, {});
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.faces, b.faces);
}

// At the sphere's radius no lattice tet lies a size inside it.
TEST(DelaunayCore, EmptyWhereNoLatticeTetFits) {
  const TriSurface s = read_surface(kSphere);
  const front::Core core = front::delaunay_core(s.points, s.triangles, 0.5, {});
  EXPECT_TRUE(core.tets.empty());
  EXPECT_TRUE(core.points.empty());
  EXPECT_TRUE(core.faces.empty());
}

// The volume of the first `count` tets of the mesh (the core's come first in each region).
double volume_of_first(const TetMesh& m, long long count) {
  double v = 0.0;
  for (long long c = 0; c < count; ++c) {
    const auto& t = m.cells[c];
    v += volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
  }
  return v;
}

// At h a fifth of the radius, the core is the ball about 1.6 h inside, a third of the volume.
TEST(TetFrontDelaunay, SphereAThirdInTheCore) {
  const auto surfaces = test::surfaces_of({LabelledSurface{read_surface(kSphere), 0, kSphere}});
  const FrontResult r = tetrahedralize_by_front(
      surfaces, {.size = kSize, .improve = false, .interior = Interior::delaunay});
  test::expect_valid(surfaces, r);
  ASSERT_GT(r.stats.core_tets, 0);
  // Unimproved, the core's tets are the mesh's first, as made.
  EXPECT_GT(volume_of_first(r.mesh, r.stats.core_tets), 0.3 * test::enclosed_volume(surfaces));
  EXPECT_EQ(r.stats.seconds.front().first, "interior");
}

// The core of the outer region surrounds the inner cube, which keeps its triangles on both
// sides; the improver runs as with the front alone.
TEST(TetFrontDelaunay, CubeInclusionCoreAroundAHole) {
  const auto surfaces = test::surfaces_of(builtin_surfaces("cube-inclusion"));
  const FrontResult r =
      tetrahedralize_by_front(surfaces, {.size = 1.0, .interior = Interior::delaunay});
  test::expect_valid(surfaces, r);
  EXPECT_GT(r.stats.core_tets, 0);
  EXPECT_GT(r.stats.improve.after.min_dihedral_deg, 0.0);
}

}  // namespace
}  // namespace volmesh::tet
