#include "tet_surfaces.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <string_view>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/geometry/self_intersections.hpp"
#include "volmesh/surfacing/implicit.hpp"
#include "volmesh/tet/rounding.hpp"

namespace volmesh::meshers {

namespace {

constexpr std::string_view kBuiltin = "builtin:";

}  // namespace

BoundarySurfaces triangulated_surfaces(const Domain& domain, const std::string& name,
                                       const std::string& method, std::optional<double> size) {
  const auto* given = dynamic_cast<const SurfaceDomain*>(&domain);
  std::optional<SurfaceDomain> polyhedral;
  if (given == nullptr && name.starts_with(kBuiltin)) {
    std::vector<LabelledSurface> list = builtin_surfaces(name.substr(kBuiltin.size()));
    if (!list.empty()) given = &polyhedral.emplace(std::move(list));
  }
  BoundarySurfaces out;
  if (given == nullptr) {
    if (!size)
      throw InputError(method + ": " + name +
                       " is not given by triangulated surfaces; give a surface file (.stl .off "
                       ".obj .ply), a builtin made of triangles, or a size to triangulate it at");
    for (surfacing::InterfaceSurface& s : surfacing::mesh_interfaces(domain, *size)) {
      tet::ProjectionSurface p{std::move(s.surface), s.inside, s.outside == 0 && s.inside != 0};
      p.name = domain.boundary_name(p.surface.points.front());
      if (p.name.empty()) p.name = "surface";
      out.surfaces.push_back(std::move(p));
    }
    out.triangulated = true;
    return out;
  }
  for (Index s = 0; s < static_cast<Index>(given->labels().size()); ++s) {
    tet::ProjectionSurface p{given->surface(s), given->labels()[s], given->depths()[s] == 0};
    p.name = domain.boundary_name(p.surface.points.front());
    if (p.name.empty()) p.name = "surface";
    out.surfaces.push_back(std::move(p));
  }
  return out;
}

void require_no_intersections(const std::vector<tet::ProjectionSurface>& surfaces,
                              const std::string& name, const std::string& method) {
  TriSurface all;
  for (const tet::ProjectionSurface& s : surfaces) {
    const Index first = all.num_points();
    all.points.insert(all.points.end(), s.surface.points.begin(), s.surface.points.end());
    for (const auto& t : s.surface.triangles)
      all.triangles.push_back({first + t[0], first + t[1], first + t[2]});
  }
  const auto pairs = find_self_intersections(all, 1);
  if (!pairs.empty())
    throw InputError(name + ": triangles " + std::to_string(pairs[0].first) + " and " +
                     std::to_string(pairs[0].second) + " intersect; " + method +
                     " needs surfaces that do not cross");
}

void drop_cavities(TetMesh& mesh, const std::vector<tet::ProjectionSurface>& surfaces) {
  // The range of point numbers each cavity's own points have.
  std::vector<std::array<Index, 3>> cavities;  // surface, first point, end
  Index first = 0;
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    const Index end = first + surfaces[s].surface.num_points();
    if (surfaces[s].label == 0) cavities.push_back({static_cast<Index>(s), first, end});
    first = end;
  }
  if (cavities.empty()) return;
  const auto key = [](std::array<Index, 3> f) {
    std::sort(f.begin(), f.end());
    return f;
  };
  std::set<std::array<Index, 3>> filled;  // the faces of the cavities' tets
  for (std::size_t c = 0; c < mesh.cells.size(); ++c)
    if (mesh.cell_region[c] == 0)
      for (const auto& f : kTetFaces)
        filled.insert(key({mesh.cells[c][f[0]], mesh.cells[c][f[1]], mesh.cells[c][f[2]]}));
  std::size_t kept = 0;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    if (mesh.cell_region[c] == 0) continue;
    const auto& cell = mesh.cells[c];
    for (const auto& f : kTetFaces) {
      const std::array<Index, 3> face{cell[f[0]], cell[f[1]], cell[f[2]]};
      if (!filled.contains(key(face))) continue;
      Index tag = cavities.front()[0];
      for (const auto& [s, begin, end] : cavities)
        for (const Index v : face)
          if (v >= begin && v < end) tag = s;
      mesh.boundary_faces.push_back(face);
      mesh.boundary_tag.push_back(tag);
    }
    mesh.cells[kept] = cell;
    mesh.cell_region[kept++] = mesh.cell_region[c];
  }
  mesh.cells.resize(kept);
  mesh.cell_region.resize(kept);
  tet::drop_unused_points(mesh);
}

}  // namespace volmesh::meshers
