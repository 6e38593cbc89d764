#pragma once
// A scratch directory and a file reader for tests that write files (used by the surface I/O
// tests).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/temp_dir.hpp"

namespace volmesh::test {

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace volmesh::test
