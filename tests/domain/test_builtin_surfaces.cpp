// The triangulated boundaries of the polyhedral built-ins (builtin_surfaces): valid closed
// surfaces without self-intersections, enclosing the exact region volumes; the twisted
// prisms' parameters and their refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/geometry/self_intersections.hpp"
#include "volmesh/geometry/surface_check.hpp"

namespace volmesh {
namespace {

constexpr double kPi = std::numbers::pi;

double twist_limit(int sides) { return 180.0 * (sides - 2) / sides; }

std::string twisted_prism(int sides, double degrees) {
  std::ostringstream name;
  name << "twisted-prism:" << sides << ':' << std::setprecision(15) << degrees;
  return name.str();
}

// Checks every surface (closed, manifold, outward, no degenerate triangle, no
// self-intersection) and returns its enclosed volume.
std::vector<double> checked_volumes(const std::string& name) {
  std::vector<double> volumes;
  for (const LabelledSurface& s : builtin_surfaces(name)) {
    TriSurface copy = s.surface;
    const SurfaceReport report = check_surface(copy, s.name);
    EXPECT_FALSE(report.flipped) << name << ": " << s.name;
    EXPECT_EQ(report.unused_points, 0) << name << ": " << s.name;
    EXPECT_EQ(report.components, 1) << name << ": " << s.name;
    EXPECT_TRUE(report.self_intersections.empty()) << name << ": " << s.name;
    EXPECT_TRUE(find_self_intersections(s.surface, 1).empty()) << name << ": " << s.name;
    volumes.push_back(report.volume);
  }
  return volumes;
}

// The top vertices (the second half) turned about the z axis by `degrees`.
TriSurface turn_top(TriSurface s, double degrees) {
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(degrees * kPi / 180.0, Vec3::UnitZ()).toRotationMatrix();
  for (std::size_t i = s.points.size() / 2; i < s.points.size(); ++i)
    s.points[i] = turn * s.points[i];
  return s;
}

TEST(BuiltinSurfaces, SchoenhardtIsTheTwistedTriangularPrism) {
  const std::vector<LabelledSurface> s = builtin_surfaces("schoenhardt");
  const std::vector<LabelledSurface> prism = builtin_surfaces("twisted-prism:3:30");
  ASSERT_EQ(s.size(), 1u);
  ASSERT_EQ(prism.size(), 1u);
  EXPECT_EQ(s[0].surface.points, prism[0].surface.points);
  EXPECT_EQ(s[0].surface.triangles, prism[0].surface.triangles);
  EXPECT_EQ(s[0].label, 1);
  EXPECT_EQ(s[0].surface.num_points(), 6);
  EXPECT_EQ(s[0].surface.num_triangles(), 8);
  const double volume = std::sqrt(3.0) / 2.0;
  EXPECT_NEAR(checked_volumes("schoenhardt")[0], volume, 1e-15);
  EXPECT_NEAR(builtin_region_volumes("schoenhardt").at(1), volume, 1e-15);
  // Every side diagonal b_i t_{i+1} is reflex: t_i lies outside the plane of the outward
  // triangle b_i b_{i+1} t_{i+1} on the diagonal's other side.
  const auto& p = s[0].surface.points;
  for (int i = 0; i < 3; ++i) {
    const Vec3 &b = p[i], &b_next = p[(i + 1) % 3], &t = p[3 + i], &t_next = p[3 + (i + 1) % 3];
    EXPECT_GT((b_next - b).cross(t_next - b).dot(t - b), 0.1) << i;
  }
}

TEST(BuiltinSurfaces, TwistedPrismsAreValidUpToTheirLimitAndEncloseTheClosedForm) {
  for (int sides = 3; sides <= 8; ++sides) {
    const double limit = twist_limit(sides);
    for (const double twist : {1.0, 0.5 * limit, limit - 1.0, limit - 1e-3}) {
      const std::string name = twisted_prism(sides, twist);
      SCOPED_TRACE(name);
      const std::vector<LabelledSurface> s = builtin_surfaces(name);
      ASSERT_EQ(s.size(), 1u);
      EXPECT_EQ(s[0].surface.num_points(), 2 * sides);
      EXPECT_EQ(s[0].surface.num_triangles(), 4 * sides - 4);
      // The name holds the twist to 15 digits: both volumes below differ from this one by ~1e-15.
      const double w = twist * kPi / 180.0, a = 2.0 * kPi / sides;
      const double closed_form = sides / 6.0 * (2.0 * std::sin(a) + std::sin(a + w) - std::sin(w));
      EXPECT_NEAR(checked_volumes(name)[0], closed_form, 1e-14);
      EXPECT_NEAR(builtin_region_volumes(name).at(1), closed_form, 1e-14);
    }
    // The limit is tight: turned a little past it, the surface self-intersects.
    const std::vector<LabelledSurface> s = builtin_surfaces(twisted_prism(sides, limit - 1e-3));
    EXPECT_FALSE(find_self_intersections(turn_top(s[0].surface, 2e-3), 1).empty()) << sides;
  }
  EXPECT_EQ(builtin_surfaces("twisted-prism:64:174")[0].surface.num_triangles(), 252);
  checked_volumes("twisted-prism:64:174");
}

TEST(BuiltinSurfaces, TwistedPrismsRefuseBadParametersWithOneLine) {
  const std::map<std::string, std::string> refusals = {
      {"twisted-prism:3:75",
       "a twist of 75 degrees makes the surface self-intersect; twists must lie in (0, 60)"},
      {"twisted-prism:3:60",
       "a twist of 60 degrees makes the surface self-intersect; twists must lie in (0, 60)"},
      {"twisted-prism:7:130",
       "a twist of 130 degrees makes the surface self-intersect; twists must lie in (0, "
       "128.571)"},
      {"twisted-prism:4:0",
       "a twist of 0 degrees leaves the side diagonals convex or flat; twists must lie in (0, "
       "90)"},
      {"twisted-prism:4:-10",
       "a twist of -10 degrees leaves the side diagonals convex or flat; twists must lie in (0, "
       "90)"},
      {"twisted-prism:2:30", "2 sides; K must lie in 3 to 64"},
      {"twisted-prism:65:30", "65 sides; K must lie in 3 to 64"},
  };
  for (const auto& [name, why] : refusals) {
    const std::string message = "builtin:" + name + ": " + why;
    for (int query = 0; query < 3; ++query) {
      try {
        if (query == 0) make_builtin_domain(name);
        if (query == 1) builtin_region_volumes(name);
        if (query == 2) builtin_surfaces(name);
        ADD_FAILURE() << name << " accepted";
      } catch (const InputError& e) {
        EXPECT_EQ(e.what(), message);
      }
    }
  }
  const std::string pattern =
      ": expected twisted-prism:K:DEG, K sides (3 to 64) and a twist of DEG degrees";
  for (const std::string name : {"twisted-prism:", "twisted-prism:3", "twisted-prism:x:30",
                                 "twisted-prism:3:30deg", "twisted-prism:3:nan",
                                 "twisted-prism:3:inf", "twisted-prism:3:30:1",
                                 "twisted-prism: 3:30"}) {
    try {
      make_builtin_domain(name);
      ADD_FAILURE() << name << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.what(), "builtin:" + name + pattern);
    }
  }
}

TEST(BuiltinSurfaces, BoxIsTheUnitCube) {
  const std::vector<LabelledSurface> s = builtin_surfaces("box");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].label, 1);
  EXPECT_EQ(s[0].surface.num_points(), 8);
  EXPECT_EQ(s[0].surface.num_triangles(), 12);
  for (const Vec3& p : s[0].surface.points)
    for (int a = 0; a < 3; ++a) EXPECT_TRUE(p[a] == 0.0 || p[a] == 1.0);
  EXPECT_EQ(checked_volumes("box")[0], 1.0);
}

