// INRIA's INRIMAGE-4 format, as CGAL reads and writes it: a text header of "KEY=value"
// lines padded to a multiple of 256 bytes and closed by "##}\n", then the samples, x fastest.
// A name ending in ".gz" means the whole file is gzipped.
#include <algorithm>
#include <iterator>
#include <map>
#include <string>
#include <string_view>

#include "text_format.hpp"
#include "voxel_output.hpp"
#include "voxel_samples.hpp"
#include "voxel_stream.hpp"

namespace volmesh::voxel {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kMagic = "#INRIMAGE-4#{";
constexpr std::string_view kEnd = "##}\n";
constexpr std::size_t kBlock = 256;
constexpr std::size_t kMaxHeader = 64 * kBlock;

// TYPE and PIXSIZE of each sample type.
struct InrType {
  SampleType type;
  const char* kind;
  const char* bits;
};
constexpr InrType kTypes[] = {
    {SampleType::u8, "unsigned fixed", "8"},   {SampleType::i8, "signed fixed", "8"},
    {SampleType::u16, "unsigned fixed", "16"}, {SampleType::i16, "signed fixed", "16"},
    {SampleType::u32, "unsigned fixed", "32"}, {SampleType::i32, "signed fixed", "32"},
    {SampleType::f32, "float", "32"},          {SampleType::f64, "float", "64"}};

// Reads 256-byte blocks up to the end marker; bytes read past it are the data's first bytes.
std::string read_header(ByteSource& source, std::string& data_prefix) {
  std::string header;
  std::size_t end = std::string::npos;
  while (end == std::string::npos) {
    if (header.size() >= kMaxHeader)
      fail(source.path(),
           "header: no '##}' end marker in the first " + std::to_string(kMaxHeader) + " bytes");
    const std::size_t old = header.size();
    header.resize(old + kBlock);
    header.resize(old + source.read(header.data() + old, kBlock));
    if (old == 0 && header.compare(0, kMagic.size(), kMagic) != 0)
      fail(source.path(), "not an INRIMAGE-4 file (no '#INRIMAGE-4#{' at the start)");
    end = header.find(kEnd, old < kEnd.size() ? 0 : old - kEnd.size());
    if (end == std::string::npos && header.size() < old + kBlock)
      fail(source.path(), "header: the file ends before the '##}' end marker");
  }
  data_prefix = header.substr(end + kEnd.size());
  header.resize(end);
  return header;
}

class InrHeader {
 public:
  InrHeader(const fs::path& path, const std::string& text) : path_(path) {
    std::size_t pos = text.find('\n') + 1;  // after the magic line
    while (pos < text.size()) {
      std::size_t eol = text.find('\n', pos);
      if (eol == std::string::npos) eol = text.size();
      const std::string_view line(text.data() + pos, eol - pos);
      pos = eol + 1;
      const std::size_t eq = line.find('=');
      if (line.empty() || line.front() == '#' || eq == std::string_view::npos) continue;
      fields_[std::string(line.substr(0, eq))] = std::string(line.substr(eq + 1));
    }
  }

  SampleLayout layout() const {
    SampleLayout layout;
    layout.dims = {integer("XDIM"), integer("YDIM"), integer("ZDIM")};
    checked_count(path_, layout.dims, "XDIM/YDIM/ZDIM");
    if (has("VDIM") && integer("VDIM") != 1)
      fail(path_,
           "VDIM=" + fields_.at("VDIM") + ": vector images are not supported (VDIM must be 1)");
    layout.spacing = {number("VX", 1.0), number("VY", 1.0), number("VZ", 1.0)};
    check_spacing(path_, layout.spacing, {"VX", "VY", "VZ"});
    layout.origin = {number("TX", 0.0), number("TY", 0.0), number("TZ", 0.0)};
    check_origin(path_, layout.origin, {"TX", "TY", "TZ"});
    layout.type = type();
    layout.big_endian = big_endian(sample_size(layout.type));
    return layout;
  }

