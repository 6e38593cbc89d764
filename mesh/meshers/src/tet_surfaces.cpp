#include "tet_surfaces.hpp"

#include <optional>
#include <string_view>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/geometry/self_intersections.hpp"

namespace volmesh::meshers {

namespace {

constexpr std::string_view kBuiltin = "builtin:";

}  // namespace

std::vector<tet::ProjectionSurface> triangulated_surfaces(const Domain& domain,
                                                          const std::string& name,
                                                          const std::string& method) {
  const auto* given = dynamic_cast<const SurfaceDomain*>(&domain);
  std::optional<SurfaceDomain> polyhedral;
  if (given == nullptr && name.starts_with(kBuiltin)) {
    std::vector<LabelledSurface> list = builtin_surfaces(name.substr(kBuiltin.size()));
    if (!list.empty()) given = &polyhedral.emplace(std::move(list));
  }
  if (given == nullptr)
    throw InputError(method + ": " + name +
                     " is not given by triangulated surfaces; give a surface file (.stl .off "
                     ".obj .ply) or a builtin made of triangles");
  std::vector<tet::ProjectionSurface> out;
  for (Index s = 0; s < static_cast<Index>(given->labels().size()); ++s) {
    tet::ProjectionSurface p{given->surface(s), given->labels()[s], given->depths()[s] == 0};
    p.name = domain.boundary_name(p.surface.points.front());
    if (p.name.empty()) p.name = "surface";
    out.push_back(std::move(p));
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

}  // namespace volmesh::meshers
