// Wavefront OBJ: "v x y z" and "f" lines whose corners are "i", "i/t", "i//n" or "i/t/n"
// (1-based, negative = relative to the last vertex so far). Other statements (vn, vt, g, o,
// usemtl, ...) are ignored; polygons with more than three corners are split into fans.
#include <cstdint>

#include "surface_file.hpp"
#include "surface_text.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;
using namespace surface_detail;

TriSurface read_obj(const fs::path& path) {
  const std::string data = load_file(path);
  TextCursor c(data);
  TriSurface surface;
  PolygonFan fan(path, surface.triangles);
  Index face = 0;
  // Positive indices may point past the vertices read so far: the largest is checked at the end.
  std::int64_t max_index = 0;
  Index max_face = 0;
  long max_line = 0;

  for (c.skip_space('#'); !c.at_end(); c.next_line(), c.skip_space('#')) {
    const std::string_view statement = c.word();
    if (statement == "v") {
      Vec3 p;
      if (!c.number(p.x()) || !c.number(p.y()) || !c.number(p.z()))
        fail(path, "vertex " + std::to_string(surface.points.size() + 1) + " (" + c.where() +
                       "): expected three coordinates");
      if (surface.points.size() >= static_cast<std::size_t>(kMaxIndex))
        fail(path, "more vertices than the 32-bit index limit (" + std::to_string(kMaxIndex) + ")");
      surface.points.push_back(p);
    } else if (statement == "f") {
      auto error = [&](const std::string& what) {
        fail(path, "face " + std::to_string(face) + " (" + c.where() + "): " + what);
      };
      fan.start();
      for (c.skip_blanks(); !c.at_line_end('#'); c.skip_blanks()) {
        const std::string_view corner = c.word();
        std::int64_t v;
        if (!parse_number(corner.substr(0, corner.find('/')), v) || v == 0)
          error("bad vertex reference '" + std::string(corner) + "'");
        if (v < 0) {
          if (v < -std::int64_t(surface.points.size()))
            error(vertex_index_error(v, surface.num_points()) + " at this point");
          fan.add(static_cast<Index>(surface.points.size() + v));
        } else {
          if (v > kMaxIndex) error(vertex_index_error(v, surface.num_points()));
          if (v > max_index) {
            max_index = v;
            max_face = face;
            max_line = c.line();
          }
          fan.add(static_cast<Index>(v - 1));
        }
      }
      if (fan.corners() < 3) error(std::to_string(fan.corners()) + " corners, at least 3 needed");
      ++face;
    }
  }
  if (max_index > surface.num_points())
    fail(path, "face " + std::to_string(max_face) + " (line " + std::to_string(max_line) +
                   "): " + vertex_index_error(max_index, surface.num_points()));
  return surface;
}

void write_obj(const TriSurface& surface, const fs::path& path) {
  write_atomically(surface, path, [&](ChunkedWriter& writer) {
    std::string& out = writer.buffer();
    for (const Vec3& p : surface.points) {
      append_line(out, "v", p);
      writer.flush_if_full();
    }
    for (const auto& t : surface.triangles) {
      append_line(out, "f", t, 1);
      writer.flush_if_full();
    }
  });
}

}  // namespace volmesh
