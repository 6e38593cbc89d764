// The staircase octree method (volmesh/octree/staircase.hpp).
#include "volmesh/octree/staircase.hpp"

#include "volmesh/meshers/octree_request.hpp"
#include "registration.hpp"

namespace volmesh::meshers {

namespace {

MeshResult mesh_staircase(const Domain& domain, const MeshRequest& request) {
  StaircaseOptions options;
  options.octree = octree_request(request);
  options.progress = request.progress;
  StaircaseStats stats;
  MeshResult r;
  r.mesh = staircase_mesh(domain, options, &stats);
  r.h = octree_cell_size(domain, options.octree);
  r.summary = {{"leaves", stats.leaves},
               {"octree_seconds", stats.octree_seconds},
               {"mesh_seconds", stats.mesh_seconds}};
  return r;
}

const Registration registered{MesherInfo{
    .name = "staircase",
    .description = "octree staircase: the leaves inside as cubes, first order at the boundary",
    .resolution = Resolution::level,
    .octree = true,
    .options = {},
    .default_domain = "builtin:ball",
    .default_space = "polyhedral",
    .run = mesh_staircase,
}};

}  // namespace

}  // namespace volmesh::meshers
