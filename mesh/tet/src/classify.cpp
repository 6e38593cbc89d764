// Stage 1: the input in the projection frame, each triangle TOP, BOT or WALL by the exact
// orientation of its projection (its outward normal's sign along the axis).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

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

void classify(const std::vector<ProjectionSurface>& surfaces, Axis axis, Surfaces& out) {
  for (Index s = 0; s < static_cast<Index>(surfaces.size()); ++s) {
    const TriSurface& surface = surfaces[s].surface;
    const Index first = static_cast<Index>(out.points.size());
    for (const Vec3& p : surface.points) {
      const Vec3 q = to_frame(p, axis);
      out.points.push_back({q.x(), q.y(), q.z()});
      out.projected.emplace_back(q.x(), q.y());
    }
    for (const auto& t : surface.triangles) {
      const Vec3 a = to_frame(surface.points[t[0]], axis);
      const Vec3 b = to_frame(surface.points[t[1]], axis);
      const Vec3 c = to_frame(surface.points[t[2]], axis);
      out.triangles.push_back({first + t[0], first + t[1], first + t[2]});
      out.surface.push_back(s);
      out.facing.push_back(facing_of(a, b, c));
    }
    out.label.push_back(surfaces[s].label);
  }
  out.plane.resize(out.triangles.size());
  for (std::size_t t = 0; t < out.triangles.size(); ++t) {
    if (out.facing[t] == Facing::wall) continue;
    const RationalPoint& a = out.points[out.triangles[t][0]];
    const RationalPoint& b = out.points[out.triangles[t][1]];
    const RationalPoint& c = out.points[out.triangles[t][2]];
    const Rational ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const Rational vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    const Rational nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    Rational ca = -nx / nz, cb = -ny / nz;
    Rational cc = a.z - ca * a.x - cb * a.y;
    out.plane[t] = {std::move(ca), std::move(cb), std::move(cc)};
  }
}

Rational height_at(const Surfaces& input, Index t, const Rational& x, const Rational& y) {
  const auto& c = input.plane[t];
  return c[0] * x + c[1] * y + c[2];
}

}  // namespace volmesh::tet::detail
