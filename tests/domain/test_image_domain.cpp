// A labelled image as a Domain: nearest-voxel regions, exact crossings on voxel faces with
// the right labels on either side, smoothed-indicator normals, bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/images.hpp"
#include "volmesh/domain/image.hpp"
#include "volmesh/io/label_image_io.hpp"

namespace volmesh {
namespace {

using image_test::two_ball_image;

const Vec3 kSpacing(0.5, 0.75, 1.25);
const Vec3 kOrigin(-3.0, 2.0, 10.1);

Vec3 centre_of(const LabelImage& image, Index i, Index j, Index k) {
  return image.origin + image.spacing.cwiseProduct(Vec3(i, j, k));
}

// The voxel-face plane nearest to x along axis m, and its distance.
double face_distance(const LabelImage& image, int m, double x) {
  const double lo = image.origin[m] - 0.5 * image.spacing[m];
  const double k = std::round((x - lo) / image.spacing[m]);
  return std::abs(x - (lo + k * image.spacing[m]));
}

// The crossings describe the regions along the segment completely: sorted, chained, on voxel
// faces with the labels just before and after, and in agreement with region() everywhere.
void expect_consistent(const ImageDomain& domain, const Vec3& a, const Vec3& b) {
  const std::vector<Crossing> crossings = domain.crossings(a, b);
  const LabelImage& image = domain.image();
  Index current = domain.region(a);
  for (std::size_t c = 0; c < crossings.size(); ++c) {
    const Crossing& x = crossings[c];
    ASSERT_EQ(x.before, current) << "crossing " << c;
    ASSERT_NE(x.before, x.after);
    if (c > 0) {
      ASSERT_GE(x.t, crossings[c - 1].t);
    }
    ASSERT_TRUE(x.t >= 0.0 && x.t <= 1.0);
    EXPECT_LT((x.point - (a + x.t * (b - a))).norm(), 1e-9);
    double on_face = std::numeric_limits<double>::infinity();
    for (int m = 0; m < 3; ++m) on_face = std::min(on_face, face_distance(image, m, x.point[m]));
    EXPECT_LT(on_face, 1e-12) << "crossing " << c << " is not on a voxel face";
    EXPECT_NEAR(x.normal.norm(), 1.0, 1e-12);
    current = x.after;
  }
  EXPECT_EQ(current, domain.region(b));
  // Dense samples: region() equals the label of the interval the crossings put them in.
  std::size_t next = 0;
  current = domain.region(a);
  for (int s = 1; s < 2000; ++s) {
    const double t = s / 2000.0;
    while (next < crossings.size() && crossings[next].t <= t) current = crossings[next++].after;
    const double gap = std::min(next < crossings.size() ? crossings[next].t - t : 1.0,
                                next > 0 ? t - crossings[next - 1].t : 1.0);
    if (gap > 1e-9) {
      ASSERT_EQ(domain.region(a + t * (b - a)), current) << "t = " << t;
    }
  }
}

TEST(ImageDomain, RegionIsTheLabelOfTheNearestVoxelCentre) {
  const ImageDomain domain(two_ball_image({32, 32, 32}, kSpacing, kOrigin));
  const LabelImage& image = domain.image();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.49, 0.49);
  for (Index k = 0; k < 32; ++k)
    for (Index j = 0; j < 32; ++j)
      for (Index i = 0; i < 32; ++i) {
        const Vec3 c = centre_of(image, i, j, k);
        ASSERT_EQ(domain.region(c), image.label(i, j, k));
        const Vec3 off(jitter(rng), jitter(rng), jitter(rng));
        ASSERT_EQ(domain.region(c + off.cwiseProduct(kSpacing)), image.label(i, j, k));
      }
  const Vec3 lo = kOrigin - 0.5 * kSpacing;
  EXPECT_EQ(domain.region(lo - Vec3(1e-9, 0, 0)), 0);
  EXPECT_EQ(domain.region(Vec3(1e9, 0, 0)), 0);
  EXPECT_EQ(domain.region(Vec3(NAN, 0, 0)), 0);
  EXPECT_EQ(domain.regions(), (std::vector<Index>{1, 2}));
}

TEST(ImageDomain, OnAVoxelFaceTheHigherLabelWins) {
  // Spacing 1 and origin 0: face coordinates are exact in floating point.
  const ImageDomain domain(
      make_label_image({3, 1, 1}, Vec3::Ones(), Vec3::Zero(), std::vector<Index>{1, 2, 0}));
  EXPECT_EQ(domain.region(Vec3(0.5, 0, 0)), 2);
  EXPECT_EQ(domain.region(Vec3(1.5, 0, 0)), 2);
  EXPECT_EQ(domain.region(Vec3(-0.5, 0, 0)),
            1);  // the image's own face: the voxel against outside (0)
  EXPECT_EQ(domain.region(Vec3(-0.5, 0.5, 0.5)), 1);
  EXPECT_EQ(domain.region(Vec3(2.5, 0, 0)), 0);
  EXPECT_EQ(domain.region(Vec3(0.49, 0, 0)), 1);
  // A segment ending on a face ends in the face's region.
  const std::vector<Crossing> c = domain.crossings(Vec3(0, 0, 0), Vec3(0.5, 0, 0));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].t, 1.0);
  EXPECT_EQ(c[0].after, 2);
}

