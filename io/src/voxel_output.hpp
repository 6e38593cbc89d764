#pragma once
// Writing image and grid files: gzip in memory, and the whole file through a temporary
// renamed at the end, so that a failed write never leaves a partial file under its name.
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace volmesh::voxel {

std::string gzip(std::string_view data);

// Writes the parts one after another; throws InputError naming `path` on failure.
void write_atomically(const std::filesystem::path& path,
                      std::initializer_list<std::string_view> parts);

}  // namespace volmesh::voxel
