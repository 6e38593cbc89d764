#pragma once
// Running the third-party tools the tests check against (meshio, gmsh, OpenFOAM).
#include <sys/wait.h>

#include <cstdio>
#include <string>

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

}  // namespace volmesh::test
