// STL: ASCII and binary reading, binary writing. STL stores every triangle's corners
// separately, in single precision for binary files; coincident corners are merged exactly.
#include <algorithm>
#include <bit>
#include <cstdint>

#include "volmesh/core/byte_order.hpp"
#include "surface_file.hpp"
#include "surface_text.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;
using namespace surface_detail;
using namespace byte_order;

namespace {

constexpr std::uint64_t kHeaderBytes = 84;  // 80 bytes of text, then the triangle count
constexpr std::uint64_t kRecordBytes = 50;  // normal, three corners, attribute word

// Gives coincident corners one index, in order of first appearance. Corners are compared by
// their bit patterns, with -0 folded onto +0, so that equal coordinates merge and nothing
// else does. An open-addressing table of point indices: STL files have millions of corners.
class PointMerger {
 public:
  PointMerger(TriSurface& surface, const fs::path& path) : surface_(surface), path_(path) {
    reserve(1024);
  }

  Index add(const Vec3& p) {
    const Key key = key_of(p);
    for (std::size_t i = hash(key) & mask_;; i = (i + 1) & mask_) {
      if (slots_[i] == kNoIndex) break;
      if (key_of(surface_.points[slots_[i]]) == key) return slots_[i];
    }
    if (surface_.points.size() >= static_cast<std::size_t>(kMaxIndex))
      fail(path_, "more vertices than the 32-bit index limit (" + std::to_string(kMaxIndex) + ")");
    const Index id = surface_.num_points();
    surface_.points.push_back(p);
    if (2 * surface_.points.size() > slots_.size()) {
      reserve(surface_.points.size());
    } else {
      insert(key, id);
    }
    return id;
  }

  // Rebuilds the table for `points` points at a load factor of at most 1/2.
  void reserve(std::size_t points) {
    std::size_t size = 1;
    while (size < 2 * points + 2) size *= 2;
    if (size <= slots_.size()) return;
    slots_.assign(size, kNoIndex);
    mask_ = size - 1;
    for (Index id = 0; id < surface_.num_points(); ++id) insert(key_of(surface_.points[id]), id);
  }

 private:
  using Key = std::array<std::uint64_t, 3>;

  static Key key_of(const Vec3& p) {
    return {std::bit_cast<std::uint64_t>(p.x() + 0.0), std::bit_cast<std::uint64_t>(p.y() + 0.0),
            std::bit_cast<std::uint64_t>(p.z() + 0.0)};
  }
  // splitmix64's finaliser: every key bit reaches the low bits the table uses.
  static std::uint64_t mix(std::uint64_t h) {
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    return h ^ (h >> 31);
  }
  static std::size_t hash(const Key& k) {
    return static_cast<std::size_t>(mix(k[0] ^ mix(k[1] ^ mix(k[2]))));
  }
  void insert(const Key& key, Index id) {
    std::size_t i = hash(key) & mask_;
    while (slots_[i] != kNoIndex) i = (i + 1) & mask_;
    slots_[i] = id;
  }

