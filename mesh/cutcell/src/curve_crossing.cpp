#include "curve_crossing.hpp"

#include <cmath>

namespace volmesh::cutcell {
namespace {

// A curve leaving its chord at more than 60 degrees (the normal's part across the chord
// below this) is no parabola over it.
constexpr double kMinAcrossChord = 0.5;
// Newton on the crossing: straight curves need one step, curved ones a few; a singular
// Jacobian (parallel tangents) or no convergence within the steps means no crossing. A step
// below kNewtonTolerance of the curves' lengths has reached rounding.
constexpr int kNewtonSteps = 20;
constexpr double kSingular = 1e-12;
constexpr double kNewtonTolerance = 1e-13;

// y(t) = bend * t * (length - t) across the chord, t along it from the first end: its end
// slopes are +-bend * length, the mean of the normals' slopes (a parabola cannot match two
// unequal ones).
struct Parabola {
  Vec3 start, along, across;
  double length = 0.0, bend = 0.0;
  Vec3 at(double t) const { return start + t * along + bend * t * (length - t) * across; }
  Vec3 tangent(double t) const { return along + bend * (length - 2.0 * t) * across; }
};

// The tangent's slope against the chord where the normal is n; nullopt when the curve
// leaves the chord too steeply (kMinAcrossChord).
std::optional<double> slope(const Vec3& n, const Parabola& p) {
  const double across = n.dot(p.across);
  if (!(std::abs(across) >= kMinAcrossChord)) return std::nullopt;
  return -n.dot(p.along) / across;
}

std::optional<Parabola> parabola(const CurveEnds& c, const Vec3& plane_normal) {
  const Vec3 chord = c.point[1] - c.point[0];
  Parabola p{c.point[0], Vec3::Zero(), Vec3::Zero(), chord.norm(), 0.0};
  if (!(p.length > 0.0)) return std::nullopt;
  p.along = chord / p.length;
  p.across = plane_normal.cross(p.along);
  const std::optional<double> s0 = slope(c.normal[0], p), s1 = slope(c.normal[1], p);
  if (!s0 || !s1) return std::nullopt;
  p.bend = (*s0 - *s1) / (2.0 * p.length);
  return p;
}

}  // namespace

std::optional<Vec3> crossing_of_curves(const CurveEnds& a, const CurveEnds& b, const Vec3& plane_normal) {
  const std::optional<Parabola> pa = parabola(a, plane_normal), pb = parabola(b, plane_normal);
  if (!pa || !pb) return std::nullopt;
  // Newton on pa(t) = pb(u) in the plane (its coordinates along pa's chord and across it),
  // from the crossing of the chords; straight curves need one step.
  const Vec3 e0 = pa->along, e1 = pa->across;
  double t = 0.5 * pa->length, u = 0.5 * pb->length;
  for (int iteration = 0; iteration < kNewtonSteps; ++iteration) {
    const Vec3 f = pa->at(t) - pb->at(u), ta = pa->tangent(t), tb = pb->tangent(u);
    const double j00 = ta.dot(e0), j01 = -tb.dot(e0), j10 = ta.dot(e1), j11 = -tb.dot(e1);
    const double det = j00 * j11 - j01 * j10;
    if (!(std::abs(det) > kSingular)) return std::nullopt;
    const double f0 = f.dot(e0), f1 = f.dot(e1);
    const double dt = (j11 * f0 - j01 * f1) / det, du = (j00 * f1 - j10 * f0) / det;
    t -= dt;
    u -= du;
    if (std::abs(dt) + std::abs(du) <= kNewtonTolerance * (pa->length + pb->length)) {
      if (t < 0.0 || t > pa->length || u < 0.0 || u > pb->length) return std::nullopt;
      return pa->at(t);
    }
  }
  return std::nullopt;
}

}  // namespace volmesh::cutcell
