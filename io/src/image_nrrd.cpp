// NRRD (teem's "nearly raw raster data"): a text header of "field: value" lines ended by a
// blank line, then the samples in the same file, raw or gzipped. Supported: 3 axes, sample
// types of 8 to 32 bits, float and double, axis-aligned positive 'space directions' (or
// 'spacings') and 'space origin'; the origin is the first sample's position.
#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "text_format.hpp"
#include "voxel_output.hpp"
#include "voxel_samples.hpp"
#include "voxel_stream.hpp"

namespace volmesh::voxel {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxHeader = std::size_t{1} << 20;

// Each sample type's NRRD spellings; the first is the one written.
const std::vector<std::pair<SampleType, std::vector<std::string>>>& type_names() {
  static const std::vector<std::pair<SampleType, std::vector<std::string>>> names = {
      {SampleType::i8, {"int8", "signed char", "int8_t"}},
      {SampleType::u8, {"uint8", "uchar", "unsigned char", "uint8_t"}},
      {SampleType::i16,
       {"int16", "short", "short int", "signed short", "signed short int", "int16_t"}},
      {SampleType::u16, {"uint16", "ushort", "unsigned short", "unsigned short int", "uint16_t"}},
      {SampleType::i32, {"int32", "int", "signed int", "int32_t"}},
      {SampleType::u32, {"uint32", "uint", "unsigned int", "uint32_t"}},
      {SampleType::f32, {"float"}},
      {SampleType::f64, {"double"}}};
  return names;
}

// The header's text (without the blank line) and the data's byte offset.
std::pair<std::string, std::uint64_t> read_header(const fs::path& path) {
  ByteSource source(path, 0, false);
  std::string text;
  while (text.size() < kMaxHeader) {
    const std::size_t old = text.size();
    text.resize(old + 4096);
    text.resize(old + source.read(text.data() + old, 4096));
    if (old == 0 && text.compare(0, 4, "NRRD") != 0)
      fail(path, "not a NRRD file (no 'NRRD' magic at the start)");
    for (std::string_view blank : {"\n\n", "\n\r\n"})
      if (std::size_t end = text.find(blank, old < 2 ? 0 : old - 2); end != std::string::npos)
        return {text.substr(0, end + 1), end + blank.size()};
    if (text.size() < old + 4096)
      fail(path, "header: the file ends before the blank line ending the header");
  }
  fail(path,
       "header: no blank line ending it in the first " + std::to_string(kMaxHeader) + " bytes");
}

class NrrdHeader {
 public:
  NrrdHeader(const fs::path& path, const std::string& text) : path_(path) {
    std::istringstream lines(text);
    std::string line;
    std::getline(lines, line);  // magic
    while (std::getline(lines, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty() || line.front() == '#') continue;
      const std::size_t colon = line.find(": ");
      if (colon == std::string::npos || line.find(":=") < colon) continue;  // key:=value pairs
      fields_[line.substr(0, colon)] = line.substr(colon + 2);
    }
  }

  SampleLayout layout() const {
    if (field("dimension") != "3")
      fail(path_, "dimension: " + field("dimension") + " (only 3 is supported)");
    for (const char* key : {"data file", "datafile"})
      if (has(key)) fail(path_, std::string(key) + ": detached data is not supported");
    for (const char* key : {"byte skip", "byteskip", "line skip", "lineskip"})
      if (has(key) && field(key) != "0")
        fail(path_, std::string(key) + ": " + field(key) + " (only 0 is supported)");
    SampleLayout layout;
    layout.dims = three<std::int64_t>("sizes");
    checked_count(path_, layout.dims, "sizes");
    layout.spacing = spacing();
    check_spacing(path_, layout.spacing,
                  axis_fields(has("space directions") ? "space directions" : "spacings"));
    if (has("space origin")) {
      const std::vector<double> origin = parse_vector("space origin", field("space origin"));
      layout.origin = {origin[0], origin[1], origin[2]};
      check_origin(path_, layout.origin, axis_fields("space origin"));
    }
    const auto& names = type_names();
    const auto type = std::find_if(names.begin(), names.end(), [&](const auto& entry) {
      return std::find(entry.second.begin(), entry.second.end(), field("type")) !=
             entry.second.end();
    });
    if (type == names.end()) fail(path_, "type: " + field("type") + ": unsupported sample type");
    layout.type = type->first;
    layout.big_endian = big_endian(sample_size(layout.type));
    return layout;
  }

