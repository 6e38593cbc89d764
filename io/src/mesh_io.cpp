#include "volmesh/io/mesh_io.hpp"

#include <algorithm>
#include <cctype>

#include "volmesh/core/errors.hpp"
#include "volmesh/io/partitioned_io.hpp"

namespace volmesh {

namespace {

std::string lower_extension(const std::filesystem::path& path) {
  // "case.foam/" names a directory: look at the last non-empty component.
  std::filesystem::path p = path;
  if (p.filename().empty()) p = p.parent_path();
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool is_foam_case(const std::filesystem::path& path) {
  return std::filesystem::is_directory(path / "constant" / "polyMesh");
}

}  // namespace

bool is_mesh_file(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".vtu" || ext == ".pvtu" || ext == ".msh" || ext == ".mesh" || ext == ".node" ||
         ext == ".ele" || ext == ".foam" || is_foam_case(path);
}

void require_writable_mesh_path(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  for (const char* known : {".vtu", ".msh", ".mesh", ".inp", ".foam"})
    if (ext == known) return;
  throw InputError(path.string() +
                   ": unknown output format (use .vtu .msh .mesh .inp or a DIR.foam case)");
}

void write_mesh(const PolyMesh& mesh, const std::filesystem::path& path, const MeshFields& fields) {
  require_writable_mesh_path(path);
  const std::string ext = lower_extension(path);
  if (ext == ".vtu") return write_vtu(mesh, path, fields);
  if (ext == ".msh") return write_msh(mesh, path);
  if (ext == ".mesh") return write_medit(mesh, path);
  if (ext == ".inp") return write_abaqus(mesh, path);
  return write_foam(mesh, path);
}

PolyMesh read_mesh(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string() + ": no such file");
  const std::string ext = lower_extension(path);
  if (ext == ".vtu") return read_vtu(path);
  if (ext == ".pvtu") return read_pvtu(path);
  if (ext == ".msh") return read_msh(path);
  if (ext == ".mesh") return read_medit(path);
  if (ext == ".node" || ext == ".ele") return read_tetgen(path);
  if (ext == ".foam" || is_foam_case(path)) return read_foam(path);
  throw InputError(path.string() +
                   ": unknown mesh format (readable: .vtu .pvtu .msh .mesh .node .ele, a DIR.foam case)");
}

}  // namespace volmesh
