#pragma once
// The meshers on the command line of `mesh`, `solve` and `study`, all taken from the
// registry: their names and descriptions, their options, and the refusal of an option the
// chosen method does not take.
#include <string>
#include <vector>

#include "volmesh/meshers/registry.hpp"

namespace CLI {
class App;
}

namespace volmesh::cli {

std::vector<std::string> mesher_names();

// "builtin:ball for cutcell, staircase; builtin:box for grid": where `solve` and `study`
// mesh when no domain is given.
std::string default_domains();

// "Methods:" and one line per method with its description, for a help footer.
std::string meshers_help();

// Every option some method declares, added once as --NAME with the methods that take it
// before its help ("cutcell: ..."); the values given land in `given`. `octree`: the shared
// octree options too.
void add_mesher_options(CLI::App& app, meshers::MethodOptions& given, bool octree);

// False, after "volmesh COMMAND: --tets applies to the grid method only" on stderr, when
// `given` holds an option `info` does not take (a usage error: exit 2).
bool options_apply(const std::string& command, const meshers::MesherInfo& info,
                   const meshers::MethodOptions& given);

}  // namespace volmesh::cli
