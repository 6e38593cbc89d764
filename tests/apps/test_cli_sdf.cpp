// volmesh sdf end to end: the .rawiv header and samples, --json, and the refusals (exit 1
// for a surface with a hole, exit 2 for bad usage), never leaving a file behind.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_volmesh.hpp"
#include "volmesh/core/byte_order.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

// The box [0, 2] x [0, 1] x [0, 1] as 12 outward triangles.
TriSurface box_2x1x1() {
  TriSurface s;
  for (int k = 0; k < 8; ++k) s.points.emplace_back(2.0 * (k & 1), (k >> 1) & 1, (k >> 2) & 1);
  s.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return s;
}

template <class T>
T big_endian(const std::string& bytes, std::size_t offset) {
  return byte_order::load<T>(bytes.data() + offset, true);
}

TEST(CliSdf, WritesTheGridWithItsHeader) {
  const fs::path dir = test::scratch_dir("sdf");
  write_surface(box_2x1x1(), dir / "box.off");
  const auto r = run_volmesh("sdf " + (dir / "box.off").string() + " --dim 17 --margin 0.25 -o " +
                                 (dir / "box.rawiv").string() + " --json",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string bytes = test::slurp(dir / "box.rawiv");
  ASSERT_EQ(bytes.size(), 68u + 4u * 17 * 17 * 17);
  EXPECT_EQ(big_endian<std::uint32_t>(bytes, 24), 17u * 17 * 17);  // numVerts
  EXPECT_EQ(big_endian<std::uint32_t>(bytes, 28), 16u * 16 * 16);  // numCells
  for (int a = 0; a < 3; ++a) EXPECT_EQ(big_endian<std::uint32_t>(bytes, 32 + 4 * a), 17u);
  // A cube of side 2 (1 + 2 x 0.25) = 3 centred on the box.
  const float h = big_endian<float>(bytes, 56);
  EXPECT_NEAR(h, 3.0 / 16, 1e-6);
  EXPECT_EQ(big_endian<float>(bytes, 60), h);
  EXPECT_EQ(big_endian<float>(bytes, 64), h);
  EXPECT_NEAR(big_endian<float>(bytes, 44), -0.5, 1e-6);  // originX
  EXPECT_NEAR(big_endian<float>(bytes, 48), -1.0, 1e-6);  // originY
  EXPECT_NEAR(big_endian<float>(bytes, 0), -0.5, 1e-6);   // minX
  EXPECT_NEAR(big_endian<float>(bytes, 12), 2.5, 1e-6);   // maxX
  const auto sample = [&](int i, int j, int k) {
    return big_endian<float>(bytes, 68 + 4 * (i + 17 * (j + 17 * k)));
  };
  EXPECT_NEAR(sample(8, 8, 8), 0.5, 1e-6);   // the centre (1, 0.5, 0.5)
  EXPECT_NEAR(sample(0, 8, 8), -0.5, 1e-6);  // (-0.5, 0.5, 0.5)
  EXPECT_NEAR(sample(0, 0, 0), -1.5, 1e-6);  // (-0.5, -1, -1) to the corner

  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["dims"], (std::vector<int>{17, 17, 17}));
  EXPECT_NEAR(j["spacing"].get<double>(), 3.0 / 16, 1e-6);
  EXPECT_NEAR(j["max_distance"].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(j["min_distance"].get<double>(), -1.5, 1e-6);
  EXPECT_EQ(j["triangles"], 12);
  EXPECT_TRUE(j["seconds"].contains("distance"));
}

TEST(CliSdf, SurfaceWithAHoleIsRefusedWithoutOutput) {
  const fs::path dir = test::scratch_dir("sdf-open");
  const fs::path in = fs::path(VOLMESH_TEST_DATA) / "bad" / "open_surface.off";
  const auto r =
      run_volmesh("sdf " + in.string() + " --dim 9 -o " + (dir / "g.rawiv").string(), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("open_surface.off"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("hole"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "g.rawiv"));
}

TEST(CliSdf, BadUsageExitsWith2) {
  const fs::path dir = test::scratch_dir("sdf-usage");
  write_surface(box_2x1x1(), dir / "box.off");
  const std::string box = (dir / "box.off").string(), out = (dir / "g.rawiv").string();
  for (const std::string& args : std::vector<std::string>{
           "--dim 16 -o " + out, "--dim 2 -o " + out, "--dim 2049 -o " + out, "--dim x -o " + out,
           "-o " + out, "--dim 9", "--dim 9 -o " + (dir / "g.vti").string(),
           "--dim 9 --margin -1 -o " + out}) {
    const auto r = run_volmesh("sdf " + box + " " + args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

}  // namespace
}  // namespace volmesh
