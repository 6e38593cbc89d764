#pragma once
// Cell-centred finite volumes for −∇·(k∇u) = f on any PolyMesh (tets, hexes, octree cells
// with hanging faces, cut cells), the scheme of OpenFOAM's laplacian with the `corrected`
// surface-normal gradient:
//   - one unknown per cell at its centroid; f is integrated as f(centroid)·volume;
//   - the flux through a face of area A and unit normal n (owner P → neighbour N) is
//     a_f (u_N − u_P) + a_f t_f·∇u_f with the two-point coefficient
//     a_f = A / (d_P/k_P + d_N/k_N), d_P = n·(x_f − x_P), d_N = n·(x_N − x_f): the
//     distance-weighted harmonic mean of k, exact for a layered solution whose kink lies on
//     the face (and OpenFOAM's over-relaxed k A / (n·d) when k_P = k_N). Each half distance
//     is kept above 0.05 of the centre-to-face distance, OpenFOAM's guard for cells whose
//     centroid lies (nearly) in a face's plane;
//   - non-orthogonal correction t_f = (d_P + d_N) n − d, d = x_N − x_P, with ∇u_f the
//     distance-weighted mean of the least-squares gradients (weights 1/|d|², as OpenFOAM's
//     leastSquares) of the two cells. t_f ⟂ n, so the correction needs only the tangential
//     gradient, which is continuous across a material interface. The correction is deferred:
//     the matrix keeps the symmetric two-point part (SPD, solve_spd) and the corrections are
//     iterated until they stop changing the solution. OpenFOAM's plain sweeps (Richardson
//     iteration) diverge next to sliver cut cells, so the sweeps are accelerated by GMRES,
//     each step one solve with the two-point matrix;
//   - a boundary face is a face with one cell, whatever surface it stands for (a cut-cell
//     face on the curved boundary is one): Dirichlet u at the face centre mapped by
//     to_true_boundary, coefficient k_P A / d_P and the same correction with ∇u_P; Neumann
//     adds the given flux times A. In the least-squares gradient a Dirichlet face enters as
//     a neighbour at the face centre, a Neumann face as the condition n·∇u = g/k_P, and an
//     interface face (k_P ≠ k_N) by the value at the face that makes the two-point fluxes of
//     both halves equal, so the gradient does not mix the two slopes of a kink.
// For a linear exact solution (one k) the converged scheme is exact on any mesh of closed
// cells, guards active or not: least squares reproduce the gradient, the correction turns the
// face flux into k ∇u·S, and the fluxes of a closed cell sum to zero. A solution that is
// linear on each side of a planar material interface is exact too (tested on oblique cuts).
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/fem/linear_solver.hpp"
#include "volmesh/fem/problem.hpp"
#include "volmesh/fem/solution.hpp"

namespace volmesh::fem {

struct FvOptions {
  bool non_orthogonal_correction = true;
  int max_corrections = 200;            // correction solves (each one solve_spd call)
  int restart = 30;                     // GMRES restart length
  double correction_tolerance = 1e-12;  // on ‖A⁻¹(corrected residual)‖ / ‖u‖ (2-norms)
};

struct FvReport {
  int corrections = 0;       // correction solves after the first solve
  double last_change = 0.0;  // ‖A⁻¹(corrected residual)‖ / ‖u‖ at exit: the relative change
                             // one more plain correction sweep would make
  bool converged = true;     // false when max_corrections ran out first
  std::vector<Vec3> cell_gradients;  // least-squares gradient of the solution per cell
};

// ScalarSolution: cell_values at the cell centroids, no point values; dofs = cells; `solve`
// sums the iterations and times of every linear solve, its residual is that of the corrected
// equations at exit. On a non-orthogonal mesh a `solver` of kind automatic solves by CG to
// the correction tolerance (a direct solve would refactorise the same matrix for every
// correction).
// Errors when the problem has an exact solution:
//   L2 = (Σ_c |c| (u(x_c) − u_c)²)^½ (centroid values times volume),
//   L∞ = max_c |u(x_c) − u_c| at the centroids,
//   H1 = (Σ_c |c| |∇u(x_c) − g_c|²)^½ with g_c the least-squares gradient (needs
//        exact_gradient).
// Throws InputError when a cell's region has no (or a non-positive) conductivity, a boundary
// tag has no condition, or no face carries a Dirichlet condition (u would be defined only up
// to a constant); std::runtime_error when the linear solver fails.
ScalarSolution solve_poisson_fv(const PolyMesh& mesh, const PoissonProblem& problem,
                                const LinearSolverOptions& solver, const FvOptions& options = {},
                                FvReport* report = nullptr);

}  // namespace volmesh::fem
