#pragma once
// Convergence studies (docs/verification.md, "Solver convergence"): one problem solved on a
// sequence of meshes, the errors per level and the observed orders — pairwise rates between
// consecutive levels and the least-squares slope of log(error) against log(h) over all levels.
//
// The driver takes the mesher and the solver as functions, so that it serves every method
// (octree, cut cells, grids) and every space without depending on them.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/fem/solution.hpp"

namespace volmesh::fem {

// log(e_i / e_{i+1}) / log(h_i / h_{i+1}) for each consecutive pair (n - 1 values); NaN where
// a value of the pair is not positive and finite or h does not change.
std::vector<double> pairwise_rates(std::span<const double> h, std::span<const double> error);
// Least-squares slope of log(error) against log(h) over the points where both are positive
// and finite; NaN with fewer than two such points or a single distinct h.
double least_squares_slope(std::span<const double> h, std::span<const double> error);

enum class Norm { l2, linf, h1 };
inline constexpr std::array<Norm, 3> kNorms{Norm::l2, Norm::linf, Norm::h1};
const char* norm_name(Norm norm);  // "L2", "Linf", "H1"
double norm_value(const ErrorNorms& errors, Norm norm);

struct LevelResult {
  int level = 0;
  double h = 0.0;  // the mesh size the rates are taken against
  Index cells = 0;
  Index dofs = 0;
  ErrorNorms errors;
  LinearSolveReport solve;  // with the solve's stage times
  double mesh_seconds = 0.0;
  double seconds = 0.0;  // the level's whole run: the mesh, then the solve's stages
};

struct ConvergenceSeries {
  std::string label;  // e.g. "staircase (polyhedral)"
  std::vector<LevelResult> levels;
};

struct SeriesRates {
  std::array<std::vector<double>, 3> pairwise;  // per norm (kNorms order), n - 1 values
  std::array<double, 3> slope{};                // per norm
};
SeriesRates convergence_rates(const ConvergenceSeries& series);

// What the driver asks for at each level.
struct StudyMesh {
  PolyMesh mesh;
  double h = 0.0;
  // The cells over all ranks when `mesh` is this rank's piece of the level's mesh; -1: the
  // mesh's own.
  std::int64_t cells = -1;
};
struct LevelSolve {
  Index dofs = 0;
  LinearSolveReport solve;
  std::optional<ErrorNorms> errors;
};
// Each reports its own stages to the Progress it is given.
using MeshAtLevel = std::function<StudyMesh(int level, const Progress& progress)>;
using SolveOnMesh = std::function<LevelSolve(const PolyMesh& mesh, const Progress& progress)>;

// Meshes and solves levels first..last in order, keeping only the figures (each mesh is
// dropped before the next level is made). `progress` gets the mesher's and the solver's
// stages as "level N: meshing: <stage>" and "level N: solving C cells: <stage>", with the
// fraction of the levels done. Throws InputError when first > last or a solve reports no
// errors (the problem has no exact solution to measure against).
ConvergenceSeries run_convergence_study(const std::string& label, int first_level,
                                        int last_level, const MeshAtLevel& mesh_at_level,
                                        const SolveOnMesh& solve_on_mesh,
                                        const Progress& progress = {});

// One row per series and level: series,level,h,cells,dofs,l2,linf,h1,rate_l2,rate_linf,rate_h1
// (rates against the previous level, empty on a series' first row). No timings: the same
// study gives the same bytes.
std::string convergence_csv(std::span<const ConvergenceSeries> series);
// The table per series (level, h, cells, DOFs, each norm with its pairwise rate) and the
// least-squares slopes, as text for a terminal.
void print_convergence_table(std::ostream& out, std::span<const ConvergenceSeries> series);

}  // namespace volmesh::fem
