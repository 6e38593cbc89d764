// Crossings of every primitive shape, in random rigid frames, against the roots of its
// implicit function found independently (sampling and bisection in long double), and the
// normals there against the analytic gradients.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "test_analytic_support.hpp"
#include "volmesh/domain/analytic_csg.hpp"

namespace volmesh {
namespace {

// Long double points, without Eigen: the reference is evaluated millions of times.
struct P {
  long double x, y, z;
};
P operator+(P a, P b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
P operator-(P a, P b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
P operator*(long double s, P a) { return {s * a.x, s * a.y, s * a.z}; }
P to_p(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
Vec3 to_vec(P p) { return Vec3(double(p.x), double(p.y), double(p.z)); }
long double sq(long double v) { return v * v; }

// A solid in the local frame: implicit function (negative inside) and unit outward normal.
struct Implicit {
  std::function<long double(P)> f;
  std::function<Vec3(const Vec3&)> normal;  // at a surface point
};

Implicit sphere_implicit(double r) {
  return {[=](P p) { return sq(p.x) + sq(p.y) + sq(p.z) - sq(r); },
          [](const Vec3& p) { return Vec3(p.normalized()); }};
}

// max of the constraints, normal of the active one (the largest at a surface point).
Implicit box_implicit(const Vec3& lo, const Vec3& hi) {
  const auto constraints = [=](P p) {
    return std::array<long double, 6>{lo.x() - p.x, p.x - hi.x(), lo.y() - p.y,
                                      p.y - hi.y(), lo.z() - p.z, p.z - hi.z()};
  };
  return {[=](P p) {
            const auto c = constraints(p);
            return *std::max_element(c.begin(), c.end());
          },
          [=](const Vec3& p) {
            const auto c = constraints(to_p(p));
            const int k = int(std::max_element(c.begin(), c.end()) - c.begin());
            return Vec3((k % 2 ? 1.0 : -1.0) * Vec3::Unit(k / 2));
          }};
}

Implicit cylinder_implicit(double r, double z0, double z1) {
  // Radial constraint as a distance so that it compares with the caps' distances.
  const auto constraints = [=](P p) {
    return std::array<long double, 3>{std::sqrt(sq(p.x) + sq(p.y)) - r, z0 - p.z, p.z - z1};
  };
  return {[=](P p) {
            const auto c = constraints(p);
            return *std::max_element(c.begin(), c.end());
          },
          [=](const Vec3& p) {
            const auto c = constraints(to_p(p));
            const int k = int(std::max_element(c.begin(), c.end()) - c.begin());
            return k == 0 ? Vec3(Vec3(p.x(), p.y(), 0).normalized())
                          : Vec3((k == 1 ? -1.0 : 1.0) * Vec3::UnitZ());
          }};
}

Implicit torus_implicit(double R, double r) {
  return {[=](P p) { return sq(std::sqrt(sq(p.x) + sq(p.y)) - R) + sq(p.z) - sq(r); },
          [=](const Vec3& p) {
            const Vec3 radial = Vec3(p.x(), p.y(), 0).normalized();
            return Vec3((p - R * radial).normalized());
          }};
}

Implicit ellipsoid_implicit(const Vec3& s) {
  return {[=](P p) { return sq(p.x / s.x()) + sq(p.y / s.y()) + sq(p.z / s.z()) - 1; },
          [=](const Vec3& p) { return Vec3(p.cwiseQuotient(s.cwiseProduct(s)).normalized()); }};
}

// Sphere of radius r cut by the plane z = h (the part below).
Implicit capped_sphere_implicit(double r, double h) {
  const Implicit s = sphere_implicit(r);
  return {[=](P p) { return std::max(s.f(p), p.z - h); },
          [=](const Vec3& p) {
            return std::abs(p.norm() - r) < std::abs(p.z() - h) ? s.normal(p) : Vec3::UnitZ();
          }};
}

struct Case {
  const char* label;
  Solid solid;  // at the origin, then moved by a random rigid motion
  Implicit implicit;
};

std::vector<Case> cases() {
  return {
      {"sphere", sphere(Vec3::Zero(), 0.8), sphere_implicit(0.8)},
      {"box", box(Vec3(-0.7, -0.4, -0.5), Vec3(0.6, 0.5, 0.3)),
       box_implicit(Vec3(-0.7, -0.4, -0.5), Vec3(0.6, 0.5, 0.3))},
      {"cylinder", cylinder(Vec3(0, 0, -0.6), Vec3(0, 0, 0.5), 0.45),
       cylinder_implicit(0.45, -0.6, 0.5)},
      {"torus", torus(Vec3::Zero(), Vec3::UnitZ(), 0.7, 0.25), torus_implicit(0.7, 0.25)},
      {"ellipsoid", ellipsoid(Vec3::Zero(), Vec3(0.9, 0.5, 0.3)),
       ellipsoid_implicit(Vec3(0.9, 0.5, 0.3))},
      {"half-space", Solid(sphere(Vec3::Zero(), 0.8)) &
                         half_space(Vec3(0, 0, 0.2), Vec3::UnitZ()),
       capped_sphere_implicit(0.8, 0.2)},
  };
}

Solid moved_solid(const Solid& s, const Rigid& motion) {
  // Solids are built from primitives; rebuild this one-primitive-or-intersection solid moved.
  const auto& p = s.primitives();
  Solid out = moved(p[0], motion);
  for (std::size_t i = 1; i < p.size(); ++i) out = out & moved(p[i], motion);
  return out;
}

// Roots of the implicit function along a -> b, by sampling and bisection in long double.
template <class F>
std::vector<long double> reference_roots(const F& f, P a, P b) {
  constexpr int kSamples = 512;  // closer pairs are near-tangent, skipped below
  const auto at = [&](long double t) { return f(a + t * (b - a)); };
  std::vector<long double> roots;
  long double t0 = 0, f0 = at(0);
  for (int k = 1; k <= kSamples; ++k) {
    const long double t1 = (long double)k / kSamples, f1 = at(t1);
    if ((f0 < 0) != (f1 < 0)) {
      long double lo = t0, hi = t1;
      for (int it = 0; it < 64; ++it) {
        const long double mid = (lo + hi) / 2;
        ((at(mid) < 0) == (f0 < 0) ? lo : hi) = mid;
      }
      roots.push_back((lo + hi) / 2);
    }
    t0 = t1, f0 = f1;
  }
  return roots;
}

TEST(AnalyticCrossings, MatchImplicitRootsAndGradientsInRandomFrames) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const Rigid motion{test::random_rotation(rng), Vec3(u(rng), u(rng), u(rng))};
    const AnalyticDomain d = solid_domain(moved_solid(c.solid, motion));
    const Eigen::Matrix3d& rot = motion.rotation;
    const auto local = [&](P p) {  // R^T (p - translation) in long double
      const P q = p - to_p(motion.translation);
      return P{rot(0, 0) * q.x + rot(1, 0) * q.y + rot(2, 0) * q.z,
               rot(0, 1) * q.x + rot(1, 1) * q.y + rot(2, 1) * q.z,
               rot(0, 2) * q.x + rot(1, 2) * q.y + rot(2, 2) * q.z};
    };
    const auto f = [&](P p) { return c.implicit.f(local(p)); };
    const auto world_normal = [&](const Vec3& p) {
      return Vec3(rot * c.implicit.normal(to_vec(local(to_p(p)))));
    };

    int checked = 0, crossings_checked = 0;
    for (int s = 0; s < 400; ++s) {
      Vec3 a = motion.translation + 1.3 * Vec3(u(rng), u(rng), u(rng));
      Vec3 b = motion.translation + 1.3 * Vec3(u(rng), u(rng), u(rng));
      std::vector<long double> ref = reference_roots(f, to_p(a), to_p(b));
      if (s % 2 == 1 && !ref.empty()) {
        // A short segment (like an octree edge) around the first crossing.
        const double t = double(ref[0]), w = 2e-3 / (b - a).norm();
        const Vec3 a2 = a + (t - w * (0.2 + 0.6 * (u(rng) + 1))) * (b - a);
        b = a + (t + w * (0.2 + 0.6 * (u(rng) + 1))) * (b - a);
        a = a2;
        ref = reference_roots(f, to_p(a), to_p(b));
      }
      // Rounding the end points moves a crossing along the segment by about
      // eps |p| / (|b - a| cos), cos between the segment and the normal: skip segments
      // where that alone could exceed the 1e-12 tolerance.
      const Vec3 dir = (b - a).normalized();
      const double rounding = 4e-16 * (a.norm() + b.norm() + 1.0) / (b - a).norm();
      const std::vector<Crossing> got = d.crossings(a, b);
      std::vector<Vec3> points;  // the reference's and ours: near-tangent pairs may differ
      for (long double t : ref) points.push_back(a + double(t) * (b - a));
      for (const Crossing& x : got) points.push_back(x.point);
      bool well_conditioned = true;
      for (const Vec3& p : points) {
        const double cos = std::abs(world_normal(p).dot(dir));
        well_conditioned &= cos > 0.02 && rounding / cos < 2.5e-13;
      }
      if (!well_conditioned) continue;
      ++checked;

      ASSERT_EQ(got.size(), ref.size()) << "segment " << s;
      Index before = f(to_p(a)) < 0 ? 1 : 0;
      EXPECT_EQ(d.region(a), before);
      for (std::size_t k = 0; k < got.size(); ++k) {
        const Crossing& x = got[k];
        EXPECT_NEAR(x.t, double(ref[k]), 1e-12) << "segment " << s;
        EXPECT_LT((x.point - (a + double(ref[k]) * (b - a))).norm(), 1e-12 * (b - a).norm());
        EXPECT_EQ(x.before, before);
        EXPECT_EQ(x.after, 1 - before);
        // From before into after: into the solid when entering.
        const Vec3 expected = (x.after == 1 ? -1.0 : 1.0) * world_normal(x.point);
        EXPECT_LT((x.normal - expected).norm(), 1e-10) << "segment " << s;
        EXPECT_NEAR(x.normal.norm(), 1.0, 1e-14);
        before = x.after;
        ++crossings_checked;
      }
      EXPECT_EQ(d.region(b), before);
    }
    EXPECT_GT(checked, 250);
    EXPECT_GT(crossings_checked, 100);
  }
}

}  // namespace
}  // namespace volmesh
