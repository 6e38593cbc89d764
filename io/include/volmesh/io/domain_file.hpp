#pragma once
// Domain files (.json): several labelled closed surfaces, layers between triangulated
// sheets, or analytic solids, described in docs/methods.md ("Domain files"). Paths inside are
// relative to the file.
#include <filesystem>
#include <istream>
#include <string>
#include <memory>

#include "volmesh/domain/domain.hpp"

namespace volmesh {

// Throws InputError with one line naming the file and the JSON path of what is wrong, e.g.
//   "layers.json: layers.horizons[2].file: cannot open 'x.stl'"
// (syntax errors, unknown keys, wrong types or values, files that cannot be read, and the
// geometric checks of the domain built).
std::unique_ptr<Domain> read_domain_file(const std::filesystem::path& path);
// The same from a stream of JSON: `name` stands for the file in messages, and the paths
// inside are relative to `dir`.
std::unique_ptr<Domain> read_domain_json(std::istream& in, const std::string& name,
                                         const std::filesystem::path& dir);

}  // namespace volmesh