  TriSurface& surface_;
  const fs::path& path_;
  std::vector<Index> slots_;
  std::size_t mask_ = 0;
};

void add_triangle(TriSurface& surface, const fs::path& path, const std::array<Index, 3>& t) {
  if (surface.triangles.size() >= static_cast<std::size_t>(kMaxIndex))
    fail(path, "more triangles than the 32-bit index limit (" + std::to_string(kMaxIndex) + ")");
  surface.triangles.push_back(t);
}

TriSurface read_binary_stl(const std::string& data, std::uint64_t count, const fs::path& path) {
  TriSurface surface;
  surface.triangles.reserve(checked_count(path, count, "triangles"));
  PointMerger merger(surface, path);
  merger.reserve(count / 2 + 3);  // a closed surface has about half as many vertices
  for (std::uint64_t t = 0; t < count; ++t) {
    const char* corner = data.data() + kHeaderBytes + kRecordBytes * t + 12;
    std::array<Index, 3> tri;
    for (int k = 0; k < 3; ++k, corner += 12)
      tri[k] = merger.add(Vec3(load<float>(corner, false), load<float>(corner + 4, false),
                               load<float>(corner + 8, false)));
    surface.triangles.push_back(tri);
  }
  return surface;
}

// solid NAME / facet normal n n n / outer loop / vertex x y z (3x) / endloop / endfacet /
// ... / endsolid NAME, possibly several solids in a row.
TriSurface read_ascii_stl(const std::string& data, const fs::path& path) {
  TriSurface surface;
  PointMerger merger(surface, path);
  TextCursor c(data);
  auto error = [&](const std::string& what) {
    fail(path,
         "facet " + std::to_string(surface.triangles.size()) + " (" + c.where() + "): " + what);
  };
  auto found = [](std::string_view w) {
    return w.empty() ? std::string("the end of the file (truncated?)") : "'" + std::string(w) + "'";
  };
  auto expect = [&](std::string_view keyword) {
    c.skip_space();
    const std::string_view w = c.word();
    if (w != keyword) error("expected '" + std::string(keyword) + "', found " + found(w));
  };
  auto vec3 = [&](const char* what) {
    Vec3 p;
    if (!c.number(p.x()) || !c.number(p.y()) || !c.number(p.z()))
      error(std::string("expected three numbers after '") + what + "'");
    return p;
  };

  c.skip_space();
  while (!c.at_end()) {
    expect("solid");
    c.next_line();  // the solid's name
    for (;;) {
      c.skip_space();
      const std::string_view w = c.word();
      if (w == "endsolid") break;
      if (w != "facet") error("expected 'facet' or 'endsolid', found " + found(w));
      expect("normal");
      vec3("normal");  // recomputed from the corners wherever needed
      expect("outer");
      expect("loop");
      std::array<Index, 3> tri;
      for (Index& v : tri) {
        expect("vertex");
        v = merger.add(vec3("vertex"));
      }
      expect("endloop");
      expect("endfacet");
      add_triangle(surface, path, tri);
    }
    c.next_line();
    c.skip_space();
  }
  return surface;
}

bool starts_with_solid(const std::string& data) {
  const std::size_t i = data.find_first_not_of(" \t\r\n");
  return i != std::string::npos && data.compare(i, 5, "solid") == 0;
}

// Some binary STL headers start with "solid" too; control bytes (e.g. the zero bytes of the
// triangle count) betray them.
bool looks_binary(const std::string& data) {
  const std::size_t n = std::min<std::size_t>(data.size(), 512);
  return std::any_of(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(n),
                     [](unsigned char ch) { return ch < 32 && !is_space(static_cast<char>(ch)); });
}

}  // namespace

TriSurface read_stl(const fs::path& path) {
  const std::string data = load_file(path);
  const std::uint64_t size = data.size();
  // A binary file's size is fixed by its triangle count: that decides, whatever the header says.
  std::uint64_t count = 0;
  if (size >= kHeaderBytes) {
    count = load<std::uint32_t>(data.data() + 80, false);
    if (size == kHeaderBytes + kRecordBytes * count) return read_binary_stl(data, count, path);
  }
  if (starts_with_solid(data) && !looks_binary(data)) return read_ascii_stl(data, path);
  if (size < kHeaderBytes)
    fail(path, "header: " + std::to_string(size) +
                   " bytes: neither an ASCII STL (starting with 'solid') nor a binary STL "
                   "(84 bytes of header at least)");
  fail(path, "header: binary STL claims " + std::to_string(count) + " triangles (" +
                 std::to_string(kHeaderBytes + kRecordBytes * count) + " bytes) but the file has " +
                 std::to_string(size) + " bytes (truncated?)");
}

void write_stl(const TriSurface& surface, const fs::path& path) {
  write_atomically(surface, path, [&](ChunkedWriter& writer) {
    std::string& out = writer.buffer();
    // Must not start with "solid", which readers take for ASCII STL.
    std::string header = "binary STL written by volmesh";
    header.resize(80, ' ');
    out += header;
    append<std::uint32_t>(out, static_cast<std::uint32_t>(surface.triangles.size()), false);
    auto append_vec3 = [&](const Vec3& v) {
      for (int k = 0; k < 3; ++k) append<float>(out, static_cast<float>(v[k]), false);
    };
    for (const auto& t : surface.triangles) {
      const Vec3 &a = surface.points[t[0]], &b = surface.points[t[1]], &c = surface.points[t[2]];
      append_vec3((b - a).cross(c - a).normalized());
      append_vec3(a);
      append_vec3(b);
      append_vec3(c);
      append<std::uint16_t>(out, 0, false);
      writer.flush_if_full();
    }
  });
}

}  // namespace volmesh