TEST(BuiltinSurfaces, CubeInclusionMatchesTheAnalyticDomain) {
  const std::vector<LabelledSurface> s = builtin_surfaces("cube-inclusion");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].label, 1);
  EXPECT_EQ(s[0].name, "outer");
  EXPECT_EQ(s[0].surface.num_triangles(), 6 * 4 * 4 * 2);  // squares of side 2
  EXPECT_EQ(s[1].label, 2);
  EXPECT_EQ(s[1].name, "inclusion");
  EXPECT_EQ(s[1].surface.num_triangles(), 6 * 2 * 2 * 2);  // squares of side 1.5
  const std::vector<double> v = checked_volumes("cube-inclusion");
  EXPECT_EQ(v[0], 512.0);
  EXPECT_NEAR(v[1], 27.0, 1e-12);
  const std::map<Index, double> exact = builtin_region_volumes("cube-inclusion");
  EXPECT_EQ(exact.at(1), v[0] - 27.0);
  EXPECT_EQ(exact.at(2), 27.0);
  // The same regions as the analytic domain, at the inclusion's corners and face centres
  // and just beyond them.
  const SurfaceDomain surfaces(s);
  const auto analytic = make_builtin_domain("cube-inclusion");
  EXPECT_EQ(surfaces.regions(), analytic->regions());
  const Vec3 centre = Vec3::Constant(4.0);
  for (const Vec3& corner : s[1].surface.points)
    for (const double scale : {0.99, 1.01}) {
      const Vec3 p = centre + scale * (corner - centre);
      EXPECT_EQ(surfaces.region(p), analytic->region(p)) << p.transpose();
      EXPECT_EQ(surfaces.region(p), scale < 1.0 ? 2 : 1);
    }
  // The outer faces' diagonals all run from least (u, v) to greatest (u, v), with u and v
  // the axes after the face's own, cyclically.
  for (const auto& t : s[0].surface.triangles) {
    const Vec3 &a = s[0].surface.points[t[0]], &b = s[0].surface.points[t[1]],
               &c = s[0].surface.points[t[2]];
    int axis = 0;
    while (!(a[axis] == b[axis] && b[axis] == c[axis])) ++axis;
    Vec3 from = a, to = b;  // the longest edge: the diagonal
    for (const auto& [p, q] : {std::pair{&b, &c}, std::pair{&c, &a}})
      if ((*q - *p).norm() > (to - from).norm()) from = *p, to = *q;
    const Vec3 d = to - from;
    EXPECT_GT(d[(axis + 1) % 3] * d[(axis + 2) % 3], 0.0);
  }
}

