// tetrahedralize_by_front: one front per surface (its inside, less the surfaces nested
// directly in it), then the stalled cavities closed (fallback.hpp).
#include "volmesh/tet/front.hpp"

#include <string>

#include "advance.hpp"
#include "fallback.hpp"
#include "improve.hpp"
#include "nesting.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"

namespace volmesh::tet {

namespace {

using Tri = std::array<Index, 3>;

// More auxiliary points than this (a gigabit) is an absurd h for the domain.
constexpr double kMaxAuxPoints = 1e9;

}  // namespace

FrontResult tetrahedralize_by_front(const std::vector<ProjectionSurface>& surfaces,
                                    const FrontOptions& options, const Progress& progress) {
  if (!(options.size > 0.0))
    throw InputError("tet-front: --size " + std::to_string(options.size) + " must be positive");
  FrontResult r;
  TetMesh& m = r.mesh;
  std::vector<std::vector<Tri>> outward;
  for (const ProjectionSurface& s : surfaces) {
    const Index first = m.num_points();
    m.points.insert(m.points.end(), s.surface.points.begin(), s.surface.points.end());
    std::vector<Tri> tris;
    for (const Tri& t : s.surface.triangles) tris.push_back({first + t[0], first + t[1], first + t[2]});
    outward.push_back(std::move(tris));
  }
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    Vec3 lo = m.points[outward[s].front()[0]], hi = lo;
    for (const Tri& t : outward[s])
      for (const Index v : t) {
        lo = lo.cwiseMin(m.points[v]);
        hi = hi.cwiseMax(m.points[v]);
      }
    const double step = options.size / options.aux_ratio;
    const Vec3 cells = (hi - lo) / step;
    if ((cells.x() + 3) * (cells.y() + 3) * (cells.z() + 3) > kMaxAuxPoints)
      throw InputError("tet-front: --size " + std::to_string(options.size) + " is too small for " +
                       surfaces[s].name + " (more than 1e9 auxiliary points at --aux-ratio " +
                       std::to_string(options.aux_ratio) + ")");
  }
  const std::vector<Index> parent = front::parents(m.points, outward);
  double front_seconds = 0.0, fallback_seconds = 0.0;
  std::vector<std::vector<Tri>> cavities(surfaces.size());
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    const auto clock = Clock::now();
    std::vector<Tri> faces;
    for (const Tri& t : outward[s]) faces.push_back({t[0], t[2], t[1]});
    for (std::size_t c = 0; c < surfaces.size(); ++c)
      if (parent[c] == static_cast<Index>(s))
        faces.insert(faces.end(), outward[c].begin(), outward[c].end());
    const double begin = double(s) / double(surfaces.size());
    front::RegionFront region = front::advance_front(
        m.points, faces, options,
        part_of(progress, begin, begin + 1.0 / double(surfaces.size()), surfaces[s].name + ": "));
    r.stats.front_tets += static_cast<long long>(region.tets.size());
    r.stats.new_nodes += region.new_nodes;
    r.stats.existing_node_tets += region.existing_node_tets;
    r.stats.relaxed_tets += region.relaxed_tets;
    r.stats.aux_points += region.aux_points;
    r.stats.aux_deleted += region.aux_deleted;
    m.cells.insert(m.cells.end(), region.tets.begin(), region.tets.end());
    m.cell_region.insert(m.cell_region.end(), region.tets.size(), surfaces[s].label);
    cavities[s] = std::move(region.cavity);
    front_seconds += seconds_since(clock);
  }
  // The cavities are closed once every front has stopped: closing one may cut faces and
  // edges of any region's tets, of the surfaces and of the cavities still open.
  const auto clock = Clock::now();
  front::FaceSplits splits;
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    if (cavities[s].empty()) continue;
    std::vector<Tri> loose;
    for (const auto& surface : outward)
      for (const Tri& t : surface) splits.resolve(t, loose);
    for (std::size_t o = s + 1; o < surfaces.size(); ++o)
      for (const Tri& t : cavities[o]) splits.resolve(t, loose);
    front::close_cavity(m, surfaces[s].label, cavities[s], loose, splits, r.stats);
  }
  fallback_seconds += seconds_since(clock);
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    m.tag_names.push_back(surfaces[s].name);
    if (!surfaces[s].outermost) continue;
    for (const Tri& t : outward[s]) {
      const std::size_t before = m.boundary_faces.size();
      splits.resolve(t, m.boundary_faces);
      r.stats.split_boundary_faces += m.boundary_faces.size() - before > 1;
    }
    m.boundary_tag.resize(m.boundary_faces.size(), static_cast<Index>(s));
  }
  if (options.improve) {
    // The surfaces' triangles as the fallback left them: pieces where it cut them, whose new
    // corners lie on the surface and are pinned with the rest.
    std::vector<Tri> kept;
    for (const std::vector<Tri>& tris : outward)
      for (const Tri& t : tris) splits.resolve(t, kept);
    Index surface_points = 0;
    for (const ProjectionSurface& s : surfaces) surface_points += s.surface.num_points();
    r.stats.improve = front::improve_mesh(m, surface_points, kept);
  }
  r.stats.tets = m.num_cells();
  r.stats.nodes = m.num_points();
  r.stats.seconds = {{"front", front_seconds}, {"fallback", fallback_seconds}};
  return r;
}

}  // namespace volmesh::tet
