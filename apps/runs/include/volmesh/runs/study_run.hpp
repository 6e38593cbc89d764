#pragma once
// A convergence study as `study convergence` and `demo` run it: one series per method over a
// range of levels, and its outputs (convergence.csv, convergence.png, summary.json).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "volmesh/runs/solve_setup.hpp"
#include "volmesh/fem/study.hpp"
#include "volmesh/meshers/registry.hpp"
#include "volmesh/plot/loglog_png.hpp"

namespace volmesh::cli {

struct StudySpec {
  ProblemSpec problem;
  std::vector<std::string> methods;  // one series each
  std::string domain;                // empty: the first method's default domain
  std::string space;                 // empty: the method's default
  meshers::MethodOptions options;    // given to every method
  int first_level = 0, last_level = 0;
  SolverBackend solver = SolverBackend::automatic;
  std::string partition;  // --partition under mpirun (mesh_pieces.hpp); empty: the default
};

struct StudyOutcome {
  std::string problem, domain;
  std::vector<std::string> methods, spaces;  // per series
  std::vector<fem::ConvergenceSeries> series;
  double seconds = 0.0;
};

// "A..B" (or "N" for one level). Throws InputError for anything else or A > B.
std::pair<int, int> parse_levels(const std::string& text);

// Every method meshes in the uniform mode (the same depth inside as at the boundary). Throws
// InputError for an unknown method or an option one of them does not take.
StudyOutcome run_study(const StudySpec& spec, const Progress& progress);

// Error against h, one line per series and norm (colour per method when several, marker per
// norm), reference slopes 1 and 2.
plot::LogLogChart study_chart(const StudyOutcome& outcome);
nlohmann::json study_summary(const StudyOutcome& outcome);

// Writes dir/convergence.csv, dir/convergence.png and dir/summary.json, each through a
// temporary name; creates dir when missing.
void write_study_outputs(const std::filesystem::path& dir, const StudyOutcome& outcome);

}  // namespace volmesh::cli
