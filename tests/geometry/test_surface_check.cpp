// Surface validation: every file of the bad-input corpus is refused with one line naming the
// file and the offending entity; orientation is fixed; real closed meshes pass with their
// known volumes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../support/surfaces.hpp"
#include "volmesh/geometry/self_intersections.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::bad_fixture;
using test::input_error_of;

// The message read_surface + check_surface give for a file, or "no error".
std::string load_error(const fs::path& path) {
  return input_error_of([&] {
    TriSurface s = read_surface(path);
    check_surface(s, path.string());
  });
}

struct BadInput {
  const char* file;
  const char* message;  // what the one-line error must contain after "FILE: "
};

const BadInput kBadInputs[] = {
    {"empty.stl", "file is empty"},
    {"truncated.stl",
     "header: binary STL claims 12 triangles (684 bytes) but the file has 354 bytes"},
    {"truncated_ascii.stl", "facet 1 (line 12): expected three numbers after 'vertex'"},
    {"huge_count.stl",
     "header: binary STL claims 4000000000 triangles (200000000084 bytes) but the file has 200 "
     "bytes"},
    {"huge_count.off", "header: 1000000000000 faces exceeds the 32-bit index limit"},
    {"huge_count.ply", "header: 3000000000 vertex elements exceeds the 32-bit index limit"},
    {"truncated.ply", "face 7: unexpected end of data (truncated?)"},
    {"two_corners.ply", "face 0 (line 13): 2 corners, at least 3 needed"},
    {"nan.off", "vertex 2: coordinate is not finite (0 nan 0)"},
    {"index_out_of_range.off", "face 3 (line 10): vertex index 7 out of range (4 vertices)"},
    {"out_of_range.obj", "face 1 (line 5): vertex index 9 out of range (3 vertices)"},
    {"bad_reference.obj", "face 1 (line 5): vertex index -4 out of range (3 vertices)"},
    {"degenerate.off", "triangle 3: degenerate, its vertices 0, 4, 1 are collinear"},
    {"nonmanifold_edge.off", "edge 0-1: non-manifold, shared by 4 triangles (0, 1, 4, 5)"},
    {"open_surface.off",
     "edge 1-5 of triangle 4: boundary edge, the surface has a hole (3 boundary edges in all)"},
    {"inconsistent.off",
     "triangle 3: orientation inconsistent with triangle 0 (both run along edge 1-2 from 2 to 1)"},
};

