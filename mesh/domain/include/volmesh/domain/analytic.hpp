#pragma once
// Analytic solids (sphere, box, cylinder, torus, ellipsoid, half-space) placed by rigid
// motions, and the domain they partition space into. Each primitive is an implicit solid
// (closed: its surface belongs to it) with an exact segment intersection and an exact
// normal. The domain maps the set of primitives containing a point — a bitmask, bit i for
// primitive i — to a region through a table: CSG solids and labelled layers
// (analytic_csg.hpp) and the multi-material mode (below) are all such tables.
#include <cstdint>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "volmesh/domain/domain.hpp"

namespace volmesh {

// Shapes in their local frame.
struct Sphere {
  double radius;  // centred at the origin
};
struct Box {
  Vec3 lo, hi;  // [lo, hi], axis-aligned
};
struct Cylinder {
  double radius;  // around the z axis
  double z0, z1;  // caps at z = z0 and z = z1 (z0 < z1)
};
struct Torus {
  double major, minor;  // around the z axis, in the plane z = 0; major > minor > 0
};
struct Ellipsoid {
  Vec3 semi_axes;  // along x, y, z, centred at the origin
};
struct HalfSpace {
  double offset;  // z <= offset
};
using Shape = std::variant<Sphere, Box, Cylinder, Torus, Ellipsoid, HalfSpace>;

// world = rotation * local + translation (rotation orthonormal, det +1).
struct Rigid {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 translation = Vec3::Zero();
};
Rigid operator*(const Rigid& outer, const Rigid& inner);  // apply inner, then outer
// Rotation R = Rz(phi) Rx(theta) Rz(psi): the classical z-x-z Euler angles.
Eigen::Matrix3d euler_zxz(double phi, double theta, double psi);

struct Primitive {
  Shape shape;
  Rigid frame;       // local -> world
  std::string name;  // names the surface, e.g. for boundary tags ("inner", "outer")
};

// Primitives in world coordinates. Axis-aligned ones keep world coordinates exact in the
// local frame, so a point exactly on a face or on the sphere x^2+y^2+z^2 = r^2 is seen as on it.
Primitive sphere(const Vec3& centre, double radius, std::string name = "sphere");
Primitive box(const Vec3& lo, const Vec3& hi, std::string name = "box");
// Finite cylinder between the centres of its two caps.
Primitive cylinder(const Vec3& base, const Vec3& top, double radius,
                   std::string name = "cylinder");
Primitive torus(const Vec3& centre, const Vec3& axis, double major, double minor,
                std::string name = "torus");
Primitive ellipsoid(const Vec3& centre, const Vec3& semi_axes, std::string name = "ellipsoid");
// The half-space {x : normal . (x - point) <= 0}; `normal` points out of it.
Primitive half_space(const Vec3& point, const Vec3& normal, std::string name = "half-space");
// The primitive moved by `motion` (applied after its current frame).
Primitive moved(Primitive p, const Rigid& motion);

// Space partitioned by primitives. A point inside exactly the primitives of `mask` is in
// region table[mask]. Priority on interfaces: a higher label wins (0, outside, is lowest).
// A point on surfaces gets the largest label among the regions around it: the masks
// obtained by putting it inside or outside each of those surfaces, where surfaces that
// coincide there go together (both or neither when equally oriented, as in A - B with B
// touching A's face from inside; exactly one when opposite, as for two boxes sharing a
// face), and labels that occur nowhere are skipped.
class AnalyticDomain final : public Domain {
 public:
  using Mask = std::uint32_t;
  static constexpr int kMaxPrimitives = 16;

  // table.size() == 2^primitives.size(), table[0] == 0 (the domain is bounded).
  // Throws InputError on invalid shapes, tables or unbounded regions.
  AnalyticDomain(std::vector<Primitive> primitives, std::vector<Index> table);

  using Domain::crossings;
  using Domain::region;
  Index region(const Vec3& p) const override;
  // Crossings at t = 0 or 1 appear when an end point lies on an interface (it then has the
  // region of higher priority, the open segment next to it another one). Tangential touches
  // have before == after; their normal points out of the region of the touching point.
  std::vector<Crossing> crossings(const Vec3& a, const Vec3& b) const override;
  Vec3 normal(const Vec3& p) const override;
  Box3 bounds() const override { return bounds_; }
  // Found at construction by tracing a 32 x 32 grid of lines along each axis through the
  // bounds, so a region thinner than bounds/32 in two directions could be missed.
  std::vector<Index> regions() const override { return regions_; }

  // Name of the primitive whose surface normal(p) uses: the nearest interface.
  std::string surface_name(const Vec3& p) const override;
  std::span<const Primitive> primitives() const { return primitives_; }

 private:
  struct Masks {  // primitives containing a point: certainly (in) or on their surface (on)
    Mask in = 0, on = 0;
  };
  struct Nearest {
    int primitive;
    Vec3 normal;  // oriented out of the higher-priority region
  };
  Masks classify(const Vec3& p) const;
  // The mask of highest priority among those around p, a point with masks m.
  Mask winner(Masks m, const Vec3& p) const;
  Nearest nearest_interface(const Vec3& p) const;

  std::vector<Primitive> primitives_;
  std::vector<Box3> reach_;  // world box of each primitive, grown far beyond rounding
  std::vector<Index> table_;
  std::vector<char> occurs_;  // per mask: its label occurs somewhere (or is 0)
  Box3 bounds_;
  std::vector<Index> regions_;
};

// Multi-material mode: every non-empty overlap of the primitives is its own region, and
// the region label is the bitmask itself (bit i for primitives[i]): with three primitives,
// 1, 2, 4 are the parts inside one only, 3, 5, 6 inside two, 7 inside all three.
AnalyticDomain multi_material_domain(std::vector<Primitive> primitives);

}  // namespace volmesh
