#pragma once
// Meshes, scratch directories and the third-party tools (meshio, gmsh) the partition tests use.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "../support/shell.hpp"
#include "../support/temp_dir.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"

namespace volmesh::test {

// n0 × n1 × n2 hexes filling [0, n0/n] × ... with n = max(n0, n1, n2): unit edges scaled.
inline PolyMesh hex_grid(Index n0, Index n1, Index n2) {
  const double h = 1.0 / std::max({n0, n1, n2});
  return to_poly_mesh(
      structured_hex_mesh(Vec3::Zero(), Vec3(n0 * h, n1 * h, n2 * h), {n0, n1, n2}));
}

// Fails the test with a hint when the tool is missing (`make test` installs both).
inline bool have_meshio() {
  std::string output;
  if (run("/usr/bin/python3 -c 'import meshio'", &output, true) == 0) return true;
  ADD_FAILURE() << "/usr/bin/python3 cannot import meshio (`make test` installs python3-meshio)";
  return false;
}
inline bool have_gmsh() {
  if (std::filesystem::exists("/usr/bin/gmsh")) return true;
  ADD_FAILURE() << "/usr/bin/gmsh is missing (`make test` installs gmsh)";
  return false;
}

// tests/partition/<script> with Debian's python, which has meshio.
inline std::string script(const std::string& name) {
  return "/usr/bin/python3 '" + (std::filesystem::path(VOLMESH_TEST_SOURCE) / "partition" / name).string() +
         "'";
}

}  // namespace volmesh::test