TEST(SurfaceCheck, EveryBadInputIsRefusedWithOneLineNamingFileAndEntity) {
  for (const BadInput& bad : kBadInputs) {
    const fs::path path = bad_fixture(bad.file);
    const std::string message = load_error(path);
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(bad.message), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// A new bad surface in tests/data/bad must come with its expected message (above) or be
// a known non-fatal case.
TEST(SurfaceCheck, EveryBadSurfaceFileHasAnExpectation) {
  for (const auto& entry : fs::directory_iterator(fs::path(VOLMESH_TEST_DATA) / "bad")) {
    const std::string name = entry.path().filename().string();
    if (!is_surface_file(name) || name == "self_intersecting.off") continue;
    EXPECT_TRUE(std::any_of(std::begin(kBadInputs), std::end(kBadInputs), [&](const BadInput& b) {
      return name == b.file;
    })) << name;
  }
}

TEST(SurfaceCheck, SelfIntersectionIsReportedNotFatal) {
  TriSurface s = read_surface(bad_fixture("self_intersecting.off"));
  const SurfaceReport report = check_surface(s, "self_intersecting.off");
  const std::vector<std::pair<Index, Index>> expected = {{0, 5}, {0, 6}, {0, 7}};
  EXPECT_EQ(report.self_intersections, expected);
  EXPECT_FALSE(report.self_intersections_truncated);
  EXPECT_EQ(report.components, 2);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("triangles 0 and 5 intersect (3 intersecting pairs)"),
            std::string::npos);
  // Big tetrahedron 64/6 plus the small one, of base 1/2 and height 1.5.
  EXPECT_NEAR(report.volume, 64.0 / 6 + 0.25, 1e-14);

  const SurfaceReport first = check_surface(s, "s", {.max_self_intersections = 2});
  EXPECT_EQ(first.self_intersections.size(), 2u);
  EXPECT_TRUE(first.self_intersections_truncated);
  EXPECT_TRUE(check_surface(s, "s", {.find_self_intersections = false}).self_intersections.empty());
}

TEST(SurfaceCheck, InwardSurfaceIsFlippedAndReported) {
  TriSurface s = test::unit_cube();
  for (auto& t : s.triangles) std::swap(t[0], t[1]);
  const SurfaceReport report = check_surface(s, "inward.off");
  EXPECT_TRUE(report.flipped);
  EXPECT_EQ(report.volume, 1.0);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("inward.off: the surface was oriented inward"),
            std::string::npos);
  TriSurface again = s;
  EXPECT_FALSE(check_surface(again, "again").flipped);
  EXPECT_EQ(again.triangles, s.triangles);
  const TriSurface outward = test::unit_cube();
  for (Index t = 0; t < s.num_triangles(); ++t) {  // the same triangles, now outward
    const auto& a = s.triangles[t];
    const auto& b = outward.triangles[t];
    EXPECT_EQ(std::vector<Index>({a[2], a[0], a[1]}), std::vector<Index>({b[0], b[1], b[2]}));
  }
}

TEST(SurfaceCheck, ReportsMeasuresComponentsAndUnusedPoints) {
  TriSurface s = test::unit_cube();
  TriSurface tetra = test::corner_tetrahedron();
  for (Vec3 p : tetra.points) s.points.push_back(p + Vec3(2, 0, 0));
  for (auto t : tetra.triangles) s.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  s.points.push_back(Vec3(-5, 0, 0));  // unused: not in the bounding box
  const SurfaceReport report = check_surface(s, "two.off");
  EXPECT_EQ(report.points, 13);
  EXPECT_EQ(report.triangles, 16);
  EXPECT_EQ(report.components, 2);
  EXPECT_EQ(report.unused_points, 1);
  EXPECT_NEAR(report.volume, 1 + 1.0 / 6, 1e-15);
  EXPECT_NEAR(report.area, 6 + 1.5 + std::sqrt(3.0) / 2, 1e-14);
  EXPECT_EQ(report.bbox_min, Vec3(0, 0, 0));
  EXPECT_EQ(report.bbox_max, Vec3(3, 1, 1));
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("1 points are not used"), std::string::npos);
}

TEST(SurfaceCheck, IcosphereConvergesToTheBall) {
  for (int level = 0; level <= 3; ++level) {
    TriSurface s = test::icosphere(level);
    const SurfaceReport report = check_surface(s, "icosphere");
    const double n = std::pow(4.0, level);
    EXPECT_EQ(report.triangles, 20 * n);
    EXPECT_EQ(report.points, 10 * n + 2);
    EXPECT_EQ(report.components, 1);
    EXPECT_FALSE(report.flipped);
    EXPECT_TRUE(report.self_intersections.empty());
    // Inscribed, so below the ball's volume, by a relative deficit that shrinks like h^2,
    // h ~ 2^-level (0.39, 0.51, 0.54, 0.55 times 4^-level).
    const double ball = 4 * std::numbers::pi / 3;
    const double deficit = 1 - report.volume / ball;
    EXPECT_GT(deficit * n, 0.35);
    EXPECT_LT(deficit * n, 0.56);
    EXPECT_LT(report.area, 4 * std::numbers::pi);
  }
}

