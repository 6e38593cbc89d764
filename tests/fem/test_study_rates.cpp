// Observed orders on synthetic data with known answers: pairwise rates, the least-squares
// slope, the CSV and the table of a convergence study, and the driver's bookkeeping.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "volmesh/core/errors.hpp"
#include "volmesh/fem/study.hpp"

namespace volmesh::fem {
namespace {

TEST(StudyRates, PairwiseRatesOfAPowerLawAreItsExponent) {
  const std::vector<double> h{0.4, 0.2, 0.1, 0.05};
  std::vector<double> e;
  for (double x : h) e.push_back(3.0 * std::pow(x, 1.7));
  const std::vector<double> r = pairwise_rates(h, e);
  ASSERT_EQ(r.size(), 3u);
  for (double v : r) EXPECT_NEAR(v, 1.7, 1e-12);
}

TEST(StudyRates, PairwiseRatesFollowChangingOrder) {
  // e halves, then quarters, then stays: rates 1, 2, 0 on halving h.
  const std::vector<double> h{1.0, 0.5, 0.25, 0.125};
  const std::vector<double> e{8.0, 4.0, 1.0, 1.0};
  const std::vector<double> r = pairwise_rates(h, e);
  EXPECT_NEAR(r[0], 1.0, 1e-14);
  EXPECT_NEAR(r[1], 2.0, 1e-14);
  EXPECT_NEAR(r[2], 0.0, 1e-14);
}

TEST(StudyRates, UnusablePairsGiveNaN) {
  const std::vector<double> h{1.0, 0.5, 0.5, 0.25};
  const std::vector<double> e{1.0, 0.0, 0.1, 0.05};
  const std::vector<double> r = pairwise_rates(h, e);
  EXPECT_TRUE(std::isnan(r[0]));  // zero error
  EXPECT_TRUE(std::isnan(r[1]));  // zero error and h unchanged
  EXPECT_NEAR(r[2], 1.0, 1e-14);
}

TEST(StudyRates, LeastSquaresSlopeFitsNoisyDataAndIgnoresBadPoints) {
  // log e = 2 log h + log 5 + noise with zero mean and zero correlation with log h:
  // the fitted slope is exactly 2.
  const std::vector<double> h{0.5, 0.25, 0.125, 0.0625};
  const std::vector<double> noise{1.1, 1.0 / 1.1, 1.0 / 1.1, 1.1};
  std::vector<double> e;
  for (std::size_t i = 0; i < h.size(); ++i) e.push_back(5.0 * h[i] * h[i] * noise[i]);
  EXPECT_NEAR(least_squares_slope(h, e), 2.0, 1e-12);
  // The fit sees the noise: the pairwise rates scatter around 2 while the slope does not.
  const std::vector<double> r = pairwise_rates(h, e);
  EXPECT_GT(std::abs(r[0] - 2.0), 0.1);

  std::vector<double> with_bad = e;
  std::vector<double> h_bad = h;
  with_bad.push_back(std::nan(""));
  h_bad.push_back(0.03);
  with_bad.push_back(0.0);
  h_bad.push_back(0.01);
  EXPECT_NEAR(least_squares_slope(h_bad, with_bad), 2.0, 1e-12);
}

TEST(StudyRates, SlopeNeedsTwoDistinctPoints) {
  EXPECT_TRUE(std::isnan(least_squares_slope(std::vector<double>{0.5}, std::vector<double>{1.0})));
  EXPECT_TRUE(std::isnan(least_squares_slope(std::vector<double>{0.5, 0.5},
                                             std::vector<double>{1.0, 0.5})));
}

// Errors e = C h^order per level, h = 2^-level; DOFs 100, 200, ... in call order.
ConvergenceSeries synthetic_series(const std::string& label, double order, int first, int last) {
  double h = 0.0;
  Index dofs = 0;
  return run_convergence_study(
      label, first, last,
      [&](int level, const Progress&) {
        h = std::ldexp(1.0, -level);
        return StudyMesh{PolyMesh{}, h};
      },
      [&](const PolyMesh&, const Progress&) {
        LevelSolve s;
        s.dofs = dofs += 100;
        ErrorNorms e;
        e.l2 = std::pow(h, order);
        e.linf = 2.0 * std::pow(h, order);
        e.h1 = std::pow(h, order - 1.0);
        s.errors = e;
        return s;
      });
}

TEST(StudyDriver, RunsEachLevelInOrderAndMeasuresRates) {
  const ConvergenceSeries s = synthetic_series("second", 2.0, 2, 5);
  ASSERT_EQ(s.levels.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(s.levels[i].level, 2 + static_cast<int>(i));
    EXPECT_DOUBLE_EQ(s.levels[i].h, std::ldexp(1.0, -(2 + static_cast<int>(i))));
    EXPECT_EQ(s.levels[i].dofs, 100 * static_cast<Index>(i + 1));
  }
  const SeriesRates r = convergence_rates(s);
  EXPECT_NEAR(r.slope[0], 2.0, 1e-12);
  EXPECT_NEAR(r.slope[1], 2.0, 1e-12);
  EXPECT_NEAR(r.slope[2], 1.0, 1e-12);
  for (double v : r.pairwise[2]) EXPECT_NEAR(v, 1.0, 1e-12);
}

TEST(StudyDriver, RefusesReversedLevelsAndProblemsWithoutExactSolution) {
  int meshes = 0;
  const MeshAtLevel mesh = [&](int, const Progress&) {
    ++meshes;
    return StudyMesh{PolyMesh{}, 1.0};
  };
  const SolveOnMesh no_errors = [](const PolyMesh&, const Progress&) { return LevelSolve{}; };
  EXPECT_THROW(run_convergence_study("x", 5, 3, mesh, no_errors), InputError);
  EXPECT_EQ(meshes, 0);
  try {
    run_convergence_study("multi-material", 1, 2, mesh, no_errors);
    FAIL() << "no exact solution must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no exact solution"), std::string::npos);
  }
}

TEST(StudyReport, CsvHasOneRowPerLevelWithRatesFromTheSecond) {
  const std::vector<ConvergenceSeries> series{synthetic_series("staircase", 1.0, 1, 3),
                                              synthetic_series("cut, cell", 2.0, 1, 3)};
  const std::string csv = convergence_csv(series);
  std::istringstream in(csv);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 7u);
  EXPECT_EQ(lines[0], "series,level,h,cells,dofs,l2,linf,h1,rate_l2,rate_linf,rate_h1");
  EXPECT_EQ(lines[1], "staircase,1,0.5,0,100,0.5,1,1,,,");
  EXPECT_EQ(lines[2], "staircase,2,0.25,0,200,0.25,0.5,1,1,1,0");
  EXPECT_EQ(lines[6], "\"cut, cell\",3,0.125,0,300,0.015625,0.03125,0.125,2,2,1");
  EXPECT_EQ(csv, convergence_csv(series));
}

TEST(StudyReport, TableShowsEveryLevelAndTheSlopes) {
  const std::vector<ConvergenceSeries> series{synthetic_series("cutcell", 2.0, 3, 5)};
  std::ostringstream out;
  print_convergence_table(out, series);
  const std::string t = out.str();
  EXPECT_NE(t.find("cutcell\n"), std::string::npos);
  EXPECT_NE(t.find("1.562e-02"), std::string::npos);  // L2 at level 3: (1/8)^2
  EXPECT_NE(t.find("least-squares slope:  L2  2.00  Linf  2.00  H1  1.00"), std::string::npos)
      << t;
}

}  // namespace
}  // namespace volmesh::fem
