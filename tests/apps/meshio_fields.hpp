#pragma once
// What meshio (an independent reader) sees of the data arrays of a mesh file: counts,
// components and largest absolute values (external/meshio_fields.py).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace volmesh::test {

inline nlohmann::json meshio_fields(const std::filesystem::path& file) {
  const std::filesystem::path script =
      std::filesystem::path(VOLMESH_TEST_SOURCE) / "apps" / "external" / "meshio_fields.py";
  const std::string command = "/usr/bin/python3 '" + script.string() + "' '" + file.string() + "' 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return {};
  std::string output;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  const int status = ::pclose(pipe);
  if (status != 0) {
    ADD_FAILURE() << "meshio could not read " << file << " (`make test` installs python3-meshio): "
                  << output;
    return {};
  }
  // meshio may print warnings before the object.
  return nlohmann::json::parse(output.substr(output.rfind("\n{") + 1));
}

}  // namespace volmesh::test
