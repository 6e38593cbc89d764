#pragma once
// Meshes, scratch directories and the third-party tools (meshio, gmsh) the partition tests use.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"

namespace volmesh::test {

// n0 × n1 × n2 hexes filling [0, n0/n] × ... with n = max(n0, n1, n2): unit edges scaled.
inline PolyMesh hex_grid(Index n0, Index n1, Index n2) {
  const double h = 1.0 / std::max({n0, n1, n2});
  return to_poly_mesh(
      structured_hex_mesh(Vec3::Zero(), Vec3(n0 * h, n1 * h, n2 * h), {n0, n1, n2}));
}

// A fresh directory named after the running test, removed at the end.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("volmesh_partition_" + std::string(info->test_suite_name()) + "_" + info->name() +
             "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

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
  return "/usr/bin/python3 '" + (std::filesystem::path(__FILE__).parent_path() / name).string() +
         "'";
}

}  // namespace volmesh::test