TEST(ImageDomain, AxisAlignedCrossingsLieOnVoxelFacesWithTheNeighbouringLabels) {
  const ImageDomain domain(two_ball_image({32, 32, 32}, kSpacing, kOrigin));
  const LabelImage& image = domain.image();
  for (int axis = 0; axis < 3; ++axis) {
    SCOPED_TRACE(axis);
    // Along `axis` through the centres of row (16, 15) of the other two axes, from outside to
    // outside.
    std::array<Index, 3> at{16, 15, 16};
    at[axis] = 0;
    Vec3 a = centre_of(image, at[0], at[1], at[2]), b = a;
    a[axis] -= 3.0 * kSpacing[axis];
    b[axis] += 34.0 * kSpacing[axis];
    std::vector<std::pair<Index, Index>> expected;  // labels across each face with a change
    std::vector<double> faces;
    Index previous = 0;
    for (Index v = 0; v <= 32; ++v) {
      std::array<Index, 3> voxel = at;
      voxel[axis] = v;
      const Index label = v < 32 ? image.label(voxel[0], voxel[1], voxel[2]) : 0;
      if (label != previous) {
        expected.emplace_back(previous, label);
        faces.push_back(kOrigin[axis] + (v - 0.5) * kSpacing[axis]);
      }
      previous = label;
    }
    ASSERT_EQ(expected.size(), 4u);  // 0 | 1 | 2 | 1 | 0
    const std::vector<Crossing> crossings = domain.crossings(a, b);
    ASSERT_EQ(crossings.size(), expected.size());
    for (std::size_t c = 0; c < crossings.size(); ++c) {
      EXPECT_EQ(crossings[c].before, expected[c].first);
      EXPECT_EQ(crossings[c].after, expected[c].second);
      EXPECT_NEAR(crossings[c].point[axis], faces[c], 1e-12);
      EXPECT_NEAR(crossings[c].t, (faces[c] - a[axis]) / (b[axis] - a[axis]), 1e-12);
      for (int m = 0; m < 3; ++m)
        if (m != axis) {
          EXPECT_EQ(crossings[c].point[m], a[m]);
        }
      // Through the balls' centre the interfaces are perpendicular to the segment.
      const double along = crossings[c].normal[axis] * (b[axis] - a[axis]);
      EXPECT_GT(along, 0.0) << "normal must point from `before` into `after`";
    }
    expect_consistent(domain, a, b);
    expect_consistent(domain, b, a);
  }
}

TEST(ImageDomain, ObliqueCrossingsAreExactAndComplete) {
  const ImageDomain domain(two_ball_image({32, 32, 32}, kSpacing, kOrigin));
  const Box3 box{kOrigin - 0.5 * kSpacing, kOrigin + 31.5 * kSpacing};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  const auto random_point = [&]() -> Vec3 {
    return box.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.size());
  };
  for (int s = 0; s < 100; ++s) {
    SCOPED_TRACE(s);
    expect_consistent(domain, random_point(), random_point());
  }
  // Exactly through voxel edges and corners (a diagonal through the centres).
  expect_consistent(domain, kOrigin, kOrigin + 31.0 * kSpacing);
  expect_consistent(domain, kOrigin - kSpacing, kOrigin + 33.0 * kSpacing);
  // Degenerate and missing segments.
  EXPECT_TRUE(domain.crossings(kOrigin, kOrigin).empty());
  EXPECT_TRUE(domain.crossings(Vec3(-100, 0, 0), Vec3(-100, 1, 0)).empty());
}

