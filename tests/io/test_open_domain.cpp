// open_domain: every kind of <domain> argument becomes the right Domain, and the wrong ones
// are refused naming the file.
#include <gtest/gtest.h>

#include <cstring>

#include "../support/images.hpp"
#include "volmesh/domain/image.hpp"
#include "volmesh/domain/layered.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/domain/grid.hpp"
#include "volmesh/io/label_image_io.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/io/voxel_grid_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using image_test::expect_input_error;
using image_test::TempDir;
using image_test::write_bytes;

const fs::path kData(VOLMESH_TEST_DATA);

template <class Kind>
const Kind* as(const std::unique_ptr<Domain>& d) {
  return dynamic_cast<const Kind*>(d.get());
}

TEST(OpenDomain, BuiltinNames) {
  const auto ball = open_domain("builtin:ball");
  EXPECT_EQ(ball->region(Vec3::Zero()), 1);
  EXPECT_EQ(ball->region(Vec3(0, 0, 1.01)), 0);
  expect_input_error([] { open_domain("builtin:nope"); }, {"builtin:nope: unknown built-in"});
  EXPECT_EQ(domain_display_name("builtin:ball"), "builtin:ball");
  EXPECT_EQ(domain_display_name("/some/dir/liver.inr.gz"), "liver.inr.gz");
}

TEST(OpenDomain, SurfaceFilesOfEveryFormatAreOneSolid) {
  for (const char* name : {"cube_ascii.stl", "cube_quads.off", "cube.obj", "cube_le.ply"}) {
    const auto d = open_domain((kData / "surfaces" / name).string());
    ASSERT_NE(as<SurfaceDomain>(d), nullptr) << name;
    EXPECT_EQ(d->region({0.5, 0.5, 0.5}), 1) << name;
    EXPECT_EQ(d->region({1.5, 0.5, 0.5}), 0) << name;
    EXPECT_EQ(d->regions(), std::vector<Index>{1});
  }
  const std::string open = (kData / "bad" / "open_surface.off").string();
  expect_input_error([&] { open_domain(open); }, {open + ": edge", "hole"});
}

TEST(OpenDomain, LabelImagesByExtensionAndNrrdByItsSampleType) {
  TempDir dir;
  std::vector<Index> labels(4 * 3 * 2, 0);
  labels[1 + 4 * (1 + 3 * 1)] = 7;
  const LabelImage image = make_label_image({4, 3, 2}, Vec3(1, 1, 2), Vec3::Zero(), labels);
  for (const char* name : {"l.inr", "l.inr.gz", "l.nrrd"}) {
    write_label_image(image, dir / name);
    const auto d = open_domain((dir / name).string());
    ASSERT_NE(as<ImageDomain>(d), nullptr) << name;
    EXPECT_EQ(d->region({1, 1, 2}), 7);
    EXPECT_EQ(d->regions(), std::vector<Index>{7});
  }

  // A float NRRD is a signed-distance grid: positive (inside) at the first sample only.
  std::string header =
      "NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 2\nencoding: raw\nendian: little\n"
      "spacings: 1 1 1\n\n";
  std::vector<float> values(8, -1.0f);
  values[0] = 1.0f;
  std::string data(sizeof(float) * values.size(), '\0');
  std::memcpy(data.data(), values.data(), data.size());
  write_bytes(dir / "f.nrrd", header + data);
  const auto grid = open_domain((dir / "f.nrrd").string());
  ASSERT_NE(as<SdfGridDomain>(grid), nullptr);
  EXPECT_EQ(grid->region({0, 0, 0}), 1);
  EXPECT_EQ(grid->region({1, 1, 1}), 0);
  // The same header with an integer type is a label image.
  header.replace(header.find("float"), 5, "int32");
  const std::vector<std::int32_t> ints{0, 3, 0, 0, 0, 0, 0, 0};
  std::memcpy(data.data(), ints.data(), data.size());
  write_bytes(dir / "i.nrrd", header + data);
  const auto ints_image = open_domain((dir / "i.nrrd").string());
  ASSERT_NE(as<ImageDomain>(ints_image), nullptr);
  EXPECT_EQ(ints_image->region({1, 0, 0}), 3);
}

TEST(OpenDomain, SignedDistanceGrids) {
  TempDir dir;
  VoxelGrid g;
  g.dims = {3, 3, 3};
  g.spacing = Vec3::Constant(0.5);
  for (Index k = 0; k < 3; ++k)
    for (Index j = 0; j < 3; ++j)
      for (Index i = 0; i < 3; ++i)
        g.values.push_back(
            static_cast<float>(0.6 - (g.point(i, j, k) - Vec3::Constant(0.5)).norm()));
  write_rawiv(g, dir / "g.rawiv");
  const auto rawiv = open_domain((dir / "g.rawiv").string());
  ASSERT_NE(as<SdfGridDomain>(rawiv), nullptr);
  EXPECT_EQ(rawiv->region({0.5, 0.5, 0.5}), 1);
  EXPECT_EQ(rawiv->region({0, 0, 0}), 0);

  std::string values;
  for (float v : g.values) values += std::to_string(v) + " ";
  write_bytes(dir / "g.vti",
              "<?xml version=\"1.0\"?>\n"
              "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
              "<ImageData WholeExtent=\"0 2 0 2 0 2\" Origin=\"0 0 0\" Spacing=\"0.5 0.5 0.5\">\n"
              "<Piece Extent=\"0 2 0 2 0 2\"><PointData Scalars=\"sdf\">\n"
              "<DataArray type=\"Float32\" Name=\"sdf\" format=\"ascii\">" +
                  values + "</DataArray>\n</PointData><CellData/></Piece></ImageData></VTKFile>\n");
  const auto vti = open_domain((dir / "g.vti").string());
  ASSERT_NE(as<SdfGridDomain>(vti), nullptr);
  EXPECT_EQ(vti->region({0.5, 0.5, 0.5}), 1);
  EXPECT_EQ(vti->region({1, 1, 1}), 0);

  write_bytes(dir / "short.rawiv", "too short");
  const std::string bad = (dir / "short.rawiv").string();
  expect_input_error([&] { open_domain(bad); }, {bad});
}

TEST(OpenDomain, DomainFiles) {
  const auto d = open_domain((kData / "domains" / "layers.json").string());
  ASSERT_NE(as<LayeredDomain>(d), nullptr);
  EXPECT_EQ(d->regions(), (std::vector<Index>{1, 2, 3}));
}

TEST(OpenDomain, UnknownExtensionsAndMissingFilesAreNamed) {
  expect_input_error([] { open_domain("mesh.xyz"); }, {"mesh.xyz: unknown domain"});
  expect_input_error([] { open_domain("nowhere/ball.stl"); }, {"nowhere/ball.stl: cannot open"});
  expect_input_error([] { open_domain("nowhere/image.inr.gz"); },
                     {"nowhere/image.inr.gz: cannot open"});
  expect_input_error([] { open_domain("builtin"); }, {"builtin: unknown domain"});
}

}  // namespace
}  // namespace volmesh
