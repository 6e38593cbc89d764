#pragma once
// Running the third-party tools the tests check against (meshio, gmsh, OpenFOAM).
#include <sys/wait.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace volmesh::test {

// Runs a shell command; returns its exit status, with its stdout (and stderr when
// merge_stderr) in *output.
inline int run(const std::string& command, std::string* output, bool merge_stderr = false) {
  FILE* pipe = ::popen((command + (merge_stderr ? " 2>&1" : "")).c_str(), "r");
  if (pipe == nullptr) return -1;
  char buffer[4096];
  output->clear();
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    output->append(buffer, n);
  const int status = ::pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The JSON objects in a tool's output, one per line (other lines, such as warnings, are
// skipped), padded with empty objects to `count`.
inline std::vector<nlohmann::json> json_lines(const std::string& output, std::size_t count) {
  std::vector<nlohmann::json> objects;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with("{")) objects.push_back(nlohmann::json::parse(line));
  objects.resize(count, nlohmann::json::object());
  return objects;
}

}  // namespace volmesh::test
