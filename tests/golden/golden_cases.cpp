#include "golden_cases.hpp"

#include <cstdint>
#include <utility>

#include "volmesh/io/open_domain.hpp"
#include "volmesh/fem/fem.hpp"
#include "volmesh/fem/problems.hpp"
#include "volmesh/meshers/registry.hpp"

namespace volmesh::golden {

// Levels and sizes chosen so that each case meshes (and solves) in well under a second in a
// Release build: the golden tests run in `make test`.
const std::vector<GoldenCase>& golden_cases() {
  static const std::vector<GoldenCase> cases{
      {.name = "cutcell-ball-4", .method = "cutcell", .domain = "builtin:ball", .level = 4},
      {.name = "cutcell-ball-midpoint-4", .method = "cutcell", .domain = "builtin:ball", .level = 4,
       .options = {{"interface-points", std::string("midpoint")}}},
      {.name = "cutcell-primitives-3", .method = "cutcell", .domain = "builtin:primitives", .level = 3},
      {.name = "cutcell-layers6-3", .method = "cutcell", .domain = "builtin:layers6", .level = 3},
      {.name = "cutcell-tetra-4", .method = "cutcell", .domain = "data:surfaces/tetra_ascii.ply",
       .level = 4},
      {.name = "staircase-ball-5", .method = "staircase", .domain = "builtin:ball", .level = 5},
      {.name = "staircase-ball-uniform-4", .method = "staircase", .domain = "builtin:ball", .level = 4,
       .options = {{"base-level", std::int64_t{4}}}},
      {.name = "staircase-primitives-4", .method = "staircase", .domain = "builtin:primitives",
       .level = 4},
      {.name = "staircase-layers6-4", .method = "staircase", .domain = "builtin:layers6", .level = 4},
      {.name = "staircase-tetra-5", .method = "staircase", .domain = "data:surfaces/tetra_ascii.ply",
       .level = 5},
      {.name = "cutcell-elephant-4", .method = "cutcell", .domain = "cgal:meshes/elephant.off",
       .level = 4},
      {.name = "staircase-elephant-5", .method = "staircase", .domain = "cgal:meshes/elephant.off",
       .level = 5},
      {.name = "cutcell-ball-3-sine", .method = "cutcell", .domain = "builtin:ball", .level = 3,
       .problem = "sine"},
      {.name = "staircase-ball-4-sine", .method = "staircase", .domain = "builtin:ball", .level = 4,
       .problem = "sine"},
      {.name = "hexdc-ball-4", .method = "hexdc", .domain = "builtin:ball", .level = 4},
      {.name = "hexdc-cube-3", .method = "hexdc", .domain = "data:domains/inner_cube.off", .level = 3},
      {.name = "hexdc-torus-4", .method = "hexdc", .domain = "data:domains/torus.json", .level = 4},
      {.name = "hexdc-ball-3-refined", .method = "hexdc", .domain = "builtin:ball", .level = 3,
       .options = {{"refine-boundary", std::int64_t{1}}}},
      {.name = "hexdc-ball-3-sine", .method = "hexdc", .domain = "builtin:ball", .level = 3,
       .problem = "sine"},
      {.name = "grid-box-2", .method = "grid", .domain = "builtin:box", .level = 2},
      {.name = "grid-box-2-tets", .method = "grid", .domain = "builtin:box", .level = 2,
       .options = {{"tets", true}}},
      {.name = "tet-projection-schoenhardt", .method = "tet-projection",
       .domain = "builtin:schoenhardt"},
      // Rounding to doubles flattens a tet along every untilted axis: the mesh is made again
      // along the chosen axis tilted, the second direction tried (directions.hpp).
      {.name = "tet-projection-cube-inclusion", .method = "tet-projection",
       .domain = "builtin:cube-inclusion"},
      {.name = "tet-projection-nested", .method = "tet-projection",
       .domain = "data:domains/nested.json"},
      {.name = "tet-front-cube-inclusion-2", .method = "tet-front",
       .domain = "builtin:cube-inclusion", .size = 2.0},
      {.name = "tet-front-ball-0.4", .method = "tet-front", .domain = "builtin:ball", .size = 0.4},
      // The front stopped after 10 tets: the fallback closes the cavity by projection and
      // refines the tets around the faces it cuts.
      {.name = "tet-front-tripod-0.3-stalled", .method = "tet-front",
       .domain = "cgal:meshes/tripod.off", .size = 0.3,
       .options = {{"stop-after", std::int64_t{10}}}},
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
  request.size = c.size;
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