 private:
  bool has(const std::string& key) const { return fields_.count(key) != 0; }

  const std::string& field(const std::string& key) const {
    auto it = fields_.find(key);
    if (it == fields_.end()) fail(path_, "header: " + key + " missing");
    return it->second;
  }

  std::int64_t integer(const std::string& key) const {
    std::int64_t value;
    if (!parse_field(field(key), value)) fail(path_, key + "=" + field(key) + ": not an integer");
    return value;
  }

  double number(const std::string& key, double fallback) const {
    if (!has(key)) return fallback;
    double value;
    if (!parse_field(field(key), value)) fail(path_, key + "=" + field(key) + ": not a number");
    return value;
  }

  SampleType type() const {
    const std::string& kind = field("TYPE");
    const std::string& size = field("PIXSIZE");
    for (const InrType& t : kTypes)
      if (kind == t.kind && size == std::string(t.bits) + " bits") return t.type;
    fail(path_, "TYPE=" + kind + ", PIXSIZE=" + size +
                    ": unsupported sample type (unsigned/signed fixed of 8, 16, 32 bits; float "
                    "of 32, 64)");
  }

  bool big_endian(std::size_t sample_bytes) const {
    if (!has("CPU")) {
      if (sample_bytes == 1) return false;
      fail(path_, "header: CPU missing (the byte order of multi-byte samples is unknown)");
    }
    const std::string& cpu = field("CPU");
    if (cpu == "decm" || cpu == "alpha" || cpu == "pc") return false;
    if (cpu == "sun" || cpu == "sgi") return true;
    fail(path_, "CPU=" + cpu + ": unknown byte order (decm, alpha, pc, sun, sgi)");
  }

  const fs::path& path_;
  std::map<std::string, std::string> fields_;
};

std::string header_text(const SampleLayout& layout) {
  const InrType& t = *std::find_if(std::begin(kTypes), std::end(kTypes),
                                   [&](const InrType& entry) { return entry.type == layout.type; });
  std::string text = std::string(kMagic) + "\n";
  const char* axes[3] = {"X", "Y", "Z"};
  for (int a = 0; a < 3; ++a)
    text += std::string(axes[a]) + "DIM=" + std::to_string(layout.dims[a]) + "\n";
  text += "VDIM=1\nTYPE=" + std::string(t.kind) + "\nPIXSIZE=" + t.bits + " bits\n";
  if (layout.type != SampleType::f32 && layout.type != SampleType::f64) text += "SCALE=2**0\n";
  text += std::string("CPU=") + (layout.big_endian ? "sun" : "decm") + "\n";
  for (int a = 0; a < 3; ++a)
    text += "V" + std::string(axes[a]) + "=" + format_number(layout.spacing[a]) + "\n";
  for (int a = 0; a < 3; ++a)
    text += "T" + std::string(axes[a]) + "=" + format_number(layout.origin[a]) + "\n";
  // Pad with newlines so that the header, end marker included, fills whole 256-byte blocks.
  const std::size_t used = (text.size() + kEnd.size()) % kBlock;
  if (used != 0) text.append(kBlock - used, '\n');
  return text + std::string(kEnd);
}

}  // namespace

Samples read_inr(const fs::path& path) {
  ByteSource source(path, 0, has_suffix(path, ".gz"));
  Samples samples;
  std::string prefix;
  const std::string header = read_header(source, prefix);
  samples.layout = InrHeader(path, header).layout();
  const std::uint64_t count =
      static_cast<std::uint64_t>(samples.count()) * sample_size(samples.layout.type);
  samples.bytes = read_exact(source, count, "XDIM x YDIM x ZDIM x PIXSIZE", std::move(prefix));
  return samples;
}

void write_inr(const Samples& samples, const fs::path& path) {
  const std::string header = header_text(samples.layout);
  if (has_suffix(path, ".gz"))
    write_atomically(path, {gzip(header + samples.bytes)});
  else
    write_atomically(path, {header, samples.bytes});
}

}  // namespace volmesh::voxel
