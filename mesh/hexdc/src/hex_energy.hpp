#pragma once
// The per-hex terms the global optimiser (optimise.hpp) minimises, each with its gradient in the
// hex's eight corners. Every hex counts its ten corner tets (kHexCornerTets): the eight corner
// Jacobians and the two inner tets of the ten-tet test.
#include <array>

#include "volmesh/core/types.hpp"

namespace volmesh::hexdc_detail {

using HexGradient = std::array<Vec3, 8>;

// The untangling energy of Garanzha et al. ("Foldover-free maps in 50 lines of code", 2021) over
// the ten tets, each measured against its shape in a cube of side `size` (J = E R⁻¹ / size, R the
// tet's edges in the unit cube, so that J = I in that cube):
//   f_ε(J) = (1 − θ) tr(JᵀJ) / χ(det J, ε)^(2/3) + θ (det² J + 1) / χ(det J, ε),
//   χ(D, ε) = (D + √(ε² + D²)) / 2,
// finite for any J when ε > 0 and a barrier at det J = 0 as ε → 0; its minimum in J is a
// rotation. Adds the gradient to `gradient` and returns the energy; `min_det` is lowered to the
// least det J of the ten.
struct Barrier {
  double epsilon = 0.0;
  double theta = 0.0;  // the volume term's weight
};
double hex_barrier(const std::array<Vec3, 8>& corners, double size, const Barrier& barrier,
                   HexGradient& gradient, double& min_det);

// The ten tets' shape measures: for the eight corner tets the corner's scaled Jacobian
// det(e1, e2, e3) / (|e1| |e2| |e3|), for the two inner tets the same scaled to 1 in a cube (as
// hex_shape_quality). Positive exactly when the tet is.
std::array<double, 10> hex_tet_qualities(const std::array<Vec3, 8>& corners);

// The scaled Jacobian at the hex's centre: det / product of lengths of the principal axes (the
// trilinear map's derivatives there), Verdict's ninth term, which no corner tet bounds.
double hex_centre_quality(const std::array<Vec3, 8>& corners);

// A hex's or quad's soft-minimum terms taken about their own least, so that no exponential
// overflows: the whole sum weighs each part by exp(−β (least − the least of all)).
struct SoftminTerms {
  double least = 0.0;  // the least term
  double sum = 0.0;    // Σ exp(−β (q − least)) over the terms, at least 1
  double least_tet = 0.0;  // a hex's least tet measure (a quad's least sine)
  double other = 0.0;      // a hex's centre measure (a quad's least sine)
};

// The ten tet measures and the centre's, which together cover every term of
// hex_scaled_jacobian; adds the gradient of `sum` to `gradient`.
SoftminTerms hex_softmin_terms(const std::array<Vec3, 8>& corners, double beta,
                               HexGradient& gradient);

// The sines of a quad's four interior angles about its unit vector-area normal: 1 at a right
// angle, 0 at 0° or 180°, negative at a reflex corner.
std::array<double, 4> quad_sines(const std::array<Vec3, 4>& quad);

// The four corner sines; adds the gradient of `sum` to `gradient`, the normal held fixed (exact
// for a planar quad, whose normal the corners' in-plane moves do not turn).
SoftminTerms quad_softmin_terms(const std::array<Vec3, 4>& quad, double beta,
                                std::array<Vec3, 4>& gradient);

}  // namespace volmesh::hexdc_detail
