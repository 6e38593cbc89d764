// Surface domains: nesting, regions and normals (crossings in surface_crossings.cpp).
#include "volmesh/domain/surface.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "surface_domain_data.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {

namespace {

surface::SurfaceGeometry geometry_of(std::vector<LabelledSurface>& surfaces) {
  if (surfaces.empty()) throw InputError("surface domain: no surfaces");
  surface::SurfaceGeometry g;
  for (LabelledSurface& s : surfaces) {
    if (s.label < 0)
      throw InputError(s.name + ": label " + std::to_string(s.label) + ": must be >= 0");
    surface::add_surface(g, std::move(s.surface), s.name);
  }
  return g;
}

}  // namespace

SurfaceDomain::SurfaceDomain(std::vector<LabelledSurface> surfaces) {
  auto data = std::make_unique<surface::DomainData>(geometry_of(surfaces));
  const surface::SurfaceGeometry& g = data->geometry;
  const Index n = g.num_surfaces();
  // Surface s lies inside the surfaces that contain one of its vertices (itself excluded:
  // the vertex is on it).
  data->depth.assign(n, 0);
  for (Index s = 0; s < n; ++s) {
    const std::vector<surface::Containment> c =
        data->exact.containment(g.corner(g.first_triangle[s], 0));
    for (Index other = 0; other < n; ++other) data->depth[s] += other != s && c[other].inside();
  }
  Box3 outer{Vec3::Constant(std::numeric_limits<double>::infinity()),
             Vec3::Constant(-std::numeric_limits<double>::infinity())};
  for (Index s = 0; s < n; ++s) {
    data->label.push_back(surfaces[s].label > 0 ? surfaces[s].label : data->depth[s] + 1);
    if (data->depth[s] > 0) continue;
    for (Index t = g.first_triangle[s]; t < g.first_triangle[s + 1]; ++t)
      for (int k = 0; k < 3; ++k) {
        outer.lo = outer.lo.cwiseMin(g.corner(t, k));
        outer.hi = outer.hi.cwiseMax(g.corner(t, k));
      }
  }
  data->bounds = outer;
  data->regions = data->label;
  std::sort(data->regions.begin(), data->regions.end());
  data->regions.erase(std::unique(data->regions.begin(), data->regions.end()), data->regions.end());
  data_ = std::move(data);
}

SurfaceDomain::~SurfaceDomain() = default;
SurfaceDomain::SurfaceDomain(SurfaceDomain&&) noexcept = default;
SurfaceDomain& SurfaceDomain::operator=(SurfaceDomain&&) noexcept = default;

Index SurfaceDomain::region(const Vec3& p) const {
  if (!p.allFinite()) return 0;
  return data_->region(data_->exact.containment(p));
}

Vec3 SurfaceDomain::normal(const Vec3& p) const {
  if (!p.allFinite()) return Vec3::UnitZ();
  const surface::ClosestPoint c = data_->closest.closest(p);
  return data_->geometry.normal(c.triangle, c.feature);
}

Box3 SurfaceDomain::bounds() const { return data_->bounds; }
std::vector<Index> SurfaceDomain::regions() const { return data_->regions; }
const std::vector<Index>& SurfaceDomain::labels() const { return data_->label; }
const std::vector<Index>& SurfaceDomain::depths() const { return data_->depth; }

TriSurface SurfaceDomain::surface(Index s) const {
  const surface::SurfaceGeometry& g = data_->geometry;
  TriSurface out;
  std::vector<Index> local(g.points.size(), kNoIndex);  // geometry point -> out's
  for (Index t = g.first_triangle.at(s); t < g.first_triangle.at(s + 1); ++t) {
    std::array<Index, 3>& c = out.triangles.emplace_back();
    for (int k = 0; k < 3; ++k) {
      Index& l = local[g.triangles[t][k]];
      if (l == kNoIndex) {
        l = out.num_points();
        out.points.push_back(g.points[g.triangles[t][k]]);
      }
      c[k] = l;
    }
  }
  return out;
}

}  // namespace volmesh
