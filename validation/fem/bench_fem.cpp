// Poisson on the unit cube with u = sin(x+0.3)·sin(2y+0.1)·sin(3z+0.7) (Dirichlet data on
// every boundary tag): assembly rate, solve time, CG iterations, the whole call (with the
// error norms) in wall and CPU seconds, and the L2 error; one markdown table row on stdout.
//   bench_fem p1 N           N³ cubes split into 6 Kuhn tets each, P1
//   bench_fem q1 N           N³ hexes, Q1
//   bench_fem poly-grid N    N³ hexes, polyhedral space
//   bench_fem poly-octree N  octree checkerboard: N³ cubes, every other one split into 8
//                            (hanging faces on all sides of the others), polyhedral space
//   bench_fem cutcell L      cut-cell octree of builtin:ball, uniform depth L, polyhedral
//   bench_fem mesh FILE SPACE   any mesh volmesh reads (e.g. a cut-cell .vtu)
// Options after the case: --solver direct|cg (default: automatic, direct up to
// direct_limit unknowns), --elasticity (a linear displacement field, E = 1, ν = 0.3,
// instead of Poisson: three unknowns per node).
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <string>

#include "fem_test_meshes.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/fem/fem.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace {

using namespace volmesh;

fem::PoissonProblem sine_problem(const PolyMesh& mesh) {
  const auto u = [](const Vec3& x) {
    return std::sin(x.x() + 0.3) * std::sin(2.0 * x.y() + 0.1) * std::sin(3.0 * x.z() + 0.7);
  };
  fem::PoissonProblem p;
  for (Index r : regions_of(mesh)) p.conductivity[r] = 1.0;
  p.source = [u](const Vec3& x) { return 14.0 * u(x); };
  p.exact = u;
  for (const std::string& tag : mesh.tag_names)
    p.boundary[tag] = {fem::ScalarBoundaryCondition::Kind::dirichlet, u};
  return p;
}

// u = (0.1, -0.2, 0.05) + A x with a non-symmetric A: no body force, displacement data on
// every boundary tag.
fem::ElasticityProblem linear_elasticity(const PolyMesh& mesh) {
  Eigen::Matrix3d a;
  a << 0.2, -0.1, 0.3, 0.1, 0.4, -0.2, -0.3, 0.1, 0.2;
  const fem::VectorFunction u = [a](const Vec3& x) -> Vec3 {
    return Vec3(0.1, -0.2, 0.05) + a * x;
  };
  fem::ElasticityProblem p;
  for (Index r : regions_of(mesh)) p.material[r] = fem::IsotropicMaterial{};
  p.exact = u;
  for (const std::string& tag : mesh.tag_names)
    p.boundary[tag] = {fem::VectorBoundaryCondition::Kind::displacement, u};
  return p;
}

int run(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: bench_fem p1|q1|poly-grid|poly-octree|cutcell N [--solver direct|cg] "
                 "[--elasticity] | bench_fem mesh FILE SPACE [...]\n";
    return 2;
  }
  const std::string kind = argv[1];
  PolyMesh mesh;
  fem::Space space = fem::Space::polyhedral;
  std::string label;
  if (kind == "mesh") {
    if (argc < 4 || !fem::space_from_name(argv[3])) {
      std::cerr << "bench_fem mesh FILE p1|p2|q1|polyhedral\n";
      return 2;
    }
    mesh = read_mesh(argv[2]);
    space = *fem::space_from_name(argv[3]);
    label = argv[2];
  } else {
    const Index n = std::stoi(argv[2]);
    if (kind == "p1") {
      mesh = test::kuhn_cube(n);
      space = fem::Space::p1;
      label = "Kuhn tets " + std::to_string(n) + "³×6";
    } else if (kind == "q1") {
      mesh = test::hex_cube(n);
      space = fem::Space::q1;
      label = "hexes " + std::to_string(n) + "³";
    } else if (kind == "poly-grid") {
      mesh = test::hex_cube(n);
      label = "hexes " + std::to_string(n) + "³";
    } else if (kind == "cutcell") {
      CutcellOptions options;
      options.octree.level = options.octree.base_level = static_cast<int>(n);
      mesh = cutcell_mesh(*make_builtin_domain("ball"), options);
      label = "cut-cell ball, level " + std::to_string(n);
    } else if (kind == "poly-octree") {
      mesh = test::octree_checkerboard(n);
      label = "octree checkerboard " + std::to_string(n) + "³";
    } else {
      std::cerr << "bench_fem: unknown case '" << kind << "'\n";
      return 2;
    }
  }
  fem::LinearSolverOptions solver;
  bool elasticity = false;
  for (int i = kind == "mesh" ? 4 : 3; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--elasticity") {
      elasticity = true;
    } else if (arg == "--solver" && i + 1 < argc && std::string(argv[i + 1]) == "direct") {
      solver.kind = fem::LinearSolverOptions::Kind::direct, ++i;
    } else if (arg == "--solver" && i + 1 < argc && std::string(argv[i + 1]) == "cg") {
      solver.kind = fem::LinearSolverOptions::Kind::cg, ++i;
    } else {
      std::cerr << "bench_fem: unknown option '" << arg << "'\n";
      return 2;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  Index dofs = 0;
  fem::LinearSolveReport report;
  double l2 = 0.0;
  if (elasticity) {
    const fem::VectorSolution s =
        fem::solve_elasticity(mesh, linear_elasticity(mesh), space, solver);
    dofs = s.dofs, report = s.solve, l2 = s.errors->l2;
    label += ", elasticity";
  } else {
    const fem::ScalarSolution s = fem::solve_poisson(mesh, sine_problem(mesh), space, solver);
    dofs = s.dofs, report = s.solve, l2 = s.errors->l2;
  }
  const double cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("| %s | %s | %d | %d | %d | %.2f | %.3g | %.2f | %s | %d | %.1e | %.2f | %.2f | %.3e |\n",
              label.c_str(), fem::space_name(space), mesh.num_cells(), dofs, report.unknowns,
              report.assembly_seconds, mesh.num_cells() / report.assembly_seconds,
              report.solve_seconds, report.method.c_str(), report.iterations, report.residual,
              total, cpu, l2);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "bench_fem: " << e.what() << "\n";
    return 1;
  }
}
