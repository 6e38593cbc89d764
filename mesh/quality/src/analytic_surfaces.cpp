// Exact distances to, sharp edges of, samples on and volumes of the analytic primitives:
// the TRUE surfaces a mesh of an analytic domain is measured against.
#include "volmesh/quality/analytic_surfaces.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "volmesh/core/geometry.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The fewest Fibonacci points put on a sphere or ellipsoid, whatever the spacing: a spacing
// near the solid's size still samples it all round.
constexpr int kMinSpherePoints = 8;

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};

Vec3 to_local(const Primitive& primitive, const Vec3& p) {
  return primitive.frame.rotation.transpose() * (p - primitive.frame.translation);
}

double box_edges_distance(const Box& box, const Vec3& q) {
  double best = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int corner = 0; corner < 4; ++corner) {
      Vec3 a = box.lo;
      a[u] = (corner & 1) ? box.hi[u] : box.lo[u];
      a[v] = (corner & 2) ? box.hi[v] : box.lo[v];
      Vec3 b = a;
      b[axis] = box.hi[axis];
      best = std::min(best, distance_to_segment(q, a, b));
    }
  }
  return best;
}

// Points i / n for i = 0..n (both ends) of [a, b], n >= 1 steps no longer than spacing.
std::vector<double> steps(double a, double b, double spacing) {
  const int n = std::max(1, static_cast<int>(std::ceil((b - a) / spacing)));
  std::vector<double> out(n + 1);
  for (int i = 0; i <= n; ++i) out[i] = a + (b - a) * i / n;
  return out;
}

// Angles 2 pi i / n, i < n, n >= `minimum` steps no longer than spacing on a circle of radius r.
std::vector<double> angles(double r, double spacing, int minimum = 3) {
  const int n = std::max(minimum, static_cast<int>(std::ceil(2.0 * kPi * r / spacing)));
  std::vector<double> out(n);
  for (int i = 0; i < n; ++i) out[i] = 2.0 * kPi * i / n;
  return out;
}

// Fibonacci points on the unit sphere, about `count` of them evenly spread.
std::vector<Vec3> fibonacci_sphere(double count) {
  const int n = std::max(kMinSpherePoints, static_cast<int>(std::ceil(count)));
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  std::vector<Vec3> out(n);
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(1.0 - z * z);
    out[i] = Vec3(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return out;
}

std::vector<SurfacePoint> box_samples(const Box& box, double spacing) {
  std::vector<SurfacePoint> out;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (const double side : {-1.0, 1.0}) {
      Vec3 normal = Vec3::Zero();
      normal[axis] = side;
      for (const double a : steps(box.lo[u], box.hi[u], spacing))
        for (const double b : steps(box.lo[v], box.hi[v], spacing)) {
          Vec3 p;
          p[axis] = side < 0 ? box.lo[axis] : box.hi[axis];
          p[u] = a;
          p[v] = b;
          out.push_back({p, normal});
        }
    }
  }
  return out;
}

std::vector<SurfacePoint> cylinder_samples(const Cylinder& c, double spacing) {
  std::vector<SurfacePoint> out;
  for (const double phi : angles(c.radius, spacing)) {
    const Vec3 radial(std::cos(phi), std::sin(phi), 0.0);
    for (const double z : steps(c.z0, c.z1, spacing))
      out.push_back({c.radius * radial + Vec3(0, 0, z), radial});
  }
  for (const double rho : steps(0.0, c.radius, spacing))
    for (const double phi : angles(rho, spacing, 1))
      for (const double z : {c.z0, c.z1})
        out.push_back({Vec3(rho * std::cos(phi), rho * std::sin(phi), z),
                       Vec3(0, 0, z == c.z0 ? -1.0 : 1.0)});
  return out;
}

std::vector<SurfacePoint> torus_samples(const Torus& t, double spacing) {
  std::vector<SurfacePoint> out;
  for (const double u : angles(t.major + t.minor, spacing))
    for (const double v : angles(t.minor, spacing)) {
      const Vec3 normal(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
      out.push_back({Vec3(t.major * std::cos(u), t.major * std::sin(u), 0.0) + t.minor * normal,
                     normal});
    }
  return out;
}

std::vector<SurfacePoint> ellipsoid_samples(const Ellipsoid& e, double spacing) {
  // The map from the unit sphere stretches distances by at most the largest semi-axis.
  const double stretch = e.semi_axes.maxCoeff();
  std::vector<SurfacePoint> out;
  for (const Vec3& s : fibonacci_sphere(4.0 * kPi * stretch * stretch / (spacing * spacing))) {
    const Vec3 p = e.semi_axes.cwiseProduct(s);
    out.push_back({p, s.cwiseQuotient(e.semi_axes).normalized()});
  }
  return out;
}

bool has_sharp_edges(const Primitive& primitive) {
  return std::holds_alternative<Box>(primitive.shape) ||
         std::holds_alternative<Cylinder>(primitive.shape);
}

}  // namespace

