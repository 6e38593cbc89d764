// The command line's <domain> argument: a built-in name, or a file chosen by its extension
// (a .nrrd by its header's sample type).
#include "volmesh/io/open_domain.hpp"

#include <fstream>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/image.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/domain/grid.hpp"
#include "volmesh/io/domain_file.hpp"
#include "volmesh/io/label_image_io.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/io/voxel_grid_io.hpp"
#include "voxel_samples.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kBuiltin = "builtin:";

// Whether the NRRD header's "type:" names a floating-point sample type (the header is
// plain text up to its first blank line, whatever the data's encoding).
bool nrrd_holds_floats(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int lines = 0; lines < 1000 && std::getline(in, line); ++lines) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) break;
    if (line.rfind("type:", 0) != 0) continue;
    std::string type = line.substr(5);
    type.erase(0, type.find_first_not_of(' '));
    return type == "float" || type == "double";
  }
  return false;  // no type field: the label reader names what is missing
}

std::unique_ptr<Domain> open_surface(const fs::path& path) {
  std::vector<LabelledSurface> surfaces(1);
  surfaces[0].surface = read_surface(path);
  surfaces[0].label = 1;
  surfaces[0].name = path.string();
  return std::make_unique<SurfaceDomain>(std::move(surfaces));
}

}  // namespace

std::unique_ptr<Domain> open_domain(const std::string& spec) {
  if (spec.rfind(kBuiltin, 0) == 0) return make_builtin_domain(spec.substr(kBuiltin.size()));
  const fs::path path(spec);
  using voxel::has_suffix;
  const bool known = is_surface_file(path) || has_suffix(path, ".inr") ||
                     has_suffix(path, ".inr.gz") || has_suffix(path, ".nrrd") ||
                     has_suffix(path, ".rawiv") || has_suffix(path, ".vti") ||
                     has_suffix(path, ".json");
  if (!known)
    throw InputError(spec +
                     ": unknown domain (expected builtin:NAME or a .stl .off .obj .ply .inr "
                     ".inr.gz .nrrd .rawiv .vti or .json file)");
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError(spec + ": cannot open (no such file)");
  if (is_surface_file(path)) return open_surface(path);
  if (has_suffix(path, ".json")) return read_domain_file(path);
  if (has_suffix(path, ".rawiv") || has_suffix(path, ".vti") ||
      (has_suffix(path, ".nrrd") && nrrd_holds_floats(path)))
    return std::make_unique<SdfGridDomain>(read_voxel_grid(path));
  return std::make_unique<ImageDomain>(read_label_image(path));
}

std::string domain_display_name(const std::string& spec) {
  if (spec.rfind(kBuiltin, 0) == 0) return spec;
  return fs::path(spec).filename().string();
}

}  // namespace volmesh
