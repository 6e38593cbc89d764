#include "voxel_output.hpp"

#include <zlib.h>

#include <fstream>
#include <stdexcept>

#include "atomic_output.hpp"
#include "voxel_samples.hpp"

namespace volmesh::voxel {

namespace fs = std::filesystem;

std::string gzip(std::string_view data) {
  z_stream z{};
  // windowBits 15 + 16: a gzip wrapper (with a zero time stamp, so output is reproducible).
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("zlib: deflateInit2 failed");
  std::string out;
  constexpr std::size_t kStep = 1u << 30;  // zlib counts in 32-bit unsigned
  std::size_t in_done = 0;
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    const std::size_t in_now = std::min(data.size() - in_done, kStep);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + in_done));
    z.avail_in = static_cast<uInt>(in_now);
    const int flush = in_done + in_now == data.size() ? Z_FINISH : Z_NO_FLUSH;
    do {
      const std::size_t old = out.size();
      out.resize(old + (1u << 20));
      z.next_out = reinterpret_cast<Bytef*>(out.data() + old);
      z.avail_out = 1u << 20;
      status = deflate(&z, flush);
      if (status == Z_STREAM_ERROR) throw std::runtime_error("zlib: deflate failed");
      out.resize(out.size() - z.avail_out);
    } while (z.avail_out == 0 || (flush == Z_FINISH && status != Z_STREAM_END));
    in_done += in_now;
  }
  deflateEnd(&z);
  return out;
}

void write_atomically(const fs::path& path, std::initializer_list<std::string_view> parts) {
  AtomicOutput output(path);
  std::ofstream out = output.open_stream();
  for (std::string_view part : parts)
    out.write(part.data(), static_cast<std::streamsize>(part.size()));
  out.close();
  if (!out) fail(path, "write error");
  output.commit();
}

}  // namespace volmesh::voxel
