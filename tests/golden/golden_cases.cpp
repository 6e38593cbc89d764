#include "golden_cases.hpp"

#include <cstdint>
#include <utility>

#include "volmesh/io/open_domain.hpp"
#include "volmesh/fem/fem.hpp"
#include "volmesh/fem/problems.hpp"
#include "volmesh/meshers/registry.hpp"

namespace volmesh::golden {

// Levels chosen so that each case meshes (and solves) in well under a second in a Release
// build: the golden tests run in `make test`.
const std::vector<GoldenCase>& golden_cases() {
  static const std::vector<GoldenCase> cases{
      {"cutcell-ball-4", "cutcell", "builtin:ball", 4, {}, ""},
      {"cutcell-ball-midpoint-4", "cutcell", "builtin:ball", 4, {{"interface-points", std::string("midpoint")}}, ""},
      {"cutcell-primitives-3", "cutcell", "builtin:primitives", 3, {}, ""},
      {"cutcell-layers6-3", "cutcell", "builtin:layers6", 3, {}, ""},
      {"cutcell-tetra-4", "cutcell", "data:surfaces/tetra_ascii.ply", 4, {}, ""},
      {"staircase-ball-5", "staircase", "builtin:ball", 5, {}, ""},
      {"staircase-ball-uniform-4", "staircase", "builtin:ball", 4, {{"base-level", std::int64_t{4}}}, ""},
      {"staircase-primitives-4", "staircase", "builtin:primitives", 4, {}, ""},
      {"staircase-layers6-4", "staircase", "builtin:layers6", 4, {}, ""},
      {"staircase-tetra-5", "staircase", "data:surfaces/tetra_ascii.ply", 5, {}, ""},
      {"cutcell-elephant-4", "cutcell", "cgal:meshes/elephant.off", 4, {}, ""},
      {"staircase-elephant-5", "staircase", "cgal:meshes/elephant.off", 5, {}, ""},
      {"cutcell-ball-3-sine", "cutcell", "builtin:ball", 3, {}, "sine"},
      {"staircase-ball-4-sine", "staircase", "builtin:ball", 4, {}, "sine"},
      {"hexdc-ball-4", "hexdc", "builtin:ball", 4, {}, ""},
      {"hexdc-cube-3", "hexdc", "data:domains/inner_cube.off", 3, {}, ""},
      {"hexdc-torus-4", "hexdc", "data:domains/torus.json", 4, {}, ""},
      {"hexdc-ball-3-refined", "hexdc", "builtin:ball", 3, {{"refine-boundary", std::int64_t{1}}}, ""},
      {"hexdc-ball-3-sine", "hexdc", "builtin:ball", 3, {}, "sine"},
  };
  return cases;
}

std::string case_domain_spec(const GoldenCase& c) {
  for (const auto& [prefix, dir] : {std::pair<std::string, std::string>{"data:", VOLMESH_TEST_DATA},
                                    {"cgal:", VOLMESH_CGAL_DATA}})
    if (c.domain.starts_with(prefix)) return dir + "/" + c.domain.substr(prefix.size());
  return c.domain;
}

std::unique_ptr<Domain> open_case_domain(const GoldenCase& c) { return open_domain(case_domain_spec(c)); }

PolyMesh mesh_case(const GoldenCase& c, const Domain& domain) {
  meshers::MeshRequest request;
  request.domain_name = c.domain;
  request.level = c.level;
  request.options = c.options;
  return meshers::mesh(meshers::find_mesher(c.method), domain, request).mesh;
}

std::string case_space(const GoldenCase& c) {
  return meshers::find_mesher(c.method).default_space;
}

fem::ScalarSolution solve_case(const GoldenCase& c, const Domain& domain, const PolyMesh& mesh) {
  const fem::PoissonProblem problem = fem::make_poisson_problem(c.problem, domain, mesh.tag_names);
  return fem::solve_poisson(mesh, problem, *fem::space_from_name(case_space(c)));
}

}  // namespace volmesh::golden
