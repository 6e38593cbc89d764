// PLY: ASCII, binary little- and big-endian. Reads x, y, z of the "vertex" element (any
// scalar type) and the "vertex_indices" (or "vertex_index") list of the "face" element;
// every other property and element is skipped. Polygons are split into fans.
// Writes binary little-endian with double coordinates, so that nothing is rounded.
#include <cstdint>
#include <optional>

#include "volmesh/core/byte_order.hpp"
#include "surface_file.hpp"
#include "surface_text.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;
using namespace surface_detail;
using namespace byte_order;

namespace {

enum class Format { ascii, binary_le, binary_be };

struct ScalarType {
  char kind;  // 'i' signed integer, 'u' unsigned integer, 'f' floating point
  int bytes;
};

std::optional<ScalarType> scalar_type(std::string_view name) {
  struct Named {
    std::string_view name, alias;
    ScalarType type;
  };
  static constexpr Named kTypes[] = {
      {"char", "int8", {'i', 1}},     {"uchar", "uint8", {'u', 1}},   {"short", "int16", {'i', 2}},
      {"ushort", "uint16", {'u', 2}}, {"int", "int32", {'i', 4}},     {"uint", "uint32", {'u', 4}},
      {"float", "float32", {'f', 4}}, {"double", "float64", {'f', 8}}};
  for (const Named& t : kTypes)
    if (name == t.name || name == t.alias) return t.type;
  return std::nullopt;
}

struct Property {
  std::string name;
  ScalarType type;
  bool list = false;
  ScalarType count_type{'u', 1};  // lists only
};

struct Element {
  std::string name;
  Index count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  std::size_t data_offset = 0;
  long data_line = 1;  // for the messages about ASCII data
};

Header read_header(const std::string& data, const fs::path& path) {
  TextCursor c(data);
  auto error = [&](const std::string& what) { fail(path, "header (" + c.where() + "): " + what); };
  auto type_of = [&](std::string_view name) {
    auto type = scalar_type(name);
    if (!type) error("unknown property type '" + std::string(name) + "'");
    return *type;
  };
  if (c.word() != "ply") fail(path, "header: not a PLY file (it does not start with 'ply')");
  Header header;
  bool has_format = false;
  for (c.next_line();; c.next_line()) {
    if (c.at_end()) error("no 'end_header' (truncated?)");
    const std::string_view keyword = c.word();
    if (keyword == "format") {
      const std::string_view format = c.word();
      if (format == "ascii")
        header.format = Format::ascii;
      else if (format == "binary_little_endian")
        header.format = Format::binary_le;
      else if (format == "binary_big_endian")
        header.format = Format::binary_be;
      else
        error("unknown format '" + std::string(format) + "'");
      has_format = true;
    } else if (keyword == "element") {
      Element element{std::string(c.word()), 0, {}};
      std::uint64_t count = 0;
      if (element.name.empty() || !parse_count(c.word(), count))
        error("expected 'element NAME COUNT'");
      element.count = checked_count(path, count, (element.name + " elements").c_str());
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) error("property before any element");
      Property property;
      const std::string_view type = c.word();
      if (type == "list") {
        property.list = true;
        property.count_type = type_of(c.word());
        if (property.count_type.kind == 'f') error("list count of floating-point type");
        property.type = type_of(c.word());
      } else {
        property.type = type_of(type);
      }
      property.name = c.word();
      if (property.name.empty()) error("property without a name");
      header.elements.back().properties.push_back(std::move(property));
    } else if (keyword == "end_header") {
      c.next_line();
      header.data_offset = data.size() - c.remaining();
      header.data_line = c.line();
      break;
    } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
      error("unexpected '" + std::string(keyword) + "'");
    }
  }
  if (!has_format) fail(path, "header: no 'format' line");

  // Each element needs at least its fixed-size fields (binary) or a character and a separator
  // per property (ASCII): refuse counts the file cannot hold before allocating for them.
  std::uint64_t needed = 0;
  const std::uint64_t available = data.size() - header.data_offset;
  for (const Element& e : header.elements) {
    std::uint64_t each = 0;
    for (const Property& p : e.properties)
      each += header.format == Format::ascii ? 2 : p.list ? p.count_type.bytes : p.type.bytes;
    needed += each * static_cast<std::uint64_t>(e.count);
    if (needed > available + 1)
      fail(path, "header: claims " + std::to_string(e.count) + " " + e.name +
                     " elements, more than the remaining " + std::to_string(available) +
                     " bytes can hold (truncated?)");
  }
  return header;
}

// The values after the header, read one at a time in the file's format.
class PlyData {
 public:
  PlyData(const std::string& data, const Header& header, const fs::path& path)
      : path_(path),
        format_(header.format),
        p_(data.data() + header.data_offset),
        end_(data.data() + data.size()),
        text_(data, header.data_offset, header.data_line) {}

  // Names the element being read in error messages.
  void at(const std::string& element, Index item) {
    element_ = &element;
    item_ = item;
  }
  [[noreturn]] void error(const std::string& what) const {
    std::string where = *element_ + " " + std::to_string(item_);
    if (format_ == Format::ascii) where += " (" + text_.where() + ")";
    fail(path_, where + ": " + what);
  }

