#pragma once
// A line meets a convex solid in one closed parameter interval: start from the whole line
// and cut it by each constraint of the solid (slabs, quadrics), remembering which
// constraint bounds each end so that its normal is exact even at edges and corners.
#include <cmath>
#include <limits>

#include "analytic_shapes.hpp"

namespace volmesh::analytic {

struct Chord {
  double t_in = -std::numeric_limits<double>::infinity();
  double t_out = std::numeric_limits<double>::infinity();
  Vec3 n_in = Vec3::Zero(), n_out = Vec3::Zero();
  bool empty = false;
  bool on = false;  // the line runs within the surface, e.g. in a face plane

  void clip(double t_lo, const Vec3& n_lo, double t_hi, const Vec3& n_hi) {
    if (t_lo > t_in) t_in = t_lo, n_in = n_lo;
    if (t_hi < t_out) t_out = t_hi, n_out = n_hi;
    if (t_in > t_out) empty = true;
  }

  // lo <= a + t d <= hi along one coordinate; n_lo, n_hi are the outward face normals.
  void clip_slab(double a, double d, double lo, double hi, const Vec3& n_lo, const Vec3& n_hi) {
    if (d == 0.0) {
      if (a < lo || a > hi) empty = true;
      if (a == lo || a == hi) on = true;
      return;
    }
    const double t_lo = (lo - a) / d, t_hi = (hi - a) / d;
    if (d > 0.0)
      clip(t_lo, n_lo, t_hi, n_hi);
    else
      clip(t_hi, n_hi, t_lo, n_lo);
  }

  // A t^2 + B t + C <= 0 with A >= 0, where the left side is the shape's sign value along
  // the line; normal_at(t) is the outward normal at a root.
  template <class NormalAt>
  void clip_quadric(double A, double B, double C, NormalAt normal_at) {
    if (A == 0.0) {  // the line is parallel to the quadric's axis: B == 0 too
      if (C > 0.0) empty = true;
      if (C == 0.0) on = true;
      return;
    }
    const double disc = B * B - 4.0 * A * C;
    if (disc < 0.0) {
      empty = true;
      return;
    }
    // Stable roots: no cancellation, and C == 0 (an end point on the surface) gives t = 0.
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    const double r1 = q / A, r2 = q != 0.0 ? C / q : r1;
    const double lo = std::min(r1, r2), hi = std::max(r1, r2);
    clip(lo, normal_at(lo), hi, normal_at(hi));
  }

  LineHits hits() const {
    LineHits h;
    if (empty) return h;
    const Side inside = on ? Side::on : Side::in;
    if (std::isinf(t_in)) h.start = inside;
    if (std::isfinite(t_in)) h.add(t_in, t_in == t_out ? Side::out : inside, n_in);
    if (std::isfinite(t_out) && t_out != t_in) h.add(t_out, Side::out, n_out);
    return h;
  }
};

}  // namespace volmesh::analytic