TEST(BuiltinSurfaces, CurvedAndLayeredBuiltinsHaveNone) {
  for (const std::string name : {"ball", "primitives", "thick-sphere", "layers6"})
    EXPECT_TRUE(builtin_surfaces(name).empty()) << name;
  EXPECT_THROW(builtin_surfaces("nope"), InputError);
}

TEST(BuiltinSurfaces, TwistedPrismsAreSurfaceDomains) {
  const auto d = make_builtin_domain("twisted-prism:6:100");
  ASSERT_NE(dynamic_cast<const SurfaceDomain*>(d.get()), nullptr);
  EXPECT_EQ(d->regions(), std::vector<Index>{1});
  EXPECT_EQ(d->region(Vec3(0, 0, 0.5)), 1);
  EXPECT_EQ(d->region(Vec3(0, 0, 1.5)), 0);
  EXPECT_EQ(d->bounds().lo.z(), 0.0);
  EXPECT_EQ(d->bounds().hi.z(), 1.0);
}

// Grid lines all but parallel to a side triangle (the prism's bottom edge b4 b5 runs along x
// up to the rounding of sin): their crossing parameters are exact, never 0 / 0.
TEST(BuiltinSurfaces, CrossingsOfSegmentsAllButParallelToAFaceAreFinite) {
  struct Case {
    const char* name;
    Vec3 a, b;
  };
  const Case cases[] = {
      {"twisted-prism:6:110", Vec3(-0x1.0f4fac02e622dp-2, -0x1.ecccccccccccep-2, 0x1.e2d5b1cac3e7cp-3),
       Vec3(-0x1.91d28b38ff78ap-3, -0x1.ecccccccccccep-2, 0x1.e2d5b1cac3e7cp-3)},
      {"twisted-prism:6:60", Vec3(0x1.bbf6a67a9694cp-3, -0x1.a66666666666bp-2, 0x1.0c20933690906p-1),
       Vec3(0x1.6ac8200a18176p-2, -0x1.a66666666666bp-2, 0x1.0c20933690906p-1)},
      {"twisted-prism:5:100", Vec3(-0x1.15bd05cb8d977p-1, 0x1.97e20b0e58a82p-2, 0x1.65309111f20e4p-3),
       Vec3(-0x1.15bd05cb8d977p-1, 0x1.51d356edd66b6p-2, 0x1.65309111f20e4p-3)},
  };
  for (const Case& c : cases) {
    const auto d = make_builtin_domain(c.name);
    const std::vector<Crossing> crossings = d->crossings(c.a, c.b);
    ASSERT_FALSE(crossings.empty()) << c.name;
    Index region = d->region(c.a);
    double t = 0.0;
    for (const Crossing& x : crossings) {
      EXPECT_TRUE(x.t >= t && x.t <= 1.0) << c.name << ": t = " << x.t;
      EXPECT_EQ(x.before, region) << c.name;
      region = x.after;
      t = x.t;
    }
    EXPECT_EQ(region, d->region(c.b)) << c.name;
  }
}

}  // namespace
}  // namespace volmesh
