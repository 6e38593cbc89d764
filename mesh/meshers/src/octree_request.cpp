#include "volmesh/meshers/octree_request.hpp"

#include <cmath>

namespace volmesh::meshers {

OctreeOptions octree_request(const MeshRequest& request) {
  OctreeOptions o;
  o.level = *request.level;
  if (const auto base = given<std::int64_t>(request.options, "base-level"))
    o.base_level = static_cast<int>(*base);
  if (const auto cells = given<std::int64_t>(request.options, "cells-between-levels"))
    o.cells_between_levels = static_cast<int>(*cells);
  if (request.uniform) o.base_level = o.level;
  return o;
}

double octree_cell_size(const Domain& domain, const OctreeOptions& options) {
  return std::ldexp(octree_root(domain, options).side, -options.level);
}

}  // namespace volmesh::meshers
