// The built-in domains made of analytic solids (builtin.hpp describes them), with their
// exact region volumes.
#include <cmath>
#include <numbers>

#include "builtin_entries.hpp"
#include "volmesh/domain/analytic_csg.hpp"

namespace volmesh {
namespace {

constexpr double kPi = std::numbers::pi;

double ball_volume(double r) { return 4.0 * kPi / 3.0 * r * r * r; }

template <class MakeDomain>
std::unique_ptr<Domain> own(MakeDomain make) {
  return std::make_unique<AnalyticDomain>(make());
}

// builtin:primitives. The box holds the whole half x >= 0 of the ball above z = -0.6, and
// the cylinder's caps lie outside the ball, which keeps every overlap volume closed-form.
constexpr double kBallRadius = 1.0, kCylinderRadius = 0.5, kCylinderHalfLength = 1.4;
const Vec3 kBoxLo(0.0, -1.2, -0.6), kBoxHi(1.2, 1.2, 1.2);

std::unique_ptr<Domain> make_primitives() {
  return own([] {
    return multi_material_domain(
        {sphere(Vec3::Zero(), kBallRadius, "ball"), box(kBoxLo, kBoxHi, "box"),
         cylinder(Vec3(0, 0, -kCylinderHalfLength), Vec3(0, 0, kCylinderHalfLength),
                  kCylinderRadius, "cylinder")});
  });
}

std::map<Index, double> primitives_volumes() {
  const double R = kBallRadius, rho = kCylinderRadius, z_lo = kBoxLo.z();
  const double box_height = kBoxHi.z() - z_lo;
  const double ball = ball_volume(R);
  const double cylinder = kPi * rho * rho * 2.0 * kCylinderHalfLength;
  const double box = (kBoxHi - kBoxLo).prod();
  // Ball inside the infinite cylinder: the ball minus the "napkin ring" around it.
  const double napkin_ring = 4.0 * kPi / 3.0 * std::pow(R * R - rho * rho, 1.5);
  const double ball_cylinder = ball - napkin_ring;
  const double cap_height = R + z_lo;  // the cap of the ball below z = z_lo
  const double cap = kPi * cap_height * cap_height * (3.0 * R - cap_height) / 3.0;
  const double ball_box = 0.5 * (ball - cap);
  const double box_cylinder = 0.5 * kPi * rho * rho * box_height;
  // Half disc of radius rho times the height between z_lo and the ball's upper surface.
  const double all =
      kPi * ((R * R * R - std::pow(R * R - rho * rho, 1.5)) / 3.0 - z_lo * rho * rho / 2.0);
  return {{1, ball - ball_box - ball_cylinder + all},
          {2, box - ball_box - box_cylinder + all},
          {3, ball_box - all},
          {4, cylinder - ball_cylinder - box_cylinder + all},
          {5, ball_cylinder - all},
          {6, box_cylinder - all},
          {7, all}};
}

std::unique_ptr<Domain> make_thick_sphere() {
  return own([] {
    return solid_domain(Solid(sphere(Vec3::Zero(), 1.0, "outer")) -
                        sphere(Vec3::Zero(), 0.5, "inner"));
  });
}

std::unique_ptr<Domain> make_cube_inclusion() {
  return own([] {
    const Vec3 centre = Vec3::Constant(4.0);
    const Primitive inclusion =
        moved(box(Vec3::Constant(-1.5), Vec3::Constant(1.5), "inclusion"),
              Rigid{euler_zxz(kPi / 4.0, kPi / 6.0, 0.0), centre});
    return layered_domain({{box(Vec3::Zero(), Vec3::Constant(8.0), "outer"), 1}, {inclusion, 2}});
  });
}

}  // namespace

std::vector<BuiltinDomain> analytic_builtin_domains() {
  return {
      {"ball",
       [] { return own([] { return solid_domain(sphere(Vec3::Zero(), 1.0, "sphere")); }); },
       [] { return std::map<Index, double>{{1, ball_volume(1.0)}}; }},
      {"box", [] { return own([] { return solid_domain(box(Vec3::Zero(), Vec3::Ones())); }); },
       [] { return std::map<Index, double>{{1, 1.0}}; }},
      {"cube-inclusion", make_cube_inclusion,
       [] { return std::map<Index, double>{{1, 512.0 - 27.0}, {2, 27.0}}; }},
      {"primitives", make_primitives, primitives_volumes},
      {"thick-sphere", make_thick_sphere,
       [] { return std::map<Index, double>{{1, ball_volume(1.0) - ball_volume(0.5)}}; }},
  };
}

}  // namespace volmesh
