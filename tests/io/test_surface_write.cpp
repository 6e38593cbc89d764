// Surface writers: write → read gives the same surface in every format, the output is
// deterministic, and a failed write leaves nothing behind.
#include <gtest/gtest.h>

#include "../support/surfaces.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/surface_io.hpp"
#include "writer_fixtures.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::input_error_of;
using test::TempDir;

// Coordinates that only a shortest-round-trip printer or a double field keeps exactly.
TriSurface awkward_icosphere() {
  TriSurface s = test::icosphere(2);
  for (Vec3& p : s.points) p = p / 3 + Vec3(1e5, -1e-7, 0.1);
  return s;
}

TEST(WriteSurface, RoundTripIsIdenticalForIndexedFormats) {
  TempDir dir;
  const TriSurface s = awkward_icosphere();
  for (const char* name : {"s.off", "s.obj", "s.ply"}) {
    SCOPED_TRACE(name);
    write_surface(s, dir / name);
    const TriSurface back = read_surface(dir / name);
    EXPECT_EQ(back.points, s.points);
    EXPECT_EQ(back.triangles, s.triangles);
  }
}

// STL stores single-precision corners per triangle: every corner reads back as its float.
TEST(WriteSurface, StlRoundTripKeepsEveryCornerInSinglePrecision) {
  TempDir dir;
  const TriSurface s = awkward_icosphere();
  write_stl(s, dir / "s.stl");
  EXPECT_EQ(fs::file_size(dir / "s.stl"), 84u + 50u * s.triangles.size());
  EXPECT_NE(test::read_text(dir / "s.stl").substr(0, 5), "solid");
  const TriSurface back = read_stl(dir / "s.stl");
  ASSERT_EQ(back.num_triangles(), s.num_triangles());
  EXPECT_EQ(back.num_points(), s.num_points());
  for (Index t = 0; t < s.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(back.points[back.triangles[t][k]],
                s.points[s.triangles[t][k]].cast<float>().cast<double>())
          << "triangle " << t << " corner " << k;
}

// Rewriting what was read reproduces the file byte for byte. For STL this holds from the
// second generation on: the first write computes normals from double-precision corners.
TEST(WriteSurface, RewritingWhatWasReadGivesTheSameBytes) {
  TempDir dir;
  for (const char* ext : {".off", ".obj", ".ply", ".stl"}) {
    SCOPED_TRACE(ext);
    const fs::path a = dir / (std::string("a") + ext), b = dir / (std::string("b") + ext);
    write_surface(awkward_icosphere(), a);
    if (std::string(ext) == ".stl") {
      write_surface(read_surface(a), b);
      fs::rename(b, a);
    }
    write_surface(read_surface(a), b);
    EXPECT_EQ(test::read_text(a), test::read_text(b));
  }
}

TEST(WriteSurface, WrittenCubeIsTheUnitCubeInEveryFormat) {
  TempDir dir;
  for (const char* name : {"c.off", "c.obj", "c.ply", "c.stl"}) {
    SCOPED_TRACE(name);
    write_surface(test::unit_cube(), dir / name);
    TriSurface back = read_surface(dir / name);
    const SurfaceReport report = check_surface(back, name);
    EXPECT_EQ(report.triangles, 12);
    EXPECT_EQ(report.volume, 1.0);
    EXPECT_FALSE(report.flipped);
  }
}

TEST(WriteSurface, FailureLeavesNoFileBehind) {
  TempDir dir;
  TriSurface broken = test::unit_cube();
  broken.triangles[5][1] = 8;
  for (const char* name : {"x.off", "x.obj", "x.ply", "x.stl"}) {
    SCOPED_TRACE(name);
    const std::string message = input_error_of([&] { write_surface(broken, dir / name); });
    EXPECT_NE(message.find("triangle 5: vertex index 8 out of range (8 vertices)"),
              std::string::npos)
        << message;
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
  EXPECT_NE(input_error_of([&] {
              write_off(test::unit_cube(), dir / "no" / "x.off");
            }).find("does not exist"),
            std::string::npos);
  EXPECT_NE(input_error_of([&] {
              write_surface(test::unit_cube(), dir / "x.vtk");
            }).find("unknown surface format"),
            std::string::npos);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

}  // namespace
}  // namespace volmesh