  bool gzip() const {
    const std::string& encoding = field("encoding");
    if (encoding == "raw") return false;
    if (encoding == "gzip" || encoding == "gz") return true;
    fail(path_, "encoding: " + encoding + " (supported: raw, gzip)");
  }

 private:
  bool has(const std::string& key) const { return fields_.count(key) != 0; }

  const std::string& field(const std::string& key) const {
    auto it = fields_.find(key);
    if (it == fields_.end()) fail(path_, "header: field '" + key + "' missing");
    return it->second;
  }

  // Three numbers separated by blanks.
  template <class T>
  std::array<T, 3> three(const std::string& key) const {
    std::istringstream words(field(key));
    std::array<T, 3> values;
    std::string word;
    for (T& x : values)
      if (!(words >> word) || !parse_field(word, x))
        fail(path_, key + ": " + field(key) + ": expected 3 numbers");
    if (words >> word) fail(path_, key + ": " + field(key) + ": expected 3 numbers");
    return values;
  }

  // "(x,y,z)" with blanks allowed.
  std::vector<double> parse_vector(const std::string& key, std::string_view text) const {
    const std::size_t open = text.find('('), close = text.find(')');
    std::vector<double> values;
    if (open != std::string_view::npos && close != std::string_view::npos && open < close) {
      std::string_view inside = text.substr(open + 1, close - open - 1);
      while (true) {
        const std::size_t comma = inside.find(',');
        double x;
        if (!parse_field(inside.substr(0, comma), x)) break;
        values.push_back(x);
        if (comma == std::string_view::npos) break;
        inside.remove_prefix(comma + 1);
      }
    }
    if (values.size() != 3)
      fail(path_, key + ": '" + std::string(text) + "' is not a vector (x,y,z)");
    return values;
  }

  Vec3 spacing() const {
    Vec3 spacing = Vec3::Ones();
    if (has("space directions")) {
      std::string_view rest = field("space directions");
      for (int a = 0; a < 3; ++a) {
        const std::size_t close = rest.find(')');
        const std::string word(
            rest.substr(0, close == std::string_view::npos ? rest.size() : close + 1));
        rest.remove_prefix(word.size());
        const std::vector<double> v = parse_vector("space directions", word);
        for (int b = 0; b < 3; ++b)
          if (b != a && v[b] != 0.0)
            fail(path_, "space directions: " + word + " is not along axis " + "xyz"[a] +
                            " (only axis-aligned grids are supported)");
        spacing[a] = v[a];
      }
    } else if (has("spacings")) {
      const auto s = three<double>("spacings");
      spacing = {s[0], s[1], s[2]};
    }
    return spacing;
  }

  bool big_endian(std::size_t sample_bytes) const {
    if (sample_bytes == 1 && !has("endian")) return false;
    const std::string& endian = field("endian");
    if (endian == "little") return false;
    if (endian == "big") return true;
    fail(path_, "endian: " + endian + " (little or big)");
  }

  const fs::path& path_;
  std::map<std::string, std::string> fields_;
};

}  // namespace

Samples read_nrrd(const fs::path& path) {
  const auto [text, offset] = read_header(path);
  const NrrdHeader header(path, text);
  Samples samples;
  samples.layout = header.layout();
  ByteSource source(path, offset, header.gzip());
  const std::uint64_t count =
      static_cast<std::uint64_t>(samples.count()) * sample_size(samples.layout.type);
  samples.bytes = read_exact(source, count, "sizes x type size");
  return samples;
}

void write_nrrd(const Samples& samples, const fs::path& path) {
  const SampleLayout& l = samples.layout;
  const auto& names = type_names();
  const auto type = std::find_if(names.begin(), names.end(),
                                 [&](const auto& entry) { return entry.first == l.type; });
  const auto n = [](double x) { return format_number(x); };
  std::string header =
      "NRRD0004\n# written by volmesh\ntype: " + type->second.front() +
      "\ndimension: 3\nspace dimension: 3\nsizes: " + std::to_string(l.dims[0]) + " " +
      std::to_string(l.dims[1]) + " " + std::to_string(l.dims[2]) + "\nspace directions: (" +
      n(l.spacing[0]) + ",0,0) (0," + n(l.spacing[1]) + ",0) (0,0," + n(l.spacing[2]) +
      ")\nkinds: domain domain domain\nendian: " + (l.big_endian ? "big" : "little") +
      "\nencoding: gzip\nspace origin: (" + n(l.origin[0]) + "," + n(l.origin[1]) + "," +
      n(l.origin[2]) + ")\n\n";
  write_atomically(path, {header, gzip(samples.bytes)});
}

}  // namespace volmesh::voxel
