#pragma once
// A test case of the octree methods: a domain and the octree options that vary.
#include <string>

#include "volmesh/octree/octree.hpp"

namespace volmesh::test {

struct Case {
  std::string domain;
  int level, base_level, cells_between_levels;
};

inline OctreeOptions options_of(const Case& c) {
  OctreeOptions o;
  o.level = c.level;
  o.base_level = c.base_level;
  o.cells_between_levels = c.cells_between_levels;
  return o;
}

}  // namespace volmesh::test