  template <class T>
  T read(ScalarType type) {
    if (format_ == Format::ascii) return read_text<T>();
    if (end_ - p_ < type.bytes) error("unexpected end of data (truncated?)");
    const bool big = format_ == Format::binary_be;
    const char* p = p_;
    p_ += type.bytes;
    switch (type.kind * 16 + type.bytes) {
      case 'i' * 16 + 1:
        return static_cast<T>(load<std::int8_t>(p, big));
      case 'u' * 16 + 1:
        return static_cast<T>(load<std::uint8_t>(p, big));
      case 'i' * 16 + 2:
        return static_cast<T>(load<std::int16_t>(p, big));
      case 'u' * 16 + 2:
        return static_cast<T>(load<std::uint16_t>(p, big));
      case 'i' * 16 + 4:
        return static_cast<T>(load<std::int32_t>(p, big));
      case 'u' * 16 + 4:
        return static_cast<T>(load<std::uint32_t>(p, big));
      case 'f' * 16 + 4:
        return static_cast<T>(load<float>(p, big));
      default:
        return static_cast<T>(load<double>(p, big));
    }
  }

  void skip(const Property& property) {
    const std::int64_t n = property.list ? read<std::int64_t>(property.count_type) : 1;
    if (n < 0) error("negative list length for '" + property.name + "'");
    if (format_ != Format::ascii) {
      if (end_ - p_ < n * property.type.bytes) error("unexpected end of data (truncated?)");
      p_ += n * property.type.bytes;
      return;
    }
    for (std::int64_t k = 0; k < n; ++k) read<double>(property.type);
  }

 private:
  template <class T>
  T read_text() {
    text_.skip_space();
    const std::string_view w = text_.word();
    if (w.empty()) error("unexpected end of data (truncated?)");
    T value{};
    if (!parse_number(w, value)) error("'" + std::string(w) + "' is not a valid value");
    return value;
  }

  const fs::path& path_;
  Format format_;
  const char* p_;
  const char* end_;
  TextCursor text_;
  const std::string* element_ = nullptr;
  Index item_ = 0;
};

const Property* find_property(const Element& element, std::string_view name) {
  for (const Property& p : element.properties)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace

TriSurface read_ply(const fs::path& path) {
  const std::string data = load_file(path);
  const Header header = read_header(data, path);

  const Element* vertex = nullptr;
  const Element* face = nullptr;
  for (const Element& e : header.elements) {
    if (e.name == "vertex") vertex = &e;
    if (e.name == "face") face = &e;
  }
  if (!vertex) fail(path, "header: no 'vertex' element");
  const Property* coordinate[3];
  for (int k = 0; k < 3; ++k) {
    const char name[] = {char('x' + k), '\0'};
    coordinate[k] = find_property(*vertex, name);
    if (!coordinate[k] || coordinate[k]->list)
      fail(path, std::string("header: the vertex element has no scalar property '") + name + "'");
  }
  const Property* indices = nullptr;
  if (face) {
    indices = find_property(*face, "vertex_indices");
    if (!indices) indices = find_property(*face, "vertex_index");
    if (!indices || !indices->list || indices->type.kind == 'f')
      fail(path, "header: the face element has no integer list 'vertex_indices'");
  }

  TriSurface surface;
  PolygonFan fan(path, surface.triangles);
  PlyData values(data, header, path);
  for (const Element& e : header.elements) {
    if (e.properties.empty()) continue;  // no data, however large the count
    // What to do with each property: a coordinate (0, 1, 2), the polygon, or skip it.
    constexpr int kSkip = -1, kPolygon = 3;
    std::vector<int> role(e.properties.size(), kSkip);
    for (std::size_t j = 0; j < role.size(); ++j) {
      for (int k = 0; k < 3; ++k)
        if (&e.properties[j] == coordinate[k]) role[j] = k;
      if (&e.properties[j] == indices) role[j] = kPolygon;
    }
    if (&e == vertex) surface.points.resize(e.count);
    if (&e == face) surface.triangles.reserve(e.count);
    for (Index i = 0; i < e.count; ++i) {
      values.at(e.name, i);
      for (std::size_t j = 0; j < role.size(); ++j) {
        const Property& p = e.properties[j];
        if (role[j] == kSkip) {
          values.skip(p);
        } else if (role[j] == kPolygon) {
          const std::int64_t corners = values.read<std::int64_t>(p.count_type);
          if (corners < 3) values.error(std::to_string(corners) + " corners, at least 3 needed");
          fan.start();
          for (std::int64_t k = 0; k < corners; ++k) {
            const std::int64_t v = values.read<std::int64_t>(p.type);
            if (v < 0 || v >= vertex->count) values.error(vertex_index_error(v, vertex->count));
            fan.add(static_cast<Index>(v));
          }
        } else {
          surface.points[i][role[j]] = values.read<double>(p.type);
        }
      }
    }
  }
  return surface;
}

void write_ply(const TriSurface& surface, const fs::path& path) {
  write_atomically(surface, path, [&](ChunkedWriter& writer) {
    std::string& out = writer.buffer();
    out += "ply\nformat binary_little_endian 1.0\ncomment written by volmesh\nelement vertex " +
           std::to_string(surface.points.size()) +
           "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
           std::to_string(surface.triangles.size()) +
           "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Vec3& p : surface.points) {
      for (int k = 0; k < 3; ++k) append<double>(out, p[k], false);
      writer.flush_if_full();
    }
    for (const auto& t : surface.triangles) {
      append<std::uint8_t>(out, 3, false);
      for (Index v : t) append<std::int32_t>(out, v, false);
      writer.flush_if_full();
    }
  });
}

}  // namespace volmesh
