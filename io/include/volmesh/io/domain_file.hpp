#pragma once
// Domain files (.json): several labelled closed surfaces, layers between triangulated
// sheets, or analytic solids, described in docs/methods.md ("Domain files"). Paths inside are
// relative to the file.
#include <filesystem>
#include <memory>

#include "volmesh/domain/domain.hpp"

namespace volmesh {

// Throws InputError with one line naming the file and the JSON path of what is wrong, e.g.
//   "layers.json: layers.horizons[2].file: cannot open 'x.stl'"
// (syntax errors, unknown keys, wrong types or values, files that cannot be read, and the
// geometric checks of the domain built).
std::unique_ptr<Domain> read_domain_file(const std::filesystem::path& path);

}  // namespace volmesh
