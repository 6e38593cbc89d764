#pragma once
// The cell-centred finite-volume discretisation (finite_volume.hpp describes the scheme):
// per-face coefficients, the least-squares gradient operator, the two-point matrix and the
// right-hand sides.
#include <cstdint>
#include <vector>

#include <Eigen/SparseCore>

#include "volmesh/core/geometry.hpp"
#include "volmesh/fem/problem.hpp"

namespace volmesh::fem {

enum class FvFace : std::uint8_t { internal, interface, dirichlet, neumann };

struct FvSystem {
  CellFaces cell_faces;
  MeshGeometry geometry;
  std::vector<double> k;  // per cell

  // Per face.
  std::vector<FvFace> kind;
  std::vector<double> coefficient;  // a_f
  std::vector<Vec3> correction;     // t_f: (d_P + d_N) n − d, zero when not corrected
  std::vector<double> owner_weight; // share of the owner's gradient in ∇u_f
  std::vector<double> boundary_value;  // u on a Dirichlet face, the flux on a Neumann face
  bool non_orthogonal = false;         // some correction vector is not zero

  // Least-squares gradient ∇u_c = constant_c + Σ_j lsq_j Δ_j over the faces j of c (in
  // cell_faces order), Δ_j = u_other − u_c across an internal face, u_b − u_c on a Dirichlet
  // face, nothing on a Neumann face (its condition sits in constant_c).
  std::vector<Vec3> lsq;               // parallel to cell_faces.faces
  std::vector<Vec3> gradient_constant; // per cell
};

// Geometry, coefficients and gradient operator; checks the problem's data against the mesh.
FvSystem build_fv_system(const PolyMesh& mesh, const PoissonProblem& problem, bool corrected);

// Lower triangle of the symmetric two-point matrix.
Eigen::SparseMatrix<double> fv_matrix(const PolyMesh& mesh, const FvSystem& system);

// Source and boundary terms: the right-hand side without non-orthogonal correction.
Eigen::VectorXd fv_base_rhs(const PolyMesh& mesh, const FvSystem& system,
                            const PoissonProblem& problem);

// With boundary_data false: the linear part alone (Dirichlet values and Neumann fluxes taken
// as zero), for the correction operator acting on a change of u.
std::vector<Vec3> fv_gradients(const PolyMesh& mesh, const FvSystem& system,
                               const Eigen::VectorXd& u, bool boundary_data = true);

// Non-orthogonal correction fluxes summed per cell (added to the right-hand side).
Eigen::VectorXd fv_correction(const PolyMesh& mesh, const FvSystem& system,
                              const std::vector<Vec3>& gradients);

}  // namespace volmesh::fem
