#pragma once
// Runs the volmesh binary and captures its exit code, stdout and stderr.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

namespace volmesh::test {

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A shell command line, its stdout and stderr captured through files in `scratch`.
inline RunResult run_captured(const std::string& command, const std::filesystem::path& scratch) {
  const auto out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  const std::string cmd = command + " >" + out.string() + " 2>" + err.string() + " </dev/null";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// `args` is appended to the binary's path as shell words (callers quote what needs it).
inline RunResult run_volmesh(const std::string& args, const std::filesystem::path& scratch) {
  return run_captured(std::string(VOLMESH_BINARY) + " " + args, scratch);
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

// A test's scratch directory under the system temp dir, named after the test and the build
// (the binary's path), so that builds tested at the same time on one machine keep apart.
inline std::filesystem::path scratch_path(const std::string& name) {
  const std::size_t build = std::hash<std::string>{}(VOLMESH_BINARY) % 0x100000000u;
  return std::filesystem::temp_directory_path() / ("volmesh-test-" + std::to_string(build) + "-" + name);
}

// A fresh scratch directory per test.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = scratch_path(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace volmesh::test
