#pragma once
// The meshers by name: what `volmesh mesh`, `solve --method`, `study convergence --method`
// and the demo mesh with. Each entry says what a caller needs to know generically (its
// description, whether it meshes by level or size, the options it takes, its default domain
// and FE space) and meshes a Domain into a PolyMesh with the mesh size at the boundary and
// its own figures as JSON.
//
// A method is added in one place: a file mesh/meshers/src/<method>.cpp that defines its
// MeshFunction and registers its MesherInfo (registration.hpp), with the method's module
// linked in mesh/meshers/CMakeLists.txt; every subcommand finds it here at once.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/meshers/options.hpp"

namespace volmesh::meshers {

// How fine a method is told to mesh.
enum class Resolution {
  level,  // an octree depth at the boundaries and interfaces (--level, docs/architecture.md)
  size,   // a target edge length (--size)
  // The domain's own triangulated surfaces, as given: neither --level nor --size.
  surface,
};

struct MeshRequest {
  std::string domain_name;     // names the domain in messages ("builtin:ball", a file name)
  // Resolution::level; for a size method only in a uniform request (a study's or a solve's
  // level), meshed at h = the octree cell edge at that level (the root cube's side / 2^level),
  // so that the methods of a study are compared at the same h.
  std::optional<int> level;
  std::optional<double> size;  // Resolution::size only
  // The same depth inside as at the boundaries (an octree's base level = level), as a
  // convergence study needs: a coarser interior would limit the rate. Octree methods only.
  bool uniform = false;
  MethodOptions options;  // checked against the method's declarations
  Progress progress;      // the method's stages, from the calling thread
};

struct MeshResult {
  PolyMesh mesh;
  double h = 0.0;  // the cell edge at the boundaries, what convergence studies plot against
  // The mesh's "cells", "faces" and "vertices" and the method's own figures, as `volmesh
  // mesh --json` prints them.
  nlohmann::json summary = nlohmann::json::object();
};

using MeshFunction = MeshResult (*)(const Domain& domain, const MeshRequest& request);

struct MesherInfo {
  std::string name;         // "cutcell"
  std::string description;  // one line for `volmesh mesh --help`
  Resolution resolution = Resolution::level;
  // Takes the octree options every octree method shares (octree_options()).
  bool octree = false;
  std::vector<OptionSpec> options;  // its own, beyond the shared octree ones
  // What `solve` and `study` mesh when no domain is given.
  std::string default_domain = "builtin:ball";
  // The FE space its meshes are solved in by default ("polyhedral"); empty: chosen from the
  // cells (p1 on tetrahedra, q1 on hexahedra, polyhedral otherwise).
  std::string default_space;
  MeshFunction run = nullptr;
};

// --base-level and --cells-between-levels (OctreeOptions), taken by every octree method.
const std::vector<OptionSpec>& octree_options();

// Every option `info` takes: the shared octree ones if it is an octree method, then its own.
std::vector<OptionSpec> options_of(const MesherInfo& info);

// Every registered method, sorted by name.
const std::vector<MesherInfo>& meshers();

// "cutcell, grid, staircase".
std::string mesher_names();

// Throws InputError "unknown method NAME (known: cutcell, grid, staircase)".
const MesherInfo& find_mesher(std::string_view name);

// Throws InputError for an option `info` does not take ("--feature-angle applies to the
// cutcell method only"), or a value of the wrong type or out of range.
void check_options(const MesherInfo& info, const MethodOptions& options);

// Checks the request (its options; a level for a level method, a size for a size method; no
// --base-level when uniform), meshes, and adds the mesh's counts to the summary. Throws
// InputError for a bad request and for what the method refuses.
MeshResult mesh(const MesherInfo& info, const Domain& domain, const MeshRequest& request);

}  // namespace volmesh::meshers
