// tetrahedralize_by_front: one front per surface (its inside, less the surfaces nested
// directly in it), then the stalled cavities closed (fallback.hpp), then the mesh improved
// (volmesh/improve).
#include "volmesh/tet_front/front.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "advance.hpp"
#include "aux_grid.hpp"
#include "delaunay_core.hpp"
#include "fallback.hpp"
#include "nesting.hpp"
#include "size_field.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/improve/improve.hpp"
#include "volmesh/improve/slides.hpp"

namespace volmesh::tet {

namespace {

using Tri = std::array<Index, 3>;

// Bisection steps for the smallest size allowed: a relative precision of 2^-40.
constexpr int kBisections = 40;
// Significant digits of the sizes and counts in the messages.
constexpr int kDigits = 4;
constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
// The share of the progress bar the improver takes, after the fronts.
constexpr double kImproveShare = 0.2;

// The outermost surfaces' triangles as one surface: the boundary the fallback's points on it
// may slide in.
TriSurface outer_boundary(const std::vector<ProjectionSurface>& surfaces) {
  TriSurface out;
  for (const ProjectionSurface& s : surfaces) {
    if (!s.outermost) continue;
    const Index first = out.num_points();
    out.points.insert(out.points.end(), s.surface.points.begin(), s.surface.points.end());
    for (const Tri& t : s.surface.triangles)
      out.triangles.push_back({first + t[0], first + t[1], first + t[2]});
  }
  return out;
}

// Improves the finished mesh, whose tets are labelled by the surface whose region they fill:
// every surface's triangles (or their pieces) then lie between two labels or on the boundary,
// so the improver keeps them all, even between two surfaces of one region.
improve::ImproveStats improve_front_mesh(TetMesh& m, const std::vector<ProjectionSurface>& surfaces,
                                         const Progress& progress) {
  improve::ImproveOptions options;
  options.slides = improve::slides_on_surface(m, outer_boundary(surfaces));
  options.progress = progress;
  return improve::improve_tet_mesh(m, options);
}

// The region's Delaunay core into the mesh, its tets labelled `label`, and its boundary into
// the region's front `faces` (facing away from the core). The core is a hole in the region as
// the front sees it: the front's auxiliary points inside the core's boundary are never alive.
void add_core(TetMesh& m, std::vector<Tri>& faces, Index label, const front::SizeField& field,
              const Progress& progress, FrontStats& stats) {
  const front::Core core = front::delaunay_core(m.points, faces, field.cap(), progress, &field);
  const Index first = m.num_points();
  m.points.insert(m.points.end(), core.points.begin(), core.points.end());
  for (const auto& t : core.tets)
    m.cells.push_back({first + t[0], first + t[1], first + t[2], first + t[3]});
  m.cell_region.insert(m.cell_region.end(), core.tets.size(), label);
  for (const Tri& t : core.faces) faces.push_back({first + t[0], first + t[1], first + t[2]});
  stats.core_points += static_cast<long long>(core.points.size());
  stats.core_tets += static_cast<long long>(core.tets.size());
}

std::string text(double x) {
  std::ostringstream out;
  out.precision(kDigits);
  out << x;
  return out.str();
}

// Refuses a graded size field whose auxiliary cells over the surfaces' box would hold more
// points than fit in their memory.
void require_front_cells(const std::vector<ProjectionSurface>& surfaces,
                         const std::vector<Vec3>& points, const std::vector<Tri>& triangles,
                         const front::SizeField& field, int aux_ratio) {
  Vec3 lo = points[triangles.front()[0]], hi = lo;
  for (const Tri& t : triangles)
    for (const Index v : t) {
      lo = lo.cwiseMin(points[v]);
      hi = hi.cwiseMax(points[v]);
    }
  const double needed = front::aux_points_needed(lo, hi, field, aux_ratio);
  if (needed <= front::kMaxAuxPoints) return;
  throw InputError("tet-front: " +
                   (surfaces.size() == 1 ? surfaces.front().name : std::string("its surfaces")) +
                   ": the graded sizes (from " + text(field.min()) + " at the boundary to " +
                   text(field.cap()) + ") need more than " + text(front::kMaxAuxPoints) +
                   " auxiliary points at --aux-ratio " + std::to_string(aux_ratio) +
                   ", more than fit in " + text(front::kMaxAuxBytes / kGiB) +
                   " GiB; a coarser boundary or a larger --interior-size needs fewer");
}

}  // namespace

void require_front_size(const std::string& name, double h, int aux_ratio, const Vec3& lo,
                        const Vec3& hi) {
  const std::string head = "tet-front: " + name + ": --size " + text(h);
  if (!(h > 0.0) || !std::isfinite(h)) throw InputError(head + " is not a positive, finite length");
  const double diagonal = (hi - lo).norm();
  if (h > diagonal)
    throw InputError(head + " is absurd: longer than the boundary's bounding-box diagonal, " +
                     text(diagonal) + ", the largest size allowed");
  const auto points = [&](double size) { return front::aux_grid_points(lo, hi, size / aux_ratio); };
  if (points(h) <= front::kMaxAuxPoints) return;
  // The smallest size whose grid fits: the count falls as the size grows, and the diagonal fits.
  double small = h, large = std::max(h, diagonal);
  for (int i = 0; i < kBisections; ++i) {
    const double mid = std::sqrt(small * large);
    (points(mid) <= front::kMaxAuxPoints ? large : small) = mid;
  }
  // Rounded up, so that the size printed is allowed.
  const double unit = std::pow(10.0, std::floor(std::log10(large)) - (kDigits - 1));
  throw InputError(head + " is too small: it needs " + text(points(h)) +
                   " auxiliary points at --aux-ratio " + std::to_string(aux_ratio) +
                   ", more than the " + text(front::kMaxAuxPoints) +
                   " that fit in " + text(front::kMaxAuxBytes / kGiB) +
                   " GiB; the smallest size allowed is " +
                   text(std::ceil(large / unit) * unit));
}

void require_front_interior_size(const std::string& name, double interior, double h,
                                 const Vec3& lo, const Vec3& hi) {
  const std::string head = "tet-front: " + name + ": --interior-size " + text(interior);
  if (!(interior > 0.0) || !std::isfinite(interior))
    throw InputError(head + " is not a positive, finite length");
  if (interior < h) throw InputError(head + " is smaller than --size " + text(h));
  const double diagonal = (hi - lo).norm();
  if (interior > diagonal)
    throw InputError(head + " is absurd: longer than the boundary's bounding-box diagonal, " +
                     text(diagonal) + ", the largest size allowed");
}

FrontResult tetrahedralize_by_front(const std::vector<ProjectionSurface>& surfaces,
                                    const FrontOptions& options, const Progress& progress) {
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
  // Each region's auxiliary grid lies in the box of all the surfaces, one grid at a time.
  if (!m.points.empty()) {
    Vec3 lo = m.points.front(), hi = lo;
    for (const Vec3& p : m.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    require_front_size(surfaces.size() == 1 ? surfaces.front().name : "its surfaces",
                       options.size, options.aux_ratio, lo, hi);
    if (options.interior_size != 0.0)
      require_front_interior_size(surfaces.size() == 1 ? surfaces.front().name : "its surfaces",
                                  options.interior_size, options.size, lo, hi);
  }
  // The local size, from every surface's triangles; the auxiliary cells of all the surfaces'
  // box must fit.
  std::vector<Tri> all;
  for (const auto& tris : outward) all.insert(all.end(), tris.begin(), tris.end());
  const front::SizeField field(m.points, all, options.size, options.interior_size);
  r.stats.size_min = field.min();
  r.stats.size_max = field.cap();
  r.stats.grading_rate = field.rate();
  if (!all.empty()) require_front_cells(surfaces, m.points, all, field, options.aux_ratio);
  const std::vector<Index> parent = front::parents(m.points, outward);
  const double front_share = options.improve ? 1.0 - kImproveShare : 1.0;
  double interior_seconds = 0.0, front_seconds = 0.0, fallback_seconds = 0.0;
  std::vector<std::vector<Tri>> cavities(surfaces.size());
  // Tets are labelled by their surface's index until the end (improve_front_mesh).
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    const auto clock = Clock::now();
    std::vector<Tri> faces;
    for (const Tri& t : outward[s]) faces.push_back({t[0], t[2], t[1]});
    for (std::size_t c = 0; c < surfaces.size(); ++c)
      if (parent[c] == static_cast<Index>(s))
        faces.insert(faces.end(), outward[c].begin(), outward[c].end());
    const double begin = front_share * double(s) / double(surfaces.size());
    const Progress part = part_of(progress, begin, begin + front_share / double(surfaces.size()),
                                  surfaces[s].name + ": ");
    if (options.interior == Interior::delaunay) {
      add_core(m, faces, static_cast<Index>(s), field, part, r.stats);
      interior_seconds += seconds_since(clock);
    }
    const auto front_clock = Clock::now();
    front::RegionFront region = front::advance_front(m.points, faces, options, field, part);
    r.stats.front_tets += static_cast<long long>(region.tets.size());
    r.stats.new_nodes += region.new_nodes;
    r.stats.existing_node_tets += region.existing_node_tets;
    r.stats.relaxed_tets += region.relaxed_tets;
    r.stats.aux_points += region.aux_points;
    r.stats.aux_deleted += region.aux_deleted;
    m.cells.insert(m.cells.end(), region.tets.begin(), region.tets.end());
    m.cell_region.insert(m.cell_region.end(), region.tets.size(), static_cast<Index>(s));
    cavities[s] = std::move(region.cavity);
    front_seconds += seconds_since(front_clock);
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
    front::close_cavity(m, static_cast<Index>(s), cavities[s], loose, splits, r.stats);
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
  if (options.improve)
    r.stats.improve =
        improve_front_mesh(m, surfaces, part_of(progress, front_share, 1.0));
  for (Index& region : m.cell_region) region = surfaces[region].label;
  r.stats.tets = m.num_cells();
  r.stats.nodes = m.num_points();
  r.stats.seconds = {
      {"interior", interior_seconds}, {"front", front_seconds}, {"fallback", fallback_seconds}};
  return r;
}

}  // namespace volmesh::tet
