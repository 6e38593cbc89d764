#pragma once
// Reading image data from a byte offset of a file, raw or gzipped, without ever allocating
// what a header merely claims.
#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace volmesh::voxel {

class ByteSource {
 public:
  // Throws InputError if the file cannot be opened.
  ByteSource(std::filesystem::path path, std::uint64_t offset, bool gzip);
  ~ByteSource();
  ByteSource(const ByteSource&) = delete;
  ByteSource& operator=(const ByteSource&) = delete;

  // Reads up to n bytes; fewer only at the end of the data. Throws InputError on a read or
  // decompression error.
  std::size_t read(char* out, std::size_t n);
  // Bytes left in a raw file; unknown for gzip until decompressed.
  std::optional<std::uint64_t> raw_remaining() const;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  gzFile gz_ = nullptr;
  std::uint64_t remaining_ = 0;
};

// The rest of the source, which must be exactly `count` bytes (after `prefix`, bytes already
// read past a header): a shorter source is "truncated", a longer one has trailing data;
// both are InputErrors naming the file and the data's expected size (from `what`, e.g.
// "the header's dims x type size"). The buffer grows only as data arrives.
std::string read_exact(ByteSource& source, std::uint64_t count, const std::string& what,
                       std::string prefix = {});

}  // namespace volmesh::voxel