TEST(SurfaceCheck, RefusesInMemoryDefects) {
  TriSurface empty;
  EXPECT_EQ(input_error_of([&] { check_surface(empty, "e"); }), "e: surface has no triangles");
  TriSurface repeated = test::unit_cube();
  repeated.triangles[7] = {3, 5, 3};
  EXPECT_EQ(input_error_of([&] { check_surface(repeated, "r"); }),
            "r: triangle 7: degenerate, vertex 3 appears twice");
  TriSurface infinite = test::unit_cube();
  infinite.points[6].z() = -INFINITY;
  EXPECT_EQ(input_error_of([&] { check_surface(infinite, "i"); }),
            "i: vertex 6: coordinate is not finite (1 1 -inf)");
  TriSurface out_of_range = test::unit_cube();
  out_of_range.triangles[2][0] = -1;
  EXPECT_EQ(input_error_of([&] { check_surface(out_of_range, "o"); }),
            "o: triangle 2: vertex index -1 out of range (8 vertices)");
}

fs::path cgal_mesh(const char* name) { return fs::path(VOLMESH_CGAL_DATA) / "meshes" / name; }

// Closed meshes from CGAL's data set. Reference volumes: exact rational sums of
// det(a, b, c)/6 over the decimal coordinates in the files (Python fractions.Fraction,
// independent of this reader), rounded to double. Self-intersections are left to the next
// test: CGAL's predicates are slow in a Debug build.
TEST(SurfaceCheck, CgalMeshesAreClosedManifoldsWithTheirKnownVolumes) {
  struct Known {
    const char* file;
    Index points, triangles;
    double volume;
  };
  for (const Known& k : {Known{"elephant.off", 2775, 5558, 0.04620123472608187},
                         Known{"fandisk.off", 6475, 12946, 0.14036031633774718},
                         Known{"knot1.off", 3200, 6400, 0.0951747267700269}}) {
    SCOPED_TRACE(k.file);
    const fs::path path = cgal_mesh(k.file);
    if (!fs::exists(path)) GTEST_SKIP() << "CGAL data not extracted: " << path;
    TriSurface s = read_surface(path);
    const SurfaceReport report =
        check_surface(s, path.string(), {.find_self_intersections = false});
    EXPECT_EQ(report.points, k.points);
    EXPECT_EQ(report.triangles, k.triangles);
    EXPECT_EQ(report.components, 1);
    EXPECT_EQ(report.unused_points, 0);
    EXPECT_FALSE(report.flipped);
    EXPECT_NEAR(report.volume, k.volume, 1e-6 * k.volume);
  }
}

// A closed mesh that does intersect itself. The pairs are those CGAL's
// Polygon_mesh_processing::self_intersections finds on a Surface_mesh built from the same
// triangles (computed once; the two agree on all 105 meshes of the data set that form valid
// halfedge meshes, 14 of which intersect themselves).
TEST(SurfaceCheck, ElkSelfIntersectionsAreThoseOfCgalPmp) {
  const fs::path path = cgal_mesh("elk.off");
  if (!fs::exists(path)) GTEST_SKIP() << "CGAL data not extracted: " << path;
  TriSurface s = read_surface(path);
  const SurfaceReport report = check_surface(s, path.string(), {.max_self_intersections = 100});
  const std::vector<std::pair<Index, Index>> expected = {
      {669, 2877}, {669, 2883}, {669, 2885}, {669, 2887}, {986, 2612}, {2611, 2621}, {2612, 2621}};
  EXPECT_EQ(report.self_intersections, expected);
  EXPECT_FALSE(report.self_intersections_truncated);
}

// A knot comes close to itself everywhere, yet does not touch.
TEST(SurfaceCheck, KnotHasNoSelfIntersections) {
  const fs::path path = cgal_mesh("knot1.off");
  if (!fs::exists(path)) GTEST_SKIP() << "CGAL data not extracted: " << path;
  bool truncated = true;
  EXPECT_TRUE(find_self_intersections(read_surface(path), 1, &truncated).empty());
  EXPECT_FALSE(truncated);
}

}  // namespace
}  // namespace volmesh
