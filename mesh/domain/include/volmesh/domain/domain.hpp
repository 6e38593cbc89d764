#pragma once
// What every mesher takes (docs/methods.md, "Domains"): a partition of space into regions, with
// the interfaces between them. Region 0 is outside; regions are numbered from 1.
#include <span>
#include <string>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

struct Box3 {
  Vec3 lo, hi;
  Vec3 size() const { return hi - lo; }
  Vec3 centre() const { return 0.5 * (lo + hi); }
};

// One interface crossing on a segment a -> b.
struct Crossing {
  double t = 0.0;         // parameter in [0, 1]: point = a + t (b - a)
  Vec3 point = Vec3::Zero();
  Index before = 0;       // region just before the crossing (towards a)
  Index after = 0;        // region just after it (towards b)
  Vec3 normal = Vec3::Zero();  // unit normal of the interface, pointing from `before` into `after`
};

class Domain {
 public:
  virtual ~Domain() = default;

  // Region at p; a point exactly on an interface gets the region of higher priority.
  virtual Index region(const Vec3& p) const = 0;
  // Every interface crossing on the segment, sorted by t; crossings between the same pair
  // of regions and tangential touches are reported so that meshers can refine edges that
  // are crossed more than once.
  virtual std::vector<Crossing> crossings(const Vec3& a, const Vec3& b) const = 0;
  // Unit normal of the interface nearest to p, pointing out of the higher-priority region
  // (for a single solid: the outward normal).
  virtual Vec3 normal(const Vec3& p) const = 0;
  // A box containing every point with region != 0.
  virtual Box3 bounds() const = 0;
  // Whether every point of bounds() lies in a region (a layered model): the box's faces are
  // then the domain's boundary, and an octree whose root starts at the box need not cut them.
  virtual bool fills_bounds() const { return false; }
  // The region labels that occur (>= 1), sorted.
  virtual std::vector<Index> regions() const = 0;
  // Name of the interface nearest to p, for tagging boundary faces (e.g. "inner", "outer");
  // empty when the domain does not name its surfaces.
  virtual std::string surface_name(const Vec3& p) const { return {}; }
  // Name of the boundary surface (between region 0 and the others) nearest to p, for tagging
  // the boundary faces of a mesh; surface_name(p) unless the domain knows its boundary better.
  virtual std::string boundary_name(const Vec3& p) const { return surface_name(p); }

  // Batch versions: in parallel, same results as the single queries in the same order.
  // Subclasses override them where a batch can be answered faster than point by point.
  virtual void region(std::span<const Vec3> points, std::span<Index> out) const;
  virtual void crossings(std::span<const Vec3> a, std::span<const Vec3> b,
                         std::vector<std::vector<Crossing>>& out) const;
};

}  // namespace volmesh
