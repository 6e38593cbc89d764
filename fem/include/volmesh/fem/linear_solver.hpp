#pragma once
// Sparse symmetric positive definite systems: a sparse LDLᵀ factorisation for small systems;
// above that conjugate gradients, preconditioned by hypre's BoomerAMG through PETSc when
// this build has PETSc (parallel.hpp), else by an incomplete Cholesky factorisation
// (Eigen's IncompleteCholesky with AMD ordering and its automatic diagonal shift). AMG keeps
// the iteration count about flat under refinement; incomplete Cholesky doubles it with each
// halving of h.
#include <cstdint>
#include <vector>

#include <Eigen/SparseCore>

#include "volmesh/core/progress.hpp"
#include "volmesh/fem/solution.hpp"

namespace volmesh::fem {

struct LinearSolverOptions {
  enum class Kind { automatic, cg, direct };
  // automatic: direct up to direct_limit unknowns, else CG; always CG with Backend::petsc.
  Kind kind = Kind::automatic;
  // Who runs CG: automatic is PETSc when the build has it and the system has more than
  // petsc_limit unknowns, else Eigen. Starting MPI costs a serial run about 0.8 s once, and
  // below the limit Eigen's CG finishes well within a second; above it BoomerAMG's flat
  // iteration count wins (the sine problem on the ball, 102k unknowns: 10 against 58
  // iterations).
  enum class Backend { automatic, eigen, petsc };
  Backend backend = Backend::automatic;
  Index petsc_limit = 50000;
  // Measured (validation/fem/run.sh --solvers): Eigen's simplicial LDLᵀ fills in heavily on
  // 3D meshes, so CG with incomplete Cholesky is faster from about 1,000 unknowns on (P1
  // tets 12,167 unknowns: 0.17 s against 4.0 s; Q1 elasticity 5,184: 0.29 s against 2.1 s).
  // Below it the exact solve costs nothing.
  Index direct_limit = 1000;
  double tolerance = 1e-10;     // on ‖b − Ax‖ / ‖b‖
  int max_iterations = 20000;
  // The solves that take these options (solve_poisson, solve_elasticity, solve_poisson_fv)
  // report their stages here ("assembly", "linear solve", "results": the cell values and
  // errors) with rough fractions of their run; solve_spd ignores it.
  Progress progress;
  // A run over the ranks (parallel.hpp): each cell's rank, the same array on every rank. The
  // finite-element solves are then collective (PETSc over all ranks, see fe_distributed.hpp),
  // whatever the number of unknowns. Null: this process solves alone.
  const std::vector<Index>* cell_rank = nullptr;
  // A run over the ranks in which each rank holds only its piece of the mesh (the pieces of
  // volmesh/octree_dist/rank_piece.hpp): each point's number over all ranks and the rank
  // owning it, the lowest whose cells use it. The solves are then collective, each rank
  // assembling its own cells (fe_pieces.hpp); faces tagged "procBoundary..." lie between
  // pieces. Null: not such a run.
  const std::vector<std::int64_t>* piece_points = nullptr;
  const std::vector<int>* piece_owner = nullptr;
};

// How the unknowns sit on the nodes: `components` per node, node-major, and the nodes'
// points, from which AMG builds the rigid-body modes of elasticity (components 3).
struct NodeLayout {
  int components = 1;
  const std::vector<Vec3>* points = nullptr;  // per node; may be null
};

// Only the lower triangle of `a` is read, so a full symmetric matrix and its lower half give
// the same result. Throws std::runtime_error when CG does not reach the tolerance or the factorisation fails
// (the matrix is not SPD: a mesh or a problem the discretisation cannot handle), or when
// the PETSc backend is asked for in a build without it.
Eigen::VectorXd solve_spd(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                          const LinearSolverOptions& options, LinearSolveReport& report,
                          const NodeLayout& layout = {});

// A symmetric system with some unknowns fixed (Dirichlet values): the rows and columns of the
// fixed unknowns are eliminated, the rest solved by solve_spd, the fixed values put back.
Eigen::VectorXd solve_spd_constrained(const Eigen::SparseMatrix<double>& a,
                                      const Eigen::VectorXd& b,
                                      const std::vector<char>& fixed,
                                      const Eigen::VectorXd& fixed_values,
                                      const LinearSolverOptions& options,
                                      LinearSolveReport& report,
                                      const NodeLayout& layout = {});

}  // namespace volmesh::fem