TEST(ImageDomain, TheImageBoxIsAnInterfaceWhereLabelsReachIt) {
  const ImageDomain domain(
      make_label_image({4, 12, 12}, Vec3::Ones(), Vec3::Zero(), std::vector<Index>(576, 3)));
  const std::vector<Crossing> c = domain.crossings(Vec3(-2.0, 5.2, 5.7), Vec3(6.0, 5.2, 5.7));
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].before, 0);
  EXPECT_EQ(c[0].after, 3);
  EXPECT_EQ(c[0].point.x(), -0.5);
  EXPECT_EQ(c[1].before, 3);
  EXPECT_EQ(c[1].after, 0);
  EXPECT_EQ(c[1].point.x(), 3.5);
  EXPECT_GT(c[0].normal.x(), 0.999);  // into the image
  EXPECT_GT(c[1].normal.x(), 0.999);  // out of it
  EXPECT_EQ(domain.bounds().lo, Vec3::Constant(-0.5));
  EXPECT_EQ(domain.bounds().hi, Vec3(3.5, 11.5, 11.5));
}

// The worst angle between crossing normals (and normal(p) there) and the true sphere normals,
// on rays from the centre of concentric balls.
double worst_normal_angle(const ImageDomain& domain, const Vec3& centre, double reach) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  double worst = 0.0;
  for (int s = 0; s < 200; ++s) {
    const Vec3 dir = Vec3(g(rng), g(rng), g(rng)).normalized();
    for (const Crossing& c : domain.crossings(centre, centre + reach * dir)) {
      const Vec3 radial = (c.point - centre).normalized();
      // The normal points into `after`: outward for 2 -> 1 and 1 -> 0; inward where the
      // staircase steps back into the higher label.
      const Vec3 expected = c.before > c.after ? radial : Vec3(-radial);
      worst = std::max(worst, std::acos(std::min(1.0, c.normal.dot(expected))));
      const Vec3 n = domain.normal(c.point);  // out of the higher label: outward
      worst = std::max(worst, std::acos(std::min(1.0, n.dot(radial))));
    }
  }
  return worst * 180.0 / M_PI;
}

TEST(ImageDomain, NormalsFollowTheSphericalInterfaces) {
  // Isotropic voxels; balls of radius 12.8 and 6.4 voxels around the image centre.
  const ImageDomain domain(two_ball_image({32, 32, 32}, Vec3::Constant(0.5), Vec3::Zero()));
  EXPECT_EQ(domain.sigma(), 0.75);  // 1.5 voxels
  // A staircase sphere's faces deviate by up to 90 degrees; smoothed, a few degrees remain
  // (5.1 measured).
  EXPECT_LT(worst_normal_angle(domain, Vec3::Constant(0.5 * 31 * 0.5), 9.0), 7.0);

  // Anisotropic voxels, balls of radius 6.5 and 3.3 (3.7 voxels along z); 3.4 measured.
  const Vec3 spacing(0.4, 0.4, 0.9), centre = Vec3::Constant(8.0);
  const std::array<Index, 3> dims{40, 40, 17};
  std::vector<Index> labels;
  for (Index k = 0; k < dims[2]; ++k)
    for (Index j = 0; j < dims[1]; ++j)
      for (Index i = 0; i < dims[0]; ++i) {
        const double r = (spacing.cwiseProduct(Vec3(i, j, k)) - centre).norm();
        labels.push_back(r < 3.3 ? 2 : r < 6.5 ? 1 : 0);
      }
  const ImageDomain anisotropic(make_label_image(dims, spacing, Vec3::Zero(), labels));
  EXPECT_LT(worst_normal_angle(anisotropic, centre, 7.5), 5.0);
}

TEST(ImageDomain, BoundsHoldExactlyTheLabelledVoxels) {
  std::vector<Index> labels(10 * 8 * 6, 0);
  const auto at = [](Index i, Index j, Index k) { return i + 10 * (j + 8 * k); };
  labels[at(2, 3, 1)] = 5;
  labels[at(7, 5, 4)] = 1;
  const ImageDomain domain(make_label_image({10, 8, 6}, Vec3(1, 2, 3), Vec3(10, 20, 30), labels));
  EXPECT_EQ(domain.bounds().lo, Vec3(10 + 1.5, 20 + 5, 30 + 1.5));
  EXPECT_EQ(domain.bounds().hi, Vec3(10 + 7.5, 20 + 11, 30 + 13.5));
  EXPECT_EQ(domain.regions(), (std::vector<Index>{1, 5}));
  const ImageDomain empty(
      make_label_image({2, 2, 2}, Vec3::Ones(), Vec3::Zero(), std::vector<Index>(8, 0)));
  EXPECT_TRUE(empty.regions().empty());
}

}  // namespace
}  // namespace volmesh
