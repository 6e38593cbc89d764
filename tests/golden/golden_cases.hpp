#pragma once
// The golden regression cases: small meshes of every mesher and one Poisson solve per
// mesher, each summarised (golden_summary.hpp) and compared with the summary stored in
// tests/golden/expected/<name>.json. regenerate.sh rewrites the stored summaries on purpose.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/fem/solution.hpp"
#include "volmesh/meshers/options.hpp"

namespace volmesh::golden {

struct GoldenCase {
  std::string name;    // the stored summary's file name, without .json
  std::string method;  // a mesher of the registry (volmesh/meshers/registry.hpp)
  // open_domain's argument; "data:" stands for the tests' data directory (tests/data) and
  // "cgal:" for libcgal-demo's unpacked data (make test installs it), so that the stored
  // summary names no absolute path.
  std::string domain;
  // The fields below are empty unless a case gives them.
  // --level for a level method, --size for a size method, neither for a method that meshes
  // the domain's surfaces as given (meshers::Resolution).
  std::optional<int> level = {};
  std::optional<double> size = {};
  meshers::MethodOptions options = {};  // by their command-line names, without "--"
  std::string problem = {};  // a Poisson problem of the library solved on the mesh, or empty
};

// Every case, in one table.
const std::vector<GoldenCase>& golden_cases();

// The case's domain argument with "data:" and "cgal:" resolved, and the domain it opens.
std::string case_domain_spec(const GoldenCase& c);
std::unique_ptr<Domain> open_case_domain(const GoldenCase& c);

// The case's mesh, from the mesher registry as `volmesh mesh` meshes. Throws InputError for
// a method or an option it does not know.
PolyMesh mesh_case(const GoldenCase& c, const Domain& domain);

// The space `volmesh solve` picks for the case's method: polyhedral on octree cells, Q1 on
// hexdc's hexes.
std::string case_space(const GoldenCase& c);

// The case's problem solved on the mesh in case_space.
fem::ScalarSolution solve_case(const GoldenCase& c, const Domain& domain, const PolyMesh& mesh);

}  // namespace volmesh::golden
