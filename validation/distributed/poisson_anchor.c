/* The anchor of the distributed study: PETSc/hypre on the plainest problem of the same size,
 * -Δu = 1 on the unit cube, u = 0 on its boundary, on an n³ grid of interior unknowns (DMDA,
 * one box per rank), in one of two stencils:
 *   -stencil 7:  the 7-point finite-difference stencil;
 *   -stencil 27: trilinear (Q1) finite elements on the grid's cubes, the 27-point box stencil
 *                (centre 8h/3, the 12 edge neighbours -h/6, the 8 corner neighbours -h/12,
 *                the 6 face neighbours 0 kept as stored entries, as a Q1 assembly stores them),
 *                so that its rows hold what volmesh's Q1 rows on whole octree cells hold.
 * CG + BoomerAMG with volmesh's scalar defaults (set_defaults in fem/src/petsc_solve.cpp: PMIS,
 * ext+i, P_max 4, strong threshold 0.25, W-cycles, Chebyshev smoothing; -pc_hypre_* options
 * given override them), relative residual 1e-8. Prints one JSON line: stencil, unknowns,
 * ranks, iterations and the assembly, preconditioner and solve seconds.
 * Usage: poisson_anchor -n N [-stencil 7|27] [PETSc options]. */
#include <petscdmda.h>
#include <petscksp.h>

enum { kStarPoints = 7, kBoxPoints = 27 };

/* The stencil's weight towards the neighbour at offset (di, dj, dk), each in {-1, 0, 1}. */
static PetscScalar weight(PetscInt stencil, PetscReal h, int di, int dj, int dk) {
  const int away = (di != 0) + (dj != 0) + (dk != 0);
  if (stencil == kStarPoints) return away == 0 ? 6.0 / (h * h) : -1.0 / (h * h);
  static const PetscReal q1[4] = {8.0 / 3.0, 0.0, -1.0 / 6.0, -1.0 / 12.0};
  return q1[away] * h;
}

static PetscErrorCode assemble(DM da, PetscInt stencil, Mat a, Vec b) {
  DMDALocalInfo info;
  MatStencil row, col[kBoxPoints];
  PetscScalar v[kBoxPoints];
  PetscFunctionBeginUser;
  PetscCall(DMDAGetLocalInfo(da, &info));
  const PetscReal h = 1.0 / (info.mx + 1);
  for (PetscInt k = info.zs; k < info.zs + info.zm; ++k)
    for (PetscInt j = info.ys; j < info.ys + info.ym; ++j)
      for (PetscInt i = info.xs; i < info.xs + info.xm; ++i) {
        PetscInt n = 0;
        row.i = i, row.j = j, row.k = k, row.c = 0;
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              const int away = (di != 0) + (dj != 0) + (dk != 0);
              if (stencil == kStarPoints && away > 1) continue;
              const PetscInt ii = i + di, jj = j + dj, kk = k + dk;
              if (ii < 0 || jj < 0 || kk < 0 || ii >= info.mx || jj >= info.my || kk >= info.mz) continue;
              col[n].i = ii, col[n].j = jj, col[n].k = kk, col[n].c = 0;
              v[n++] = weight(stencil, h, di, dj, dk);
            }
        PetscCall(MatSetValuesStencil(a, 1, &row, n, col, v, INSERT_VALUES));
      }
  PetscCall(MatAssemblyBegin(a, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(a, MAT_FINAL_ASSEMBLY));
  /* The load of f = 1: h² per unknown for the difference stencil, h³ for Q1 (lumped). */
  PetscCall(VecSet(b, stencil == kStarPoints ? 1.0 : h * h * h));
  PetscFunctionReturn(0);
}

int main(int argc, char** argv) {
  PetscInt n = 64, stencil = kStarPoints;
  DM da;
  Mat a;
  Vec x, b;
  KSP ksp;
  PC pc;
  PetscMPIInt ranks;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &ranks));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-n", &n, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-stencil", &stencil, NULL));
  PetscCheck(stencil == kStarPoints || stencil == kBoxPoints, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
             "-stencil %" PetscInt_FMT ": the anchor has the 7- and the 27-point stencils", stencil);
  double t0 = MPI_Wtime();
  const DMDAStencilType shape = stencil == kStarPoints ? DMDA_STENCIL_STAR : DMDA_STENCIL_BOX;
  PetscCall(DMDACreate3d(PETSC_COMM_WORLD, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, shape, n,
                         n, n, PETSC_DECIDE, PETSC_DECIDE, PETSC_DECIDE, 1, 1, NULL, NULL, NULL, &da));
  PetscCall(DMSetUp(da));
  PetscCall(DMCreateMatrix(da, &a));
  PetscCall(DMCreateGlobalVector(da, &b));
  PetscCall(VecDuplicate(b, &x));
  PetscCall(assemble(da, stencil, a, b));
  double t1 = MPI_Wtime();
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetOperators(ksp, a, a));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED));
  PetscCall(KSPSetTolerances(ksp, 1e-8, 0.0, PETSC_DEFAULT, 1000));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCHYPRE));
  PetscCall(PCHYPRESetType(pc, "boomeramg"));
  /* volmesh's scalar defaults; the command line's own -pc_hypre_* options win. */
  const char* defaults[][2] = {{"-pc_hypre_boomeramg_coarsen_type", "PMIS"},
                               {"-pc_hypre_boomeramg_interp_type", "ext+i"},
                               {"-pc_hypre_boomeramg_P_max", "4"},
                               {"-pc_hypre_boomeramg_strong_threshold", "0.25"},
                               {"-pc_hypre_boomeramg_cycle_type", "W"},
                               {"-pc_hypre_boomeramg_relax_type_all", "Chebyshev"}};
  for (size_t i = 0; i < sizeof defaults / sizeof defaults[0]; ++i) {
    PetscBool given;
    PetscCall(PetscOptionsHasName(NULL, NULL, defaults[i][0], &given));
    if (!given) PetscCall(PetscOptionsSetValue(NULL, defaults[i][0], defaults[i][1]));
  }
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(KSPSetUp(ksp));
  PetscCall(PCSetUp(pc));
  double t2 = MPI_Wtime();
  PetscCall(KSPSolve(ksp, b, x));
  double t3 = MPI_Wtime();
  PetscInt its;
  PetscCall(KSPGetIterationNumber(ksp, &its));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                        "{\"stencil\": %" PetscInt_FMT ", \"unknowns\": %" PetscInt_FMT
                        ", \"ranks\": %d, \"iterations\": %" PetscInt_FMT
                        ", \"assembly\": %.3f, \"preconditioner\": %.3f, \"solve\": %.3f}\n",
                        stencil, n * n * n, ranks, its, t1 - t0, t2 - t1, t3 - t2));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&a));
  PetscCall(DMDestroy(&da));
  PetscCall(PetscFinalize());
  return 0;
}
