#pragma once
// What meshio reads from a mesh file, as printed by tests/io/external/meshio_counts.py.
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "volume_mesh_fixtures.hpp"

namespace volmesh::test {

// "cells hexahedron" -> 8, "ref quad 7" -> 4, "cellset region_1" -> 4, "minvolume tetra" ->
// 0.0026, ... (the script documents every key). Empty, with a test failure, when meshio is
// missing.
inline std::map<std::string, double> meshio_counts(const std::filesystem::path& path) {
  std::istringstream lines(run_meshio_script("meshio_counts.py", "'" + path.string() + "'"));
  std::map<std::string, double> counts;
  for (std::string line; std::getline(lines, line);) {
    const auto space = line.rfind(' ');
    if (space != std::string::npos)
      counts[line.substr(0, space)] = std::stod(line.substr(space + 1));
  }
  return counts;
}

}  // namespace volmesh::test
