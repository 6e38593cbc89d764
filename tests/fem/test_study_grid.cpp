// The study driver on real solves: P1 on Kuhn-split grids of the unit cube converges at
// second order in L2 and first order in the H1 seminorm, and the figures per level are the
// meshes' own.
#include <gtest/gtest.h>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/fem/fem.hpp"
#include "volmesh/fem/problems.hpp"
#include "volmesh/fem/study.hpp"

namespace volmesh::fem {
namespace {

TEST(StudyGrid, P1OnTetGridsIsSecondOrderInL2) {
  const std::unique_ptr<Domain> box = make_builtin_domain("box");
  const MeshAtLevel mesh = [](int level, const Progress&) {
    const Index n = Index{1} << level;
    return StudyMesh{to_poly_mesh(kuhn_tet_mesh(Vec3::Zero(), Vec3::Ones(), {n, n, n})),
                     1.0 / n};
  };
  const SolveOnMesh solve = [&](const PolyMesh& m, const Progress&) {
    const ScalarSolution s =
        solve_poisson(m, make_poisson_problem("sine", *box, m.tag_names), Space::p1);
    return LevelSolve{s.dofs, s.solve, s.errors};
  };
  const ConvergenceSeries series = run_convergence_study("grid tets (p1)", 2, 4, mesh, solve);
  ASSERT_EQ(series.levels.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const Index n = Index{4} << i;
    EXPECT_EQ(series.levels[i].cells, 6 * n * n * n);
    EXPECT_EQ(series.levels[i].dofs, (n + 1) * (n + 1) * (n + 1));
    EXPECT_DOUBLE_EQ(series.levels[i].h, 1.0 / n);
  }
  const SeriesRates rates = convergence_rates(series);
  EXPECT_NEAR(rates.slope[0], 2.0, 0.15) << "L2";
  EXPECT_NEAR(rates.slope[1], 2.0, 0.2) << "Linf";
  EXPECT_NEAR(rates.slope[2], 1.0, 0.1) << "H1";
  for (double r : rates.pairwise[0]) EXPECT_GT(r, 1.8);
}

}  // namespace
}  // namespace volmesh::fem
