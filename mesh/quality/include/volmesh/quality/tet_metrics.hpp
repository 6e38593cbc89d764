#pragma once
// Shape metrics of a single tetrahedron.
#include "volmesh/core/types.hpp"

namespace volmesh {

struct TetMetrics {
  // Interior dihedral angles along the six edges, in degrees. They do not depend on the
  // orientation: an inverted tet has the angles of its mirror image (see `volume`).
  double min_dihedral_deg = 0.0, max_dihedral_deg = 0.0;
  // Circumradius / shortest edge: sqrt(6)/4 ≈ 0.612 for the regular tet (the quality measure
  // of Delaunay refinement). +inf for a flat tet.
  double radius_edge_ratio = 0.0;
  // Circumradius / (3 · inradius), Verdict's "radius ratio": 1 for the regular tet, growing
  // without bound as the tet flattens; +inf for a flat tet.
  double aspect_ratio = 0.0;
  // Signed volume, positive for det(b-a, c-a, d-a) > 0 (VTK order); negative = inverted.
  double volume = 0.0;
};

TetMetrics tet_metrics(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace volmesh
