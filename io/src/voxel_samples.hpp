#pragma once
// Samples on a regular axis-aligned grid as image files store them: what the header says
// plus the raw data bytes, decoded by the labelled-image and scalar-grid code on demand.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "volmesh/core/byte_order.hpp"
#include "volmesh/core/types.hpp"
#include "volmesh/core/voxel_grid.hpp"

namespace volmesh::voxel {

using byte_order::append;
using byte_order::load;

enum class SampleType { u8, i8, u16, i16, u32, i32, f32, f64 };

std::size_t sample_size(SampleType type);

// Calls f(T{}) with the C++ type T of the samples.
template <class F>
decltype(auto) with_sample_type(SampleType type, F&& f) {
  switch (type) {
    case SampleType::u8:
      return f(std::uint8_t{});
    case SampleType::i8:
      return f(std::int8_t{});
    case SampleType::u16:
      return f(std::uint16_t{});
    case SampleType::i16:
      return f(std::int16_t{});
    case SampleType::u32:
      return f(std::uint32_t{});
    case SampleType::i32:
      return f(std::int32_t{});
    case SampleType::f32:
      return f(float{});
    case SampleType::f64:
      break;
  }
  return f(double{});
}

struct SampleLayout {
  std::array<std::int64_t, 3> dims{};  // samples along x, y, z; x varies fastest in the data
  Vec3 spacing = Vec3::Ones();         // distance between neighbouring samples, > 0
  Vec3 origin = Vec3::Zero();          // position of sample (0, 0, 0)
  SampleType type = SampleType::u8;
  bool big_endian = false;

  // Valid once the reader has checked the sample count against the 32-bit index range.
  std::array<Index, 3> index_dims() const {
    return {static_cast<Index>(dims[0]), static_cast<Index>(dims[1]), static_cast<Index>(dims[2])};
  }
};

struct Samples {
  SampleLayout layout;
  std::string bytes;  // in the file's byte order

  std::int64_t count() const { return layout.dims[0] * layout.dims[1] * layout.dims[2]; }
  template <class T>
  T at(std::int64_t n) const {
    return load<T>(bytes.data() + n * static_cast<std::int64_t>(sizeof(T)), layout.big_endian);
  }
};

// Grids hold at most this many samples, so that voxel indices fit the 32-bit Index.
inline constexpr std::int64_t kMaxSamples = kMaxIndex;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what);

// Whether the file name ends in `suffix` (lower case), ignoring case.
bool has_suffix(const std::filesystem::path& path, std::string_view suffix);
// "(i, j, k)" for sample n of an x-fastest grid.
std::string sample_position(const std::array<Index, 3>& dims, std::int64_t n);

// Shortest text that reads back to the same double, independent of the locale.
std::string format_number(double x);

// Number of samples for `dims`, each >= 1 and their product <= kMaxSamples; otherwise an
// InputError naming the file and `field`. Checked before anything is allocated.
std::int64_t checked_count(const std::filesystem::path& path,
                           const std::array<std::int64_t, 3>& dims, const std::string& field);
// Spacing finite and > 0, origin finite; `fields` name the header fields of x, y, z.
using AxisFields = std::array<std::string, 3>;
AxisFields axis_fields(const std::string& field);  // "field x", "field y", "field z"
void check_spacing(const std::filesystem::path& path, const Vec3& spacing,
                   const AxisFields& fields);
void check_origin(const std::filesystem::path& path, const Vec3& origin, const AxisFields& fields);

// Image files. `.gz` after `.inr` means the whole file is gzipped; NRRD is written with gzip
// encoding. Writers replace the file atomically.
Samples read_inr(const std::filesystem::path& path);
Samples read_nrrd(const std::filesystem::path& path);
void write_inr(const Samples& samples, const std::filesystem::path& path);
void write_nrrd(const Samples& samples, const std::filesystem::path& path);

// Scalar grids (sdf_grid_io.cpp). A grid needs at least 2 samples per axis (`field` names the
// header's dims for the message); values are stored as float and must be finite there.
void check_grid_dims(const std::array<Index, 3>& dims, const std::filesystem::path& path,
                     const std::string& field);
float checked_float(double value, const std::array<Index, 3>& dims, std::int64_t n,
                    const std::filesystem::path& path);
VoxelGrid to_voxel_grid(const Samples& samples, const std::filesystem::path& path,
                        const std::string& field);

}  // namespace volmesh::voxel
