#pragma once
// Shape metrics of a single trilinear hexahedron.
#include <array>

#include "volmesh/core/types.hpp"

namespace volmesh {

// Verdict's scaled Jacobian: the minimum over the 8 corners and the centre of
// det(e1, e2, e3) / (|e1|·|e2|·|e3|), where e1..e3 are the three edges leaving a corner
// (at the centre, the three principal axes). Corners in VTK order. 1 for a parallelepiped
// with right angles, in (0, 1) for a valid distorted hex, <= 0 for an inverted one.
// Unlike Verdict, which returns DBL_MAX ("perfect") when an edge has zero length, a
// collapsed edge or principal axis (shorter than 1e-12 of the longest one) gives 0: the hex
// is degenerate (docs/verification.md, "Quality measures").
double hex_scaled_jacobian(const std::array<Vec3, 8>& corners);

// The scaled Jacobian together with the determinants it is made of, from one pass over the
// corners: corner_determinants[k] = det(e1, e2, e3) at corner k, in Verdict's edge order, which
// is 6 times the volume of the tet of corner k and its three edge neighbours.
struct HexJacobians {
  std::array<double, 8> corner_determinants{};
  double scaled_jacobian = 0.0;  // hex_scaled_jacobian
};
HexJacobians hex_jacobians(const std::array<Vec3, 8>& corners);

}  // namespace volmesh
