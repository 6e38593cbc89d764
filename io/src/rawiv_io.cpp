// .rawiv reading and writing (format in voxel_grid_io.hpp).
#include <cmath>
#include <string>

#include "volmesh/io/voxel_grid_io.hpp"
#include "voxel_output.hpp"
#include "voxel_samples.hpp"
#include "voxel_stream.hpp"

namespace volmesh {

namespace fs = std::filesystem;
using namespace voxel;

namespace {

constexpr std::size_t kHeaderBytes = 68;

}  // namespace

VoxelGrid read_rawiv(const fs::path& path) {
  ByteSource source(path, 0, false);
  std::string header(kHeaderBytes, '\0');
  if (const std::size_t got = source.read(header.data(), kHeaderBytes); got < kHeaderBytes)
    fail(path, "header truncated: " + std::to_string(got) + " of " + std::to_string(kHeaderBytes) +
                   " bytes");
  const auto f32 = [&](int word) {
    return static_cast<double>(load<float>(header.data() + 4 * word, true));
  };
  const auto u32 = [&](int word) {
    return static_cast<std::int64_t>(load<std::uint32_t>(header.data() + 4 * word, true));
  };

  for (int w = 0; w < 6; ++w)
    if (!std::isfinite(f32(w)))
      fail(path, std::string(w < 3 ? "min" : "max") + "XYZ"[w % 3] + ": not finite");
  Samples samples;
  SampleLayout& l = samples.layout;
  l.dims = {u32(8), u32(9), u32(10)};
  checked_count(path, l.dims, "dimX/dimY/dimZ");
  l.origin = {f32(11), f32(12), f32(13)};
  check_origin(path, l.origin, {"originX", "originY", "originZ"});
  l.spacing = {f32(14), f32(15), f32(16)};
  check_spacing(path, l.spacing, {"spanX", "spanY", "spanZ"});
  l.type = SampleType::f32;
  l.big_endian = true;
  if (u32(6) != samples.count())
    fail(path, "numVerts: " + std::to_string(u32(6)) +
                   ", but dimX * dimY * dimZ = " + std::to_string(samples.count()));
  const std::int64_t cells = (l.dims[0] - 1) * (l.dims[1] - 1) * (l.dims[2] - 1);
  if (u32(7) != cells)
    fail(path, "numCells: " + std::to_string(u32(7)) +
                   ", but (dimX-1) * (dimY-1) * (dimZ-1) = " + std::to_string(cells));
  samples.bytes =
      read_exact(source, 4 * static_cast<std::uint64_t>(samples.count()), "4 x dimX x dimY x dimZ");
  return to_voxel_grid(samples, path, "dimX/dimY/dimZ");
}

void write_rawiv(const VoxelGrid& grid, const fs::path& path) {
  const std::int64_t count = static_cast<std::int64_t>(grid.dims[0]) * grid.dims[1] * grid.dims[2];
  if (grid.dims[0] < 2 || grid.dims[1] < 2 || grid.dims[2] < 2 || count > kMaxSamples ||
      static_cast<std::int64_t>(grid.values.size()) != count)
    fail(path, "cannot write an inconsistent grid (dims and values disagree)");
  std::string bytes;
  bytes.reserve(kHeaderBytes + 4 * grid.values.size());
  const auto f32 = [&](double x) { append<float>(bytes, static_cast<float>(x), true); };
  const auto u32 = [&](std::int64_t x) {
    append<std::uint32_t>(bytes, static_cast<std::uint32_t>(x), true);
  };
  const Vec3 far = grid.point(grid.dims[0] - 1, grid.dims[1] - 1, grid.dims[2] - 1);
  for (int a = 0; a < 3; ++a) f32(grid.origin[a]);
  for (int a = 0; a < 3; ++a) f32(far[a]);
  u32(count);
  u32(static_cast<std::int64_t>(grid.dims[0] - 1) * (grid.dims[1] - 1) * (grid.dims[2] - 1));
  for (int a = 0; a < 3; ++a) u32(grid.dims[a]);
  for (int a = 0; a < 3; ++a) f32(grid.origin[a]);
  for (int a = 0; a < 3; ++a) f32(grid.spacing[a]);
  for (float v : grid.values) append<float>(bytes, v, true);
  write_atomically(path, {bytes});
}

}  // namespace volmesh
