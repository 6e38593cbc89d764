// Reading scalar grids: dispatch by extension, and the checks every reader shares.
#include <cmath>
#include <limits>

#include "volmesh/core/errors.hpp"
#include "volmesh/io/voxel_grid_io.hpp"
#include "voxel_samples.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace voxel {

void check_grid_dims(const std::array<Index, 3>& n, const fs::path& path,
                     const std::string& field) {
  if (n[0] < 2 || n[1] < 2 || n[2] < 2)
    fail(path, field + ": " + std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " +
                   std::to_string(n[2]) + " samples (a grid needs at least 2 along each axis)");
}

float checked_float(double value, const std::array<Index, 3>& dims, std::int64_t n,
                    const fs::path& path) {
  if (!(std::abs(value) <= std::numeric_limits<float>::max()))  // NaN too
    fail(path, "sample " + sample_position(dims, n) + ": value " + format_number(value) +
                   " is not finite (as a float)");
  return static_cast<float>(value);
}

VoxelGrid to_voxel_grid(const Samples& samples, const fs::path& path, const std::string& field) {
  VoxelGrid grid;
  const SampleLayout& l = samples.layout;
  grid.dims = l.index_dims();
  grid.origin = l.origin;
  grid.spacing = l.spacing;
  check_grid_dims(grid.dims, path, field);
  grid.values.resize(static_cast<std::size_t>(samples.count()));
  with_sample_type(l.type, [&](auto tag) {
    using T = decltype(tag);
    for (std::int64_t n = 0; n < samples.count(); ++n)
      grid.values[n] = checked_float(static_cast<double>(samples.at<T>(n)), grid.dims, n, path);
  });
  return grid;
}

}  // namespace voxel

VoxelGrid read_voxel_grid(const fs::path& path) {
  using voxel::has_suffix;
  if (has_suffix(path, ".rawiv")) return read_rawiv(path);
  if (has_suffix(path, ".vti")) return read_vti(path);
  if (has_suffix(path, ".nrrd")) return voxel::to_voxel_grid(voxel::read_nrrd(path), path, "sizes");
  throw InputError(path.string() + ": not a scalar grid (expected .rawiv, .vti or .nrrd)");
}

}  // namespace volmesh
