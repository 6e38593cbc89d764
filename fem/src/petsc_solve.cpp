#include "petsc_solve.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#ifdef VOLMESH_HAVE_PETSC
#include <petscksp.h>
#endif

#include "volmesh/fem/parallel.hpp"

namespace volmesh::fem::detail {

OwnedRows owned_rows_of(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& rhs) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> full =
      lower.selfadjointView<Eigen::Lower>();
  OwnedRows out;
  out.global = static_cast<Index>(full.rows());
  out.offsets.assign(full.outerIndexPtr(), full.outerIndexPtr() + full.rows() + 1);
  out.columns.assign(full.innerIndexPtr(), full.innerIndexPtr() + full.nonZeros());
  out.values.assign(full.valuePtr(), full.valuePtr() + full.nonZeros());
  out.rhs = rhs;
  return out;
}

#ifdef VOLMESH_HAVE_PETSC
namespace {

using Clock = std::chrono::steady_clock;

void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw std::runtime_error(std::string("PETSc: ") + what + ": " + (text ? text : "error"));
}

// Destroys PETSc objects at scope exit, exceptions included.
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Owned {
  T object = nullptr;
  ~Owned() {
    if (object) Destroy(&object);
  }
};

// The backend's defaults, put in PETSc's options database only where the command line has
// not set them, and taken out again once the solver has read them (the next solve may be
// of the other kind).
class Defaults {
 public:
  void set(const char* name, const char* value) {
    if (given(name)) return;
    check(PetscOptionsSetValue(nullptr, name, value), "options");
    names_.push_back(name);
  }
  static bool given(const char* name) {
    PetscBool has = PETSC_FALSE;
    check(PetscOptionsHasName(nullptr, nullptr, name, &has), "options");
    return has;
  }
  ~Defaults() {
    for (const char* name : names_) PetscOptionsClearValue(nullptr, name);
  }

 private:
  std::vector<const char*> names_;
};

// BoomerAMG for the 3D Laplacian: PMIS coarsening, extended+i interpolation (at most 4
// entries per row) and a strong threshold of 0.25. On cut-cell matrices (about 26 entries per
// row) HMIS with a threshold of 0.5 keeps 42% of the rows on the first coarse level, an
// operator complexity of 2.6; PMIS with 0.25 gives 1.3 and fewer iterations. Aggressive
// coarsening (-pc_hypre_boomeramg_agg_nl 1) is cheaper still but the iterations grow by about
// 3 per level. W-cycles keep the iterations flat over refinement (V-cycles add one per
// level), and Chebyshev smoothing, matrix-vector products only, makes each cycle cheaper than
// hybrid Gauss-Seidel on these dense rows. Elasticity: HMIS with 0.5 on the nodal (block
// size 3) system, nodes coarsened together, Chebyshev smoothing; interpolation fitted to the
// rigid-body modes (vec_interp_variant) multiplies the set-up time by nine on cut-cell meshes
// for the same iterations, so it is left to the command line, and with it the smoothing stays
// hypre's own (hypre 2.26's set-up does not return with both).
void set_defaults(Defaults& d, int block_size) {
  const bool nodal = block_size == 3;
  d.set("-pc_type", "hypre");
  d.set("-pc_hypre_type", "boomeramg");
  d.set("-pc_hypre_boomeramg_coarsen_type", nodal ? "HMIS" : "PMIS");
  d.set("-pc_hypre_boomeramg_interp_type", "ext+i");
  d.set("-pc_hypre_boomeramg_P_max", "4");
  d.set("-pc_hypre_boomeramg_strong_threshold", nodal ? "0.5" : "0.25");
  if (!d.given("-pc_hypre_boomeramg_vec_interp_variant"))
    d.set("-pc_hypre_boomeramg_relax_type_all", "Chebyshev");
  if (nodal)
    d.set("-pc_hypre_boomeramg_nodal_coarsen", "6");
  else
    d.set("-pc_hypre_boomeramg_cycle_type", "W");
}

std::string method_name(KSP ksp, PC pc) {
  KSPType ksp_type = nullptr;
  PCType pc_type = nullptr;
  check(KSPGetType(ksp, &ksp_type), "solver type");
  check(PCGetType(pc, &pc_type), "preconditioner type");
  std::string pc_name = pc_type ? pc_type : "none";
  if (pc_name == PCHYPRE) {
    const char* hypre = nullptr;
    check(PCHYPREGetType(pc, &hypre), "hypre type");
    if (hypre) pc_name = hypre;
  }
  return std::string(ksp_type ? ksp_type : "?") + "+" + pc_name;
}

}  // namespace