double sharp_edge_distance(const Primitive& primitive, const Vec3& p) {
  const Vec3 q = to_local(primitive, p);
  return std::visit(Overloaded{
                        [&](const Box& b) { return box_edges_distance(b, q); },
                        [&](const Cylinder& c) {
                          const double rho = std::hypot(q.x(), q.y()) - c.radius;
                          return std::min(std::hypot(rho, q.z() - c.z0),
                                          std::hypot(rho, q.z() - c.z1));
                        },
                        [&](const auto&) { return kInfinity; },
                    },
                    primitive.shape);
}

std::vector<SurfacePoint> sample_surface(const Primitive& primitive, double spacing) {
  std::vector<SurfacePoint> local = std::visit(
      Overloaded{
          [&](const Sphere& s) {
            std::vector<SurfacePoint> out;
            for (const Vec3& n : fibonacci_sphere(4.0 * kPi * s.radius * s.radius /
                                                  (spacing * spacing)))
              out.push_back({s.radius * n, n});
            return out;
          },
          [&](const Box& b) { return box_samples(b, spacing); },
          [&](const Cylinder& c) { return cylinder_samples(c, spacing); },
          [&](const Torus& t) { return torus_samples(t, spacing); },
          [&](const Ellipsoid& e) { return ellipsoid_samples(e, spacing); },
          [&](const HalfSpace&) { return std::vector<SurfacePoint>{}; },
      },
      primitive.shape);
  for (SurfacePoint& s : local) {
    s.point = primitive.frame.rotation * s.point + primitive.frame.translation;
    s.normal = primitive.frame.rotation * s.normal;
  }
  return local;
}

double solid_volume(const Primitive& primitive) {
  return std::visit(
      Overloaded{
          [](const Sphere& s) { return 4.0 / 3.0 * kPi * std::pow(s.radius, 3); },
          [](const Box& b) { return (b.hi - b.lo).prod(); },
          [](const Cylinder& c) { return kPi * c.radius * c.radius * (c.z1 - c.z0); },
          [](const Torus& t) { return 2.0 * kPi * kPi * t.major * t.minor * t.minor; },
          [](const Ellipsoid& e) { return 4.0 / 3.0 * kPi * e.semi_axes.prod(); },
          [](const HalfSpace&) { return kInfinity; },
      },
      primitive.shape);
}

AnalyticSurfaces::AnalyticSurfaces(const AnalyticDomain& domain)
    : primitives_(domain.primitives().begin(), domain.primitives().end()) {
  for (std::size_t i = 0; i < primitives_.size(); ++i)
    if (has_sharp_edges(primitives_[i])) sharp_.push_back(i);
}

double AnalyticSurfaces::distance(const Vec3& p) const {
  double d = kInfinity;
  for (const Primitive& primitive : primitives_)
    d = std::min(d, (closest_surface_point(primitive, p).point - p).norm());
  return d;
}

void AnalyticSurfaces::sample(std::size_t part, double spacing, std::vector<Vec3>& out) const {
  for (const SurfacePoint& s : sample_surface(primitives_[part], spacing)) out.push_back(s.point);
}

std::vector<std::string> AnalyticSurfaces::feature_groups() const {
  std::vector<std::string> names;
  for (const std::size_t i : sharp_) names.push_back(primitives_[i].name);
  return names;
}

double AnalyticSurfaces::feature_distance(std::size_t group, const Vec3& p) const {
  return sharp_edge_distance(primitives_[sharp_[group]], p);
}

std::map<Index, double> exact_region_volumes(const std::string& spec, const Domain& domain) {
  const std::string prefix = "builtin:";
  if (spec.starts_with(prefix)) return builtin_region_volumes(spec.substr(prefix.size()));
  const auto* analytic = dynamic_cast<const AnalyticDomain*>(&domain);
  if (analytic && analytic->primitives().size() == 1 && domain.regions().size() == 1)
    return {{domain.regions()[0], solid_volume(analytic->primitives()[0])}};
  return {};
}

}  // namespace volmesh
