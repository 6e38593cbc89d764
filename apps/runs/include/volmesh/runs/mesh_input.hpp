#pragma once
// What the subcommands share about their inputs.
#include <filesystem>
#include <string>

#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::cli {

// The most samples per axis of a signed-distance grid (`volmesh sdf --dim`).
inline constexpr Index kMaxSdfDim = 1025;

// Throws InputError "PATH: unknown format" for anything else.
void require_known_format(const std::filesystem::path& path);

// Bounding box of a point set.
struct Box {
  Vec3 lo, hi;
  double diagonal() const { return (hi - lo).norm(); }
};
Box bounding_box(const std::vector<Vec3>& points);

}  // namespace volmesh::cli
