#pragma once
// Matching the faces of fixed-corner cells by vertex set, shared by the element-mesh
// conversions.
#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

template <int N>
std::array<Index, N> sorted_key(std::span<const Index, N> loop) {
  std::array<Index, N> key;
  std::copy(loop.begin(), loop.end(), key.begin());
  std::sort(key.begin(), key.end());
  return key;
}

}  // namespace volmesh
