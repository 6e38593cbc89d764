// OFF (Object File Format): "OFF" (or COFF, NOFF, STOFF, ... ), the vertex, face and edge
// counts, one vertex per line, one polygon per line ("k i1 ... ik", then maybe a colour).
// '#' starts a comment. Polygons with more than three corners are split into fans.
#include <cstdint>

#include "surface_file.hpp"
#include "surface_text.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;
using namespace surface_detail;

namespace {

// Accepts an optional [ST][C][N]OFF keyword; 4OFF, nOFF and binary OFF are refused.
void read_header_keyword(TextCursor& c, const fs::path& path) {
  TextCursor peek = c;
  const std::string_view w = peek.word();
  if (w.size() >= 3 && w.substr(w.size() - 3) == "OFF") {
    if (w.substr(0, w.size() - 3).find_first_not_of("STCN") != std::string_view::npos)
      fail(path, "header: OFF variant '" + std::string(w) +
                     "' is not supported (3D OFF, COFF, NOFF and STOFF are)");
    c = peek;
    if (peek.word() == "BINARY") fail(path, "header: binary OFF is not supported");
    return;
  }
  std::uint64_t count = 0;
  if (!parse_count(w, count))  // no keyword at all is tolerated: the counts come first
    fail(path, "header: not an OFF file (it starts with '" + std::string(w.substr(0, 20)) + "')");
}

Index read_count(TextCursor& c, const fs::path& path, const char* what) {
  std::uint64_t count = 0;
  if (!parse_count(c.word(), count))
    fail(path, "header (" + c.where() + "): expected the number of " + what);
  return checked_count(path, count, what);
}

}  // namespace

TriSurface read_off(const fs::path& path) {
  const std::string data = load_file(path);
  TextCursor c(data);
  c.skip_space('#');
  read_header_keyword(c, path);
  c.skip_space('#');
  const Index num_vertices = read_count(c, path, "vertices");
  const Index num_faces = read_count(c, path, "faces");
  c.next_line();  // the edge count, unused
  // At least "x y z" per vertex and "3 a b c" per face: refuse a header the file cannot hold.
  if (6 * std::uint64_t(num_vertices) + 8 * std::uint64_t(num_faces) > c.remaining() + 2)
    fail(path, "header: claims " + std::to_string(num_vertices) + " vertices and " +
                   std::to_string(num_faces) + " faces, more than the remaining " +
                   std::to_string(c.remaining()) + " bytes can hold (truncated?)");

  TriSurface surface;
  surface.points.resize(num_vertices);
  for (Index i = 0; i < num_vertices; ++i) {
    c.skip_space('#');
    Vec3& p = surface.points[i];
    if (!c.number(p.x()) || !c.number(p.y()) || !c.number(p.z()))
      fail(path,
           "vertex " + std::to_string(i) + " (" + c.where() + "): " +
               (c.at_end() ? "unexpected end of file (truncated?)" : "expected three coordinates"));
    c.next_line();  // colour or normal, unused
  }

  surface.triangles.reserve(num_faces);
  PolygonFan fan(path, surface.triangles);
  for (Index f = 0; f < num_faces; ++f) {
    c.skip_space('#');
    auto error = [&](const std::string& what) {
      fail(path, "face " + std::to_string(f) + " (" + c.where() + "): " + what);
    };
    std::int64_t corners;
    if (!c.number(corners))
      error(c.at_end() ? "unexpected end of file (truncated?)" : "expected the number of corners");
    if (corners < 3) error(std::to_string(corners) + " corners, at least 3 needed");
    fan.start();
    for (std::int64_t k = 0; k < corners; ++k) {
      std::int64_t v;
      if (!c.number(v))
        error("expected " + std::to_string(corners) + " vertex indices, found " +
              std::to_string(k));
      if (v < 0 || v >= num_vertices) error(vertex_index_error(v, num_vertices));
      fan.add(static_cast<Index>(v));
    }
    c.next_line();  // colour, unused
  }
  return surface;
}

void write_off(const TriSurface& surface, const fs::path& path) {
  write_atomically(surface, path, [&](ChunkedWriter& writer) {
    std::string& out = writer.buffer();
    out += "OFF\n";
    append_number(out, surface.num_points());
    out += ' ';
    append_number(out, surface.num_triangles());
    out += " 0\n";
    for (const Vec3& p : surface.points) {
      append_line(out, "", p);
      writer.flush_if_full();
    }
    for (const auto& t : surface.triangles) {
      append_line(out, "3", t);
      writer.flush_if_full();
    }
  });
}

}  // namespace volmesh
