// Scalar grid files: .rawiv byte-exact round trips, its big-endian header and hostile files;
// grids read from .vti and .nrrd.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>

#include "../support/images.hpp"
#include "volmesh/io/voxel_grid_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using image_test::expect_input_error;
using image_test::read_bytes;
using image_test::TempDir;
using image_test::write_bytes;

VoxelGrid small_grid() {
  VoxelGrid grid;
  grid.dims = {5, 4, 3};
  grid.origin = Vec3(-1.5, 0.25, 2.0);
  grid.spacing = Vec3(0.5, 0.25, 0.125);
  for (Index k = 0; k < 3; ++k)
    for (Index j = 0; j < 4; ++j)
      for (Index i = 0; i < 5; ++i)
        grid.values.push_back(0.75f * i - 1.0f * j + 0.3f * k * k - 1.0f);
  return grid;
}

std::string be32(std::uint32_t x) {
  return {static_cast<char>(x >> 24), static_cast<char>(x >> 16), static_cast<char>(x >> 8),
          static_cast<char>(x)};
}
std::string be32(float x) { return be32(std::bit_cast<std::uint32_t>(x)); }

TEST(Rawiv, RoundTripIsByteIdentical) {
  TempDir dir;
  const VoxelGrid grid = small_grid();
  write_rawiv(grid, dir / "a.rawiv");
  const VoxelGrid back = read_rawiv(dir / "a.rawiv");
  EXPECT_EQ(back.dims, grid.dims);
  EXPECT_EQ(back.origin, grid.origin);
  EXPECT_EQ(back.spacing, grid.spacing);
  EXPECT_EQ(back.values, grid.values);
  write_rawiv(back, dir / "b.rawiv");
  EXPECT_EQ(read_bytes(dir / "a.rawiv"), read_bytes(dir / "b.rawiv"));
  EXPECT_EQ(read_voxel_grid(dir / "b.rawiv").values, grid.values);
  // Only the two files: no temporary left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 2);
}

TEST(Rawiv, HeaderIsBigEndian) {
  TempDir dir;
  const VoxelGrid grid = small_grid();
  write_rawiv(grid, dir / "g.rawiv");
  const std::string bytes = read_bytes(dir / "g.rawiv");
  ASSERT_EQ(bytes.size(), 68u + 4 * 60);
  std::string header = be32(-1.5f) + be32(0.25f) + be32(2.0f);  // min = origin
  header += be32(0.5f) + be32(1.0f) + be32(2.25f);              // max = origin + (dims - 1) spacing
  header += be32(60u) + be32(24u);                              // numVerts, numCells
  header += be32(5u) + be32(4u) + be32(3u);                     // dims
  header += be32(-1.5f) + be32(0.25f) + be32(2.0f);             // origin
  header += be32(0.5f) + be32(0.25f) + be32(0.125f);            // span
  EXPECT_EQ(bytes.substr(0, 68), header);
  EXPECT_EQ(bytes.substr(0, 4),
            std::string("\xbf\xc0\x00\x00", 4));  // -1.5f, most significant byte first
  EXPECT_EQ(bytes.substr(68, 4), be32(grid.values[0]));
  EXPECT_EQ(bytes.substr(68 + 4 * 59, 4), be32(grid.values[59]));
}

TEST(Rawiv, RejectsBadFiles) {
  TempDir dir;
  write_rawiv(small_grid(), dir / "good.rawiv");
  const std::string good = read_bytes(dir / "good.rawiv");
  const auto check = [&](const std::string& bytes, const std::vector<std::string>& fragments) {
    SCOPED_TRACE(fragments.front());
    write_bytes(dir / "bad.rawiv", bytes);
    std::vector<std::string> expected = fragments;
    expected.push_back((dir / "bad.rawiv").string() + ": ");
    expect_input_error([&] { read_rawiv(dir / "bad.rawiv"); }, expected);
  };
  const auto patched = [&](std::size_t offset, const std::string& word) {
    std::string bytes = good;
    bytes.replace(offset, word.size(), word);
    return bytes;
  };
  check(good.substr(0, good.size() - 1), {"truncated", "240 bytes"});
  check(good + "x", {"data:", "240 bytes"});
  check(good.substr(0, 40), {"header truncated", "40 of 68"});
  check(patched(56, be32(0.0f)), {"spanX: spacing 0"});
  check(patched(64, be32(-0.125f)), {"spanZ: spacing -0.125"});
  check(patched(44, be32(std::numeric_limits<float>::infinity())), {"originX"});
  check(patched(0, be32(std::numeric_limits<float>::quiet_NaN())), {"minX"});
  check(patched(24, be32(61u)), {"numVerts: 61", "60"});
  check(patched(28, be32(25u)), {"numCells: 25", "24"});
  check(patched(32, be32(0u)), {"dimX/dimY/dimZ", "0 samples"});
  // Dims whose product overflows 32 bits: refused before any allocation.
  check(patched(32, be32(65536u) + be32(65536u) + be32(65536u)), {"dimX/dimY/dimZ", "more than"});
  // 1 x 1 x 1: consistent, but too small for trilinear interpolation.
  check(patched(24, be32(1u) + be32(0u) + be32(1u) + be32(1u) + be32(1u)).substr(0, 72),
        {"at least 2"});
  check(patched(68 + 4 * 17, be32(std::numeric_limits<float>::quiet_NaN())),
        {"sample (2, 3, 0)", "not finite"});
  expect_input_error([&] { read_rawiv(dir / "none.rawiv"); }, {"none.rawiv: ", "cannot open"});
}

