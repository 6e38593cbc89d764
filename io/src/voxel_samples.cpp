#include "voxel_samples.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "text_format.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh::voxel {

std::size_t sample_size(SampleType type) {
  return with_sample_type(type, [](auto tag) { return sizeof(tag); });
}

void fail(const std::filesystem::path& path, const std::string& what) {
  throw InputError(path.string() + ": " + what);
}

bool has_suffix(const std::filesystem::path& path, std::string_view suffix) {
  const std::string name = path.filename().string();
  return name.size() > suffix.size() &&
         std::equal(suffix.rbegin(), suffix.rend(), name.rbegin(), [](char s, char c) {
           return s == std::tolower(static_cast<unsigned char>(c));
         });
}

std::string sample_position(const std::array<Index, 3>& dims, std::int64_t n) {
  return "(" + std::to_string(n % dims[0]) + ", " + std::to_string(n / dims[0] % dims[1]) + ", " +
         std::to_string(n / dims[0] / dims[1]) + ")";
}

std::string format_number(double x) {
  std::string text;
  append_number(text, x);
  return text;
}

std::int64_t checked_count(const std::filesystem::path& path,
                           const std::array<std::int64_t, 3>& dims, const std::string& field) {
  std::int64_t count = 1;
  for (std::int64_t n : dims) {
    if (n < 1)
      fail(path, field + ": " + std::to_string(n) + " samples along an axis (must be >= 1)");
    if (n > kMaxSamples / count)  // before multiplying, so that nothing overflows
      fail(path, field + ": " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " +
                     std::to_string(dims[2]) + " samples: more than " +
                     std::to_string(kMaxSamples) + " (32-bit voxel indices)");
    count *= n;
  }
  return count;
}

AxisFields axis_fields(const std::string& field) {
  return {field + " x", field + " y", field + " z"};
}

void check_spacing(const std::filesystem::path& path, const Vec3& spacing,
                   const AxisFields& fields) {
  for (int a = 0; a < 3; ++a)
    if (!(std::isfinite(spacing[a]) && spacing[a] > 0.0))
      fail(path,
           fields[a] + ": spacing " + format_number(spacing[a]) + " (must be finite and > 0)");
}

void check_origin(const std::filesystem::path& path, const Vec3& origin, const AxisFields& fields) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(origin[a]))
      fail(path, fields[a] + ": origin " + format_number(origin[a]) + " is not finite");
}

}  // namespace volmesh::voxel
