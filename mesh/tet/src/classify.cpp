// Stage 1: the input in the projection frame, each triangle TOP, BOT or WALL by the exact
// orientation of its projection (its outward normal's sign along the axis).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>

#include "projection_data.hpp"

namespace volmesh::tet::detail {

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

// The axis becomes z by a cyclic permutation, which keeps orientations.
Vec3 to_frame(const Vec3& p, Axis axis) {
  switch (axis) {
    case Axis::x: return {p.y(), p.z(), p.x()};
    case Axis::y: return {p.z(), p.x(), p.y()};
    case Axis::z: break;
  }
  return p;
}

Facing facing_of(const Vec3& a, const Vec3& b, const Vec3& c) {
  switch (CGAL::orientation(Epick::Point_2(a.x(), a.y()), Epick::Point_2(b.x(), b.y()),
                            Epick::Point_2(c.x(), c.y()))) {
    case CGAL::LEFT_TURN: return Facing::top;
    case CGAL::RIGHT_TURN: return Facing::bot;
    default: return Facing::wall;
  }
}

Index walls_along(const std::vector<ProjectionSurface>& surfaces, Axis axis) {
  Index walls = 0;
  for (const ProjectionSurface& s : surfaces)
    for (const auto& t : s.surface.triangles)
      walls += facing_of(to_frame(s.surface.points[t[0]], axis),
                         to_frame(s.surface.points[t[1]], axis),
                         to_frame(s.surface.points[t[2]], axis)) == Facing::wall;
  return walls;
}

}  // namespace

Axis choose_axis(const std::vector<ProjectionSurface>& surfaces) {
  Axis best = Axis::z;
  Index fewest = walls_along(surfaces, Axis::z);
  for (const Axis a : {Axis::x, Axis::y}) {
    const Index walls = walls_along(surfaces, a);
    if (walls < fewest) {
      fewest = walls;
      best = a;
    }
  }
  return best;
}

std::array<Rational, 2> shear_of(int tilt) {
  if (tilt == 0) return {0, 0};
  const auto& eighths = kTiltEighths[static_cast<std::size_t>(tilt - 1)];
  std::array<Rational, 2> shear{Rational(eighths[0], 8), Rational(eighths[1], 8)};
  for (Rational& r : shear) r.canonicalize();  // a fraction from two integers is not reduced
  return shear;
}

void classify(const std::vector<ProjectionSurface>& surfaces, Axis axis, int tilt,
              Surfaces& out) {
  const auto [a, b] = shear_of(tilt);
  for (Index s = 0; s < static_cast<Index>(surfaces.size()); ++s) {
    const TriSurface& surface = surfaces[s].surface;
    const Index first = static_cast<Index>(out.points.size());
    for (const Vec3& p : surface.points) {
      const Vec3 q = to_frame(p, axis);
      RationalPoint r{Rational(q.x()) + a * q.z(), Rational(q.y()) + b * q.z(), q.z()};
      out.projected.emplace_back(K::FT(r.x), K::FT(r.y));
      out.points.push_back(std::move(r));
    }
    for (const auto& t : surface.triangles) {
      out.triangles.push_back({first + t[0], first + t[1], first + t[2]});
      out.surface.push_back(s);
      switch (CGAL::orientation(out.projected[first + t[0]], out.projected[first + t[1]],
                                out.projected[first + t[2]])) {
        case CGAL::LEFT_TURN: out.facing.push_back(Facing::top); break;
        case CGAL::RIGHT_TURN: out.facing.push_back(Facing::bot); break;
        default: out.facing.push_back(Facing::wall);
      }
    }
    out.label.push_back(surfaces[s].label);
  }
  out.plane.resize(out.triangles.size());
  for (std::size_t t = 0; t < out.triangles.size(); ++t) {
    if (out.facing[t] == Facing::wall) continue;
    const RationalPoint& p = out.points[out.triangles[t][0]];
    const RationalPoint& q = out.points[out.triangles[t][1]];
    const RationalPoint& r = out.points[out.triangles[t][2]];
    const Rational ux = q.x - p.x, uy = q.y - p.y, uz = q.z - p.z;
    const Rational vx = r.x - p.x, vy = r.y - p.y, vz = r.z - p.z;
    const Rational nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    Rational ca = -nx / nz, cb = -ny / nz;
    Rational cc = p.z - ca * p.x - cb * p.y;
    out.plane[t] = {std::move(ca), std::move(cb), std::move(cc)};
  }
}

std::array<double, 4> projected_box(const Surfaces& input, Index t) {
  std::array<double, 4> box{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const Index p : input.triangles[t]) {
    const double x = input.points[p].x.get_d(), y = input.points[p].y.get_d();
    box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
  }
  return box;
}

Rational height_at(const Surfaces& input, Index t, const Rational& x, const Rational& y) {
  const auto& c = input.plane[t];
  return c[0] * x + c[1] * y + c[2];
}

}  // namespace volmesh::tet::detail
