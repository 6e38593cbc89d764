#pragma once
// Conforming finite elements for Poisson and linear elasticity on a PolyMesh.
//
// Spaces (Space):
//   p1          linear tetrahedra; needs a mesh of tets
//   p2          quadratic tetrahedra (nodes at corners and edge midpoints); needs tets.
//               Isoparametric where the boundary is curved: given problem.to_true_boundary,
//               the node of each boundary-face edge whose ends lie on the true boundary
//               moves to its midpoint's image there, and the tets with such a node use the
//               quadratic (10-node) geometry map in every integral (degree-5 rule), their
//               boundary faces the 6-node one; the other tets stay affine. Third order in L2
//               on curved domains, where straight edges cap it at second.
//   q1          trilinear hexahedra, 2×2×2 Gauss points; needs hexes
//   polyhedral  lowest-order conforming space on any cell (octree cells with hanging faces,
//               cut cells with warped or non-convex faces): P1 on the sub-tessellation of
//               polyhedral.hpp. A face node at each face's vertex average carries the mean of
//               the face's vertex values (one constraint seen alike from both cells:
//               conforming; exact for linear functions, whose mean over the vertices is their
//               value at the vertex average); a non-convex face whose fan would fold is
//               triangulated instead. A cell node at the cell's star centre (its vertex
//               average unless that does not see every face) is a free unknown eliminated per
//               cell by static condensation. Condensing rather than fixing the cell node to
//               the vertex mean: the space is larger (it contains the constrained one), so the
//               Galerkin solution is at least as accurate in energy, at no cost in global
//               unknowns, and the node may sit anywhere that sees the faces. Sub-tessellation
//               rather than lowest-order VEM: a genuine piecewise-linear space, so errors,
//               stresses and VTU output are evaluated exactly, with no projection or
//               stabilisation parameter.
// The global unknowns are the mesh vertices (plus edge midpoints for p2).
//
// Boundary data are taken at the mesh boundary point mapped by problem.to_true_boundary:
// Dirichlet values at the nodes (a p2 edge node: at its mapped edge midpoint), Neumann
// fluxes and tractions at the face quadrature points (degree 5). A node on faces of several
// Dirichlet tags takes the data of the lowest tag index. Dirichlet values are eliminated
// (solve_spd_constrained).
//
// Errors (when problem.exact is given): L2 and the H1 seminorm with a degree-5 rule on each
// (sub-)element (3×3×3 Gauss on hexes), L∞ at the nodes.
//
// Input checks throw volmesh::InputError: a region without conductivity/material, a
// boundary tag without a condition, no Dirichlet (displacement) tag at all, an inverted or
// degenerate cell (non-positive Jacobian; for the polyhedral space: no point inside sees all
// its faces; for curved p2: at a quadrature point of the curved map), a cell the space cannot
// take (p1 on a hex).
//
// Local matrices are computed in parallel (TBB) and added in cell order: the same bytes for
// any thread count. The problem's functions (source, boundary data, exact solution) are
// called from several threads at once and must allow it.
#include <Eigen/Core>
#include <optional>
#include <string_view>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/fem/linear_solver.hpp"
#include "volmesh/fem/problem.hpp"
#include "volmesh/fem/solution.hpp"

namespace volmesh::fem {

enum class Space { p1, p2, q1, polyhedral };

const char* space_name(Space space);  // "p1", "p2", "q1", "polyhedral"
std::optional<Space> space_from_name(std::string_view name);

// cell_values: the mean of u_h over each cell. point_values: u_h at each mesh point (NaN at a
// point no cell uses). solve: the stage times (setup, assembly, ... errors) add up to the run.
ScalarSolution solve_poisson(const PolyMesh& mesh, const PoissonProblem& problem, Space space,
                             const LinearSolverOptions& options = {});

// cell_stress: the mean stress over each cell; von_mises: of that mean. Errors are those of
// the displacement (vector norms).
VectorSolution solve_elasticity(const PolyMesh& mesh, const ElasticityProblem& problem, Space space,
                                const LinearSolverOptions& options = {});

struct LameParameters {
  double lambda;
  double mu;
};
LameParameters lame_parameters(const IsotropicMaterial& material);

// σ = λ tr(ε) I + 2μ ε with ε the symmetric part of the displacement gradient.
Eigen::Matrix3d isotropic_stress(const Eigen::Matrix3d& displacement_gradient,
                                 const LameParameters& lame);

// √(3/2 s:s), s the deviatoric part of σ.
double von_mises(const Eigen::Matrix3d& stress);

}  // namespace volmesh::fem
