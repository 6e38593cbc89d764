// Chooses the surface reader or writer from the file name's extension.
#include "volmesh/io/surface_io.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "surface_file.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

enum class SurfaceFormat { stl, off, obj, ply, unknown };

SurfaceFormat format_of(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".stl") return SurfaceFormat::stl;
  if (ext == ".off") return SurfaceFormat::off;
  if (ext == ".obj") return SurfaceFormat::obj;
  if (ext == ".ply") return SurfaceFormat::ply;
  return SurfaceFormat::unknown;
}

[[noreturn]] void unknown_format(const fs::path& path) {
  surface_detail::fail(path, "unknown surface format '" + path.extension().string() +
                                 "' (expected .stl, .off, .obj or .ply)");
}

}  // namespace

bool is_surface_file(const fs::path& path) { return format_of(path) != SurfaceFormat::unknown; }

TriSurface read_surface(const fs::path& path) {
  switch (format_of(path)) {
    case SurfaceFormat::stl:
      return read_stl(path);
    case SurfaceFormat::off:
      return read_off(path);
    case SurfaceFormat::obj:
      return read_obj(path);
    case SurfaceFormat::ply:
      return read_ply(path);
    case SurfaceFormat::unknown:
      break;
  }
  unknown_format(path);
}

void write_surface(const TriSurface& surface, const fs::path& path) {
  switch (format_of(path)) {
    case SurfaceFormat::stl:
      return write_stl(surface, path);
    case SurfaceFormat::off:
      return write_off(surface, path);
    case SurfaceFormat::obj:
      return write_obj(surface, path);
    case SurfaceFormat::ply:
      return write_ply(surface, path);
    case SurfaceFormat::unknown:
      break;
  }
  unknown_format(path);
}

}  // namespace volmesh
