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

// builtin:cube-inclusion: the cube [0, 8]^3 holding a 3 x 3 x 3 cube about its centre,
// rotated by the z-x-z Euler angles (pi/4, pi/6, 0). Triangulated (builtin_surfaces), the
// outer faces are cut into squares of side 2 and the inclusion's into squares of side 1.5.
constexpr double kOuterSide = 8.0, kInclusionHalfSide = 1.5;
constexpr int kOuterSquares = 4, kInclusionSquares = 2;  // per edge of a face
constexpr Index kOuterLabel = 1, kInclusionLabel = 2;

Rigid inclusion_frame() {
  return {euler_zxz(kPi / 4.0, kPi / 6.0, 0.0), Vec3::Constant(kOuterSide / 2.0)};
}

std::unique_ptr<Domain> make_cube_inclusion() {
  return own([] {
    const Vec3 half = Vec3::Constant(kInclusionHalfSide);
    return layered_domain({{box(Vec3::Zero(), Vec3::Constant(kOuterSide), "outer"), kOuterLabel},
                           {moved(box(-half, half, "inclusion"), inclusion_frame()),
                            kInclusionLabel}});
  });
}

std::map<Index, double> cube_inclusion_volumes() {
  const double inclusion = std::pow(2.0 * kInclusionHalfSide, 3);
  return {{kOuterLabel, std::pow(kOuterSide, 3) - inclusion}, {kInclusionLabel, inclusion}};
}

std::vector<LabelledSurface> cube_inclusion_surfaces() {
  const Vec3 half = Vec3::Constant(kInclusionHalfSide);
  return {{box_surface(Vec3::Zero(), Vec3::Constant(kOuterSide), kOuterSquares), kOuterLabel,
           "outer"},
          {box_surface(-half, half, kInclusionSquares, inclusion_frame()), kInclusionLabel,
           "inclusion"}};
}

}  // namespace

std::vector<BuiltinDomain> analytic_builtin_domains() {
  return {
      {"ball",
       [] { return own([] { return solid_domain(sphere(Vec3::Zero(), 1.0, "sphere")); }); },
       [] { return std::map<Index, double>{{1, ball_volume(1.0)}}; }},
      {"box", [] { return own([] { return solid_domain(box(Vec3::Zero(), Vec3::Ones())); }); },
       [] { return std::map<Index, double>{{1, 1.0}}; },
       [] {
         return std::vector<LabelledSurface>{{box_surface(Vec3::Zero(), Vec3::Ones(), 1), 1, "box"}};
       }},
      {"cube-inclusion", make_cube_inclusion, cube_inclusion_volumes, cube_inclusion_surfaces},
      {"primitives", make_primitives, primitives_volumes},
      {"thick-sphere", make_thick_sphere,
       [] { return std::map<Index, double>{{1, ball_volume(1.0) - ball_volume(0.5)}}; }},
  };
}

}  // namespace volmesh