Eigen::VectorXd petsc_solve_spd(const OwnedRows& rows, const LinearSolverOptions& options,
                                LinearSolveReport& report) {
  start_petsc();
  const MPI_Comm comm = rows.distributed ? PETSC_COMM_WORLD : PETSC_COMM_SELF;
  const PetscInt m = static_cast<PetscInt>(rows.rhs.size());
  Owned<Mat, MatDestroy> a;
  Owned<Vec, VecDestroy> x, b, coordinates;
  Owned<KSP, KSPDestroy> ksp;
  PC pc = nullptr;
  // The matrix, the solver and its set-up: the stage "preconditioner" (fem::stage).
  stage("preconditioner", [&] {
    check(MatCreate(comm, &a.object), "matrix");
    check(MatSetSizes(a.object, m, m, rows.global, rows.global), "matrix sizes");
    check(MatSetBlockSize(a.object, rows.block_size), "matrix block size");
    check(MatSetType(a.object, MATAIJ), "matrix type");
    // The CSR rows give the exact preallocation and the values at once; only the call of the
    // matrix's own type (one rank: sequential) acts.
    check(MatSeqAIJSetPreallocationCSR(a.object, rows.offsets.data(), rows.columns.data(),
                                       rows.values.data()),
          "matrix values");
    check(MatMPIAIJSetPreallocationCSR(a.object, rows.offsets.data(), rows.columns.data(),
                                       rows.values.data()),
          "matrix values");
    check(MatSetOption(a.object, MAT_SPD, PETSC_TRUE), "matrix option");

    check(MatCreateVecs(a.object, &x.object, &b.object), "vectors");
    {
      PetscScalar* v = nullptr;
      check(VecGetArray(b.object, &v), "right-hand side");
      for (PetscInt i = 0; i < m; ++i) v[i] = rows.rhs[i];
      check(VecRestoreArray(b.object, &v), "right-hand side");
    }
    if (rows.block_size == 3 && !rows.coordinates.empty()) {
      check(VecCreateMPI(comm, m, rows.global, &coordinates.object), "coordinates");
      check(VecSetBlockSize(coordinates.object, 3), "coordinates");
      PetscScalar* v = nullptr;
      check(VecGetArray(coordinates.object, &v), "coordinates");
      for (PetscInt i = 0; i < m; ++i) v[i] = rows.coordinates[i];
      check(VecRestoreArray(coordinates.object, &v), "coordinates");
      Owned<MatNullSpace, MatNullSpaceDestroy> rigid;
      check(MatNullSpaceCreateRigidBody(coordinates.object, &rigid.object), "rigid-body modes");
      check(MatSetNearNullSpace(a.object, rigid.object), "rigid-body modes");
    }

    PetscBool hypre = PETSC_FALSE;
    check(PetscHasExternalPackage("hypre", &hypre), "external packages");
    if (!hypre)
      throw std::runtime_error(
          "this PETSc has no hypre (PCHYPRE not available): install PETSc with hypre "
          "(Debian: petsc-dev), or choose the Eigen solver (--solver eigen)");
    check(KSPCreate(comm, &ksp.object), "solver");
    check(KSPSetOperators(ksp.object, a.object, a.object), "solver");
    check(KSPSetType(ksp.object, KSPCG), "solver");
    // The tolerance means what it means for the Eigen solvers: ‖b − Ax‖ / ‖b‖ from x = 0.
    check(KSPSetNormType(ksp.object, KSP_NORM_UNPRECONDITIONED), "solver");
    check(KSPSetTolerances(ksp.object, options.tolerance, 0.0, PETSC_DEFAULT,
                           options.max_iterations),
          "solver");
    check(KSPGetPC(ksp.object, &pc), "preconditioner");
    {
      Defaults defaults;
      set_defaults(defaults, rows.block_size);
      check(KSPSetFromOptions(ksp.object), "solver options");
    }
    const Clock::time_point setting_up = Clock::now();
    check(KSPSetUp(ksp.object), "preconditioner set-up");
    check(PCSetUp(pc), "preconditioner set-up");
    report.preconditioner_seconds =
        std::chrono::duration<double>(Clock::now() - setting_up).count();
  });

  // CG, its outcome and the solution: the stage "solve".
  Eigen::VectorXd out(m);
  stage("solve", [&] {
    const Clock::time_point solving = Clock::now();
    // A solve that fails at its iterations (-ksp_error_if_not_converged) says so by the
    // reason, not by the error code.
    const PetscErrorCode solved = KSPSolve(ksp.object, b.object, x.object);
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    PetscInt iterations = 0;
    check(KSPGetConvergedReason(ksp.object, &reason), "solve");
    check(KSPGetIterationNumber(ksp.object, &iterations), "solve");
    report.method = method_name(ksp.object, pc);
    report.iterations = static_cast<int>(iterations);
    if (reason >= 0) check(solved, "solve");

    // The true relative residual, over all ranks.
    Owned<Vec, VecDestroy> r;
    check(VecDuplicate(b.object, &r.object), "residual");
    check(MatMult(a.object, x.object, r.object), "residual");
    check(VecAYPX(r.object, -1.0, b.object), "residual");
    PetscReal nr = 0.0, nb = 0.0;
    check(VecNorm(r.object, NORM_2, &nr), "residual");
    check(VecNorm(b.object, NORM_2, &nb), "residual");
    report.residual = nb > 0.0 ? nr / nb : nr;
    if (reason < 0)
      throw std::runtime_error("PETSc: " + report.method + " did not converge in " +
                               std::to_string(iterations) +
                               (iterations == 1 ? " iteration" : " iterations") +
                               " (relative residual " + std::to_string(report.residual) +
                               "; PETSc's reason: " + KSPConvergedReasons[reason] + ")");
    const PetscScalar* v = nullptr;
    check(VecGetArrayRead(x.object, &v), "solution");
    for (PetscInt i = 0; i < m; ++i) out[i] = v[i];
    check(VecRestoreArrayRead(x.object, &v), "solution");
    report.solve_seconds = std::chrono::duration<double>(Clock::now() - solving).count();
  });
  return out;
}

#else

Eigen::VectorXd petsc_solve_spd(const OwnedRows&, const LinearSolverOptions&,
                                LinearSolveReport&) {
  throw std::runtime_error("this volmesh was built without PETSc (--solver eigen)");
}

#endif

}  // namespace volmesh::fem::detail
