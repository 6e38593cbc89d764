// A real segmentation: liver.inr.gz from Debian's libcgal-demo data (CGAL's own example),
// read and queried as a Domain.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "volmesh/domain/image.hpp"
#include "volmesh/io/label_image_io.hpp"

namespace volmesh {
namespace {

TEST(ImageLiver, LoadsWithTheHeadersDimsSpacingAndLabels) {
  const std::filesystem::path path =
      std::filesystem::path(VOLMESH_CGAL_DATA) / "images" / "liver.inr.gz";
  ASSERT_TRUE(std::filesystem::exists(path))
      << path << " not found (make test installs libcgal-demo)";
  const LabelImage image = read_label_image(path);
  // The header says: XDIM=438 YDIM=353 ZDIM=165, unsigned fixed 8 bits, CPU=decm,
  // VX=0.617188 VY=0.617188 VZ=1.33333 and no TX/TY/TZ.
  EXPECT_EQ(image.dims, (std::array<Index, 3>{438, 353, 165}));
  EXPECT_EQ(image.spacing, Vec3(0.617188, 0.617188, 1.33333));
  EXPECT_EQ(image.origin, Vec3::Zero());
  // The voxel values, counted independently (python3 over the decompressed data).
  EXPECT_EQ(image.labels, (std::vector<Index>{0, 84, 85, 127, 255}));
  std::vector<std::int64_t> count(image.labels.size(), 0);
  for (std::uint16_t code : image.codes) ++count[code];
  EXPECT_EQ(count, (std::vector<std::int64_t>{22019024, 2, 17702, 314086, 3160496}));

  const ImageDomain domain(image);
  EXPECT_EQ(domain.regions(), (std::vector<Index>{84, 85, 127, 255}));
  const Box3 box = domain.bounds();
  const Vec3 image_hi = image.origin + image.spacing.cwiseProduct(Vec3(437.5, 352.5, 164.5));
  EXPECT_TRUE((box.lo.array() >= -0.5 * image.spacing.array()).all() &&
              (box.hi.array() <= image_hi.array()).all());
  // Through the labelled part: crossings chain from region(a) to region(b).
  const Vec3 a(box.lo.x(), box.centre().y(), box.centre().z()),
      b(box.hi.x(), box.centre().y(), box.centre().z());
  const std::vector<Crossing> crossings = domain.crossings(a, b);
  ASSERT_FALSE(crossings.empty());
  Index current = domain.region(a);
  for (const Crossing& c : crossings) {
    EXPECT_EQ(c.before, current);
    EXPECT_EQ(domain.region(c.point + 1e-6 * (b - a)), c.after);
    current = c.after;
  }
  EXPECT_EQ(current, domain.region(b));
}

}  // namespace
}  // namespace volmesh
