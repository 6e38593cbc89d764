// Labelled images from and to files: sample values become labels through a small palette,
// so that a voxel costs two bytes whatever the file's sample type.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <unordered_set>
#include <utility>

#include "volmesh/core/errors.hpp"
#include "volmesh/io/label_image_io.hpp"
#include "voxel_samples.hpp"

namespace volmesh {

namespace fs = std::filesystem;
using namespace voxel;

namespace {

constexpr std::size_t kMaxLabels = 65536;  // codes are 16-bit

[[noreturn]] void not_a_label(const LabelImage& image, std::int64_t n, double value,
                              const std::string& source) {
  throw InputError(source + ": " + "voxel " + sample_position(image.dims, n) + ": value " +
                   format_number(value) + " is not a label (labels are integers >= 0)");
}

[[noreturn]] void too_many_labels(const std::string& source) {
  throw InputError(source + ": more than " + std::to_string(kMaxLabels) +
                   " distinct labels (is this a labelled image?)");
}

void set_labels(LabelImage& image, std::vector<Index> labels, const std::string& source) {
  if (labels.empty() || labels.front() != 0)
    labels.insert(labels.begin(), 0);  // 0, the outside, is code 0
  if (labels.size() > kMaxLabels) too_many_labels(source);
  image.labels = std::move(labels);
}

// Fills image.labels and image.codes from get(n), the value of voxel n, in two passes: the
// distinct values, then the codes. 8- and 16-bit samples go through a table indexed by the
// value; wider ones compare with the previous voxel first, labels being spatially coherent.
template <class T, class Get>
void encode(LabelImage& image, std::int64_t count, Get get, const std::string& source) {
  image.codes.resize(static_cast<std::size_t>(count));
  if constexpr (std::is_integral_v<T> && sizeof(T) <= 2) {
    using U = std::make_unsigned_t<T>;
    std::vector<std::int64_t> first(std::size_t{1} << (8 * sizeof(T)),
                                    -1);  // first voxel of each value
    for (std::int64_t n = 0; n < count; ++n) {
      std::int64_t& f = first[static_cast<U>(get(n))];
      if (f < 0) f = n;
    }
    std::vector<Index> labels;
    std::int64_t bad = -1;
    for (T v = std::numeric_limits<T>::min();; ++v) {  // ascending values
      if (const std::int64_t f = first[static_cast<U>(v)]; f >= 0) {
        if (std::cmp_less(v, 0) && (bad < 0 || f < bad)) bad = f;
        if (std::cmp_greater_equal(v, 0)) labels.push_back(static_cast<Index>(v));
      }
      if (v == std::numeric_limits<T>::max()) break;
    }
    if (bad >= 0) not_a_label(image, bad, static_cast<double>(get(bad)), source);
    set_labels(image, std::move(labels), source);
    std::vector<std::uint16_t> table(first.size(), 0);
    for (std::size_t c = 0; c < image.labels.size(); ++c)
      table[static_cast<U>(static_cast<T>(image.labels[c]))] = static_cast<std::uint16_t>(c);
    for (std::int64_t n = 0; n < count; ++n) image.codes[n] = table[static_cast<U>(get(n))];
  } else {
    std::unordered_set<T> seen;
    T last{};
    for (std::int64_t n = 0; n < count; ++n) {
      const T v = get(n);
      if ((n > 0 && v == last) || !seen.insert(v).second) {
        last = v;
        continue;
      }
      last = v;
      const double x = static_cast<double>(v);
      if (!(x >= 0.0 && x <= static_cast<double>(kMaxIndex) && x == std::floor(x)))
        not_a_label(image, n, x, source);
      if (seen.size() > kMaxLabels) too_many_labels(source);
    }
    std::vector<Index> labels(seen.begin(), seen.end());
    std::sort(labels.begin(), labels.end());
    set_labels(image, std::move(labels), source);
    std::uint16_t code = 0;
    for (std::int64_t n = 0; n < count; ++n) {
      const T v = get(n);
      if (static_cast<T>(image.labels[code]) != v)
        code = static_cast<std::uint16_t>(
            std::lower_bound(image.labels.begin(), image.labels.end(), static_cast<Index>(v)) -
            image.labels.begin());
      image.codes[n] = code;
    }
  }
}

LabelImage from_samples(const Samples& samples, const fs::path& path) {
  LabelImage image;
  const SampleLayout& l = samples.layout;
  image.dims = l.index_dims();
  image.spacing = l.spacing;
  image.origin = l.origin;
  with_sample_type(l.type, [&](auto tag) {
    using T = decltype(tag);
    encode<T>(
        image, samples.count(), [&](std::int64_t n) { return samples.at<T>(n); }, path.string());
  });
  return image;
}

template <class T>
void append_labels(const LabelImage& image, std::string& bytes) {
  bytes.reserve(image.codes.size() * sizeof(T));
  for (std::uint16_t code : image.codes)
    append<T>(bytes, static_cast<T>(image.labels[code]), false);
}

enum class Format { inr, nrrd };

Format image_format(const fs::path& path) {
  if (has_suffix(path, ".inr") || has_suffix(path, ".inr.gz")) return Format::inr;
  if (has_suffix(path, ".nrrd")) return Format::nrrd;
  throw InputError(path.string() + ": not a labelled image (expected .inr, .inr.gz or .nrrd)");
}

}  // namespace

LabelImage make_label_image(const std::array<Index, 3>& dims, const Vec3& spacing,
                            const Vec3& origin, std::span<const Index> voxel_labels) {
  const std::string source = "label image";
  const std::int64_t count = checked_count(source, {dims[0], dims[1], dims[2]}, "dims");
  check_spacing(source, spacing, axis_fields("spacing"));
  check_origin(source, origin, axis_fields("origin"));
  if (static_cast<std::int64_t>(voxel_labels.size()) != count)
    throw InputError(source + ": " + std::to_string(voxel_labels.size()) + " labels for " +
                     std::to_string(count) + " voxels");
  LabelImage image;
  image.dims = dims;
  image.spacing = spacing;
  image.origin = origin;
  encode<Index>(
      image, count, [&](std::int64_t n) { return voxel_labels[n]; }, source);
  return image;
}

LabelImage read_label_image(const fs::path& path) {
  return from_samples(image_format(path) == Format::inr ? read_inr(path) : read_nrrd(path), path);
}

void write_label_image(const LabelImage& image, const fs::path& path) {
  const Format format = image_format(path);
  Samples samples;
  samples.layout.dims = {image.dims[0], image.dims[1], image.dims[2]};
  samples.layout.spacing = image.spacing;
  samples.layout.origin = image.origin;
  const Index top = image.labels.empty() ? 0 : image.labels.back();
  samples.layout.type = top <= 0xff     ? SampleType::u8
                        : top <= 0xffff ? SampleType::u16
                                        : SampleType::i32;
  with_sample_type(samples.layout.type,
                   [&](auto tag) { append_labels<decltype(tag)>(image, samples.bytes); });
  if (format == Format::inr)
    write_inr(samples, path);
  else
    write_nrrd(samples, path);
}

}  // namespace volmesh
