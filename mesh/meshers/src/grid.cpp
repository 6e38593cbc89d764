// The Cartesian grid of a box: 2^level hexahedra per axis of the domain's bounding box, or
// their Kuhn tetrahedra.
#include <array>
#include <cstdint>

#include "registration.hpp"
#include "volmesh/meshers/grid.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/structured.hpp"

namespace volmesh::meshers {

namespace {

// 2^(3 level) cells must fit an Index.
constexpr int kMaxGridLevel = 10;
// How far inside its corners a box-filling domain is probed, as a fraction of the box.
constexpr double kCornerInset = 0.001;

// Only a domain that fills its bounding box is meshed by the grid of that box.
void require_box(const Domain& domain, const Box3& box, const std::string& name) {
  for (int k = 0; k < 8; ++k) {
    Vec3 t;
    for (int a = 0; a < 3; ++a) t[a] = (k >> a & 1) ? 1.0 - kCornerInset : kCornerInset;
    if (domain.region(box.lo + t.cwiseProduct(box.size())) == 0)
      throw InputError("grid: " + name +
                       " does not fill its bounding box; the grid meshes boxes only");
  }
}

}  // namespace

Box3 grid_box(const Domain& domain, const MeshRequest& request) {
  const int level = *request.level;
  if (level > kMaxGridLevel)
    throw InputError("grid: --level " + std::to_string(level) + " gives " +
                     std::to_string(std::int64_t{1} << (3 * level)) +
                     " cells, beyond the index limit (at most --level " +
                     std::to_string(kMaxGridLevel) + ")");
  if (level < 0) throw InputError("grid: --level must be at least 0");
  const Box3 box = domain.bounds();
  if (!box.lo.allFinite() || !box.hi.allFinite() || !((box.hi - box.lo).minCoeff() > 0.0))
    throw InputError(request.domain_name + ": empty or flat bounding box; no grid to build");
  require_box(domain, box, request.domain_name);
  return box;
}

namespace {

MeshResult mesh_grid(const Domain& domain, const MeshRequest& request) {
  const int level = *request.level;
  const Box3 box = grid_box(domain, request);
  const bool tets = given<bool>(request.options, "tets").value_or(false);
  const Index n = Index{1} << level;
  const std::array<Index, 3> cells{n, n, n};
  MeshResult r;
  r.mesh = tets ? to_poly_mesh(kuhn_tet_mesh(box.lo, box.hi, cells))
                : to_poly_mesh(structured_hex_mesh(box.lo, box.hi, cells));
  r.h = box.size().maxCoeff() / static_cast<double>(n);
  r.summary = {{"cells_per_axis", n}, {"element", tets ? "tet" : "hex"}};
  return r;
}

const Registration registered{MesherInfo{
    .name = "grid",
    .description = "Cartesian grid of a box: 2^level hexahedra per axis, or their Kuhn tetrahedra",
    .resolution = Resolution::level,
    .octree = false,
    .options = {{.name = "tets",
                 .help = "split each hex into 6 Kuhn tetrahedra",
                 .type = OptionSpec::Type::flag}},
    .default_domain = "builtin:box",
    .default_space = "",
    .run = mesh_grid,
}};

}  // namespace

}  // namespace volmesh::meshers
