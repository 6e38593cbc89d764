#include <chrono>

#include "volmesh/core/errors.hpp"
#include "volmesh/fem/study.hpp"

namespace volmesh::fem {

ConvergenceSeries run_convergence_study(const std::string& label, int first_level,
                                        int last_level, const MeshAtLevel& mesh_at_level,
                                        const SolveOnMesh& solve_on_mesh,
                                        const Progress& progress) {
  if (first_level > last_level)
    throw InputError("levels " + std::to_string(first_level) + ".." +
                     std::to_string(last_level) + ": the first level exceeds the last");
  ConvergenceSeries series{label, {}};
  for (int level = first_level; level <= last_level; ++level) {
    LevelResult r;
    r.level = level;
    // Each level has an equal share of the progress, its first half for the meshing.
    const std::string stage = "level " + std::to_string(level) + ": ";
    const double share = 1.0 / (last_level - first_level + 1);
    const double begin = (level - first_level) * share, meshed = begin + share / 2;
    const auto start = std::chrono::steady_clock::now();
    StudyMesh m = mesh_at_level(level, part_of(progress, begin, meshed, stage + "meshing: "));
    r.mesh_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.h = m.h;
    r.cells = m.cells >= 0 ? static_cast<Index>(m.cells) : m.mesh.num_cells();
    LevelSolve s = solve_on_mesh(m.mesh, part_of(progress, meshed, begin + share,
                                                 stage + "solving " + std::to_string(r.cells) +
                                                     " cells: "));
    if (!s.errors)
      throw InputError(label + ": level " + std::to_string(level) +
                       ": the problem has no exact solution to measure errors against");
    r.dofs = s.dofs;
    r.solve = s.solve;
    r.errors = *s.errors;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    series.levels.push_back(r);
  }
  return series;
}

}  // namespace volmesh::fem