TEST(Rawiv, WritesAtomically) {
  TempDir dir;
  expect_input_error([&] { write_rawiv(small_grid(), dir / "no" / "such" / "dir.rawiv"); },
                     {"dir.rawiv: "});
  EXPECT_TRUE(fs::is_empty(dir.path()));
  write_bytes(dir / "old.rawiv", "previous contents");
  VoxelGrid broken = small_grid();
  broken.values.pop_back();
  expect_input_error([&] { write_rawiv(broken, dir / "old.rawiv"); }, {"old.rawiv: "});
  EXPECT_EQ(read_bytes(dir / "old.rawiv"), "previous contents");
}

TEST(VoxelGridFiles, ReadsScalarFieldsFromVtiAndNrrd) {
  TempDir dir;
  // 3 x 2 x 2 points, extent starting at 1 along x: the first point is at origin + spacing.x.
  std::string values;
  for (int v = 0; v < 12; ++v) values += std::to_string(v - 5.5) + " ";
  write_bytes(dir / "f.vti",
              "<?xml version=\"1.0\"?>\n"
              "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
              "<ImageData WholeExtent=\"1 3 0 1 0 1\" Origin=\"0.5 -1 2\" Spacing=\"0.25 0.5 1\">\n"
              "<Piece Extent=\"1 3 0 1 0 1\"><PointData Scalars=\"sdf\">\n"
              "<DataArray type=\"Float64\" Name=\"sdf\" format=\"ascii\">" +
                  values +
                  "</DataArray>\n"
                  "</PointData><CellData/></Piece></ImageData></VTKFile>\n");
  const VoxelGrid vti = read_voxel_grid(dir / "f.vti");
  EXPECT_EQ(vti.dims, (std::array<Index, 3>{3, 2, 2}));
  EXPECT_EQ(vti.origin, Vec3(0.75, -1.0, 2.0));
  EXPECT_EQ(vti.spacing, Vec3(0.25, 0.5, 1.0));
  for (int v = 0; v < 12; ++v) EXPECT_EQ(vti.values[v], static_cast<float>(v - 5.5));

  std::string nrrd =
      "NRRD0004\ntype: float\ndimension: 3\nsizes: 3 2 2\nspacings: 0.25 0.5 1\nencoding: "
      "raw\nendian: " +
      std::string(std::endian::native == std::endian::big ? "big" : "little") + "\n\n";
  for (int v = 0; v < 12; ++v) {
    const float x = static_cast<float>(v - 5.5);
    nrrd.append(reinterpret_cast<const char*>(&x), 4);
  }
  write_bytes(dir / "f.nrrd", nrrd);
  EXPECT_EQ(read_voxel_grid(dir / "f.nrrd").values, vti.values);
  // A double beyond float's range is refused, not turned into infinity.
  std::string wide = "NRRD0004\ntype: double\ndimension: 3\nsizes: 2 2 2\nencoding: raw\nendian: " +
                     std::string(std::endian::native == std::endian::big ? "big" : "little") +
                     "\n\n";
  for (int v = 0; v < 8; ++v) {
    const double x = v == 6 ? 1e300 : 1.0;
    wide.append(reinterpret_cast<const char*>(&x), 8);
  }
  write_bytes(dir / "wide.nrrd", wide);
  expect_input_error([&] { read_voxel_grid(dir / "wide.nrrd"); },
                     {"wide.nrrd: ", "sample (0, 1, 1)", "1e+300", "not finite"});

  write_bytes(dir / "bad.vti", "<VTKFile type=\"ImageData\"><broken");
  expect_input_error([&] { read_voxel_grid(dir / "bad.vti"); }, {"bad.vti: "});
  expect_input_error([&] { read_voxel_grid(dir / "none.vti"); }, {"none.vti: "});
  expect_input_error([&] { read_voxel_grid(dir / "f.stl"); }, {"f.stl: ", ".rawiv"});
}

}  // namespace
}  // namespace volmesh
