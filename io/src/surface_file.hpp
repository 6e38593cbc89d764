#pragma once
// Plumbing shared by the surface readers and writers: whole-file loading, one-line errors,
// the 32-bit index limit, fan triangulation of polygons and buffered atomic writing.
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "atomic_output.hpp"
#include "text_format.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/tri_surface.hpp"

namespace volmesh::surface_detail {

[[noreturn]] inline void fail(const std::filesystem::path& path, const std::string& what) {
  throw InputError(path.string() + ": " + what);
}

// The readers parse from memory; the file size then bounds every count a header claims.
inline std::string load_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a surface file");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) fail(path, "cannot open file");
  const std::streamoff size = in.tellg();
  if (size < 0) fail(path, "cannot determine the file size");
  if (size == 0) fail(path, "file is empty");
  std::string data(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(data.data(), size)) fail(path, "read error");
  return data;
}

// Refuses a count before anything is allocated for it.
inline Index checked_count(const std::filesystem::path& path, std::uint64_t count,
                           const char* what) {
  if (count > static_cast<std::uint64_t>(kMaxIndex))
    fail(path, "header: " + std::to_string(count) + " " + what +
                   " exceeds the 32-bit index limit (" + std::to_string(kMaxIndex) + ")");
  return static_cast<Index>(count);
}

// Splits a polygon into a fan around its first corner as its corners arrive. The result is
// right for convex (and star-shaped around that corner) polygons, which is what polygonal
// OFF/OBJ/PLY faces are in practice; check_surface catches the rest as degenerate or
// intersecting triangles.
class PolygonFan {
 public:
  PolygonFan(const std::filesystem::path& path, std::vector<std::array<Index, 3>>& triangles)
      : path_(path), triangles_(triangles) {}
  void start() { corners_ = 0; }
  void add(Index v) {
    if (corners_ == 0) {
      first_ = v;
    } else if (corners_ >= 2) {
      if (triangles_.size() >= static_cast<std::size_t>(kMaxIndex))
        fail(path_,
             "more triangles than the 32-bit index limit (" + std::to_string(kMaxIndex) + ")");
      triangles_.push_back({first_, last_, v});
    }
    last_ = v;
    ++corners_;
  }
  std::int64_t corners() const { return corners_; }

 private:
  const std::filesystem::path& path_;
  std::vector<std::array<Index, 3>>& triangles_;
  Index first_ = 0, last_ = 0;
  std::int64_t corners_ = 0;
};

// Collects output in memory and hands it to the stream in chunks of about 1 MiB.
class ChunkedWriter {
 public:
  explicit ChunkedWriter(std::ofstream& out) : out_(out) {}
  std::string& buffer() { return buffer_; }
  void flush_if_full() {
    if (buffer_.size() >= (std::size_t{1} << 20)) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  std::ofstream& out_;
  std::string buffer_;
};

// One line of a text writer: `prefix` (if any) and three numbers separated by spaces.
template <class Three>
void append_line(std::string& out, std::string_view prefix, const Three& values, int offset = 0) {
  out += prefix;
  for (int k = 0; k < 3; ++k) {
    if (k > 0 || !prefix.empty()) out += ' ';
    append_number(out, values[k] + offset);
  }
  out += '\n';
}

// Writes through a temporary file renamed at the end, so that a failure never leaves a
// partial file under `path`.
template <class Produce>
void write_atomically(const TriSurface& surface, const std::filesystem::path& path,
                      Produce produce) {
  require_valid_indices(surface, path.string());
  AtomicOutput output(path);
  std::ofstream out = output.open_stream();
  ChunkedWriter writer(out);
  produce(writer);
  writer.flush();
  out.close();
  if (!out) fail(path, "write error");
  output.commit();
}

}  // namespace volmesh::surface_detail
