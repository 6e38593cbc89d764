// Surface readers: the fixtures of tests/data/surfaces in every format and variant read as the
// right solid (counts, volume, numbering).
#include <gtest/gtest.h>

#include <fstream>

#include "../support/surfaces.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/surface_io.hpp"
#include "writer_fixtures.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::corner_tetrahedron;
using test::input_error_of;
using test::surface_fixture;
using test::unit_cube;

struct Solid {
  const char* file;
  Index triangles, points;
  double volume, area;
};

// Names the parameter by its file in test names (ctest lists them).
void PrintTo(const Solid& solid, std::ostream* os) { *os << solid.file; }

class ReadSurfaceSolid : public ::testing::TestWithParam<Solid> {};

TEST_P(ReadSurfaceSolid, HasTheRightCountsAndMeasures) {
  const Solid& expected = GetParam();
  TriSurface surface = read_surface(surface_fixture(expected.file));
  EXPECT_EQ(surface.num_triangles(), expected.triangles);
  EXPECT_EQ(surface.num_points(), expected.points);
  const SurfaceReport report = check_surface(surface, expected.file);
  EXPECT_NEAR(report.volume, expected.volume, 1e-15);
  EXPECT_NEAR(report.area, expected.area, 1e-14);
  EXPECT_EQ(report.components, 1);
  EXPECT_FALSE(report.flipped);
  EXPECT_TRUE(report.self_intersections.empty());
  EXPECT_TRUE(report.warnings.empty());
  EXPECT_EQ(report.bbox_min, Vec3(0, 0, 0));
  EXPECT_EQ(report.bbox_max, Vec3(1, 1, 1));
}

const double kTetraArea = 1.5 + std::sqrt(3.0) / 2;
INSTANTIATE_TEST_SUITE_P(Fixtures, ReadSurfaceSolid,
                         ::testing::Values(Solid{"cube_quads.off", 12, 8, 1.0, 6.0},
                                           Solid{"cube.obj", 12, 8, 1.0, 6.0},
                                           Solid{"cube_ascii.stl", 12, 8, 1.0, 6.0},
                                           Solid{"cube_solid_header.stl", 12, 8, 1.0, 6.0},
                                           Solid{"cube_le.ply", 12, 8, 1.0, 6.0},
                                           Solid{"cube_be.ply", 12, 8, 1.0, 6.0},
                                           Solid{"tetra_colour.off", 4, 4, 1.0 / 6, kTetraArea},
                                           Solid{"tetra_ascii.ply", 4, 4, 1.0 / 6, kTetraArea}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// Indexed formats keep the file's numbering; polygons become fans around their first corner.
TEST(ReadSurface, IndexedFormatsKeepTheNumberingAndSplitPolygonsIntoFans) {
  const TriSurface cube = unit_cube();
  for (const char* file : {"cube_quads.off", "cube.obj", "cube_le.ply", "cube_be.ply"}) {
    SCOPED_TRACE(file);
    const TriSurface s = read_surface(surface_fixture(file));
    EXPECT_EQ(s.points, cube.points);
    EXPECT_EQ(s.triangles, cube.triangles);
  }
  const TriSurface tetra = corner_tetrahedron();
  for (const char* file : {"tetra_colour.off", "tetra_ascii.ply"}) {
    SCOPED_TRACE(file);
    const TriSurface s = read_surface(surface_fixture(file));
    EXPECT_EQ(s.points, tetra.points);
    EXPECT_EQ(s.triangles, tetra.triangles);
  }
}

// STL corners are merged exactly, numbered by first appearance: ASCII and binary (whose header
// starts with "solid") give the same surface.
TEST(ReadSurfaceStl, MergesCoincidentCornersInOrderOfAppearance) {
  const TriSurface ascii = read_stl(surface_fixture("cube_ascii.stl"));
  const TriSurface binary = read_stl(surface_fixture("cube_solid_header.stl"));
  EXPECT_EQ(ascii.points, binary.points);
  EXPECT_EQ(ascii.triangles, binary.triangles);
  ASSERT_EQ(ascii.num_points(), 8);
  EXPECT_EQ(ascii.points[0], Vec3(0, 0, 0));
  EXPECT_EQ(ascii.points[1], Vec3(0, 1, 0));
  EXPECT_EQ(ascii.triangles[0], (std::array<Index, 3>{0, 1, 2}));
}

TEST(ReadSurfaceStl, MergesMinusZeroWithZeroButNothingElse) {
  test::TempDir dir;
  std::ofstream(dir / "z.stl")
      << "solid z\n"
         "facet normal 0 0 1\nouter loop\n"
         "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
         "facet normal 0 0 1\nouter loop\n"
         "vertex -0 -0.0 0\nvertex 1 0 1e-300\nvertex 0 1 0\nendloop\nendfacet\n"
         "endsolid z\n";
  const TriSurface s = read_stl(dir / "z.stl");
  EXPECT_EQ(s.num_points(), 4);
  EXPECT_EQ(s.triangles[1], (std::array<Index, 3>{0, 3, 2}));
}

TEST(ReadSurface, ChoosesTheFormatByExtensionIgnoringCase) {
  test::TempDir dir;
  fs::copy_file(surface_fixture("cube_quads.off"), dir / "CUBE.Off");
  EXPECT_EQ(read_surface(dir / "CUBE.Off").num_triangles(), 12);
  EXPECT_TRUE(is_surface_file("a/b.STL"));
  EXPECT_TRUE(is_surface_file("b.ply"));
  EXPECT_FALSE(is_surface_file("b.vtu"));
  EXPECT_FALSE(is_surface_file("stl"));
  const std::string message = input_error_of([&] { read_surface(dir / "cube.vtu"); });
  EXPECT_NE(message.find("cube.vtu: unknown surface format '.vtu'"), std::string::npos) << message;
}

TEST(ReadSurface, MissingFileOrDirectoryIsAnInputError) {
  test::TempDir dir;
  EXPECT_NE(input_error_of([&] { read_off(dir / "none.off"); }).find("none.off: cannot open"),
            std::string::npos);
  fs::create_directory(dir / "d.obj");
  EXPECT_NE(input_error_of([&] { read_obj(dir / "d.obj"); }).find("is a directory"),
            std::string::npos);
}

}  // namespace
}  // namespace volmesh
