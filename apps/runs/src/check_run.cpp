#include "volmesh/runs/check_run.hpp"

#include <cmath>

#include "volmesh/core/errors.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/quality/analytic_surfaces.hpp"
#include "volmesh/runs/reports.hpp"

namespace volmesh::cli {

namespace {

// Where the steps start on the progress bar.
constexpr double kValidityStart = 0.1, kQualityStart = 0.2, kDistanceStart = 0.4;

// Against a triangulated surface, the accuracy of the reported Hausdorff distance as a
// fraction of the diagonal.
constexpr double kHausdorffBound = 1e-6;
// Against an analytic domain, samples this many times finer than the mean cell size (the
// cell edge of a uniform octree mesh), as validation/geometry samples.
constexpr double kSamplesPerCell = 6.0;

SurfaceComparison compare(const PolyMesh& mesh, const ValidityReport& validity,
                          const Reference& r) {
  SurfaceComparison c;
  c.name = r.name;
  c.volume = r.volume;
  c.volume_error = (validity.total_volume - r.volume) / r.volume;
  c.diagonal = r.diagonal;
  c.distance = surface_distance(mesh, *r.surface, r.options).all;
  if (r.surface->triangulation() == nullptr) c.sample_spacing = r.options.tolerance;
  return c;
}

}  // namespace

Reference surface_reference(TriSurface surface, const std::string& name) {
  Reference r;
  r.name = name;
  r.volume = check_surface(surface, name).volume;
  r.diagonal = bounding_box(surface.points).diagonal();
  r.options = {.tolerance = kHausdorffBound * r.diagonal, .interfaces = false};
  r.surface = std::make_unique<TriangulatedSurface>(std::move(surface));
  return r;
}

Reference open_reference(const std::string& spec, const ValidityReport& validity) {
  if (is_surface_file(spec)) return surface_reference(read_surface(spec), spec);
  Reference r;
  r.name = spec;
  const std::unique_ptr<Domain> domain = open_domain(spec);
  const auto* analytic = dynamic_cast<const AnalyticDomain*>(domain.get());
  if (!analytic)
    throw InputError(spec + ": not analytic: --surface takes a surface file (.stl .off .obj "
                            ".ply) or an analytic domain (builtin:ball, a .json of solids)");
  for (const auto& [region, volume] : exact_region_volumes(spec, *domain)) r.volume += volume;
  r.diagonal = domain->bounds().size().norm();
  const double cell = std::cbrt(std::abs(validity.total_volume) / static_cast<double>(validity.cells));
  if (!(cell > 0.0))
    throw InputError("--surface " + spec + ": the mesh has no volume to size the samples by");
  r.options = {.tolerance = cell / kSamplesPerCell, .interfaces = true};
  r.surface = std::make_unique<AnalyticSurfaces>(*analytic);
  return r;
}

MeshCheck check_mesh(const PolyMesh& mesh, const ReferenceOpener& reference,
                     const Progress& progress) {
  MeshCheck out;
  report(progress, "validity", kValidityStart);
  out.validity = check_validity(mesh);
  // Geometry is meaningless when faces point at vertices or cells that do not exist.
  if (out.validity.bad_indices != 0) return out;
  report(progress, "quality", kQualityStart);
  out.measured = measure_quality(mesh);
  out.quality = quality_report(mesh, *out.measured);
  if (!reference) return out;
  const Reference r = reference(out.validity);
  report(progress, "distance to " + r.name, kDistanceStart);
  out.surface = compare(mesh, out.validity, r);
  return out;
}

nlohmann::json to_json(const MeshCheck& check, const PolyMesh& mesh, const std::string& file) {
  nlohmann::json j{{"file", file},
                   {"validity", to_json(check.validity)},
                   {"bounding_box", to_json(bounding_box(mesh.points))}};
  if (check.quality) j["quality"] = to_json(*check.quality);
  if (check.surface) {
    const SurfaceComparison& c = *check.surface;
    const TwoSidedDistance& d = c.distance;
    nlohmann::json s{{"file", c.name},
                     {"diagonal", c.diagonal},
                     {"hausdorff", d.hausdorff()},
                     {"hausdorff_relative", d.hausdorff() / c.diagonal},
                     {"hausdorff_mesh_to_surface", d.mesh_to_surface.distance},
                     {"hausdorff_surface_to_mesh", d.surface_to_mesh.distance}};
    if (c.volume > 0.0) {
      s["surface_volume"] = c.volume;
      s["volume_error"] = c.volume_error;
    }
    if (c.sample_spacing) s["sample_spacing"] = *c.sample_spacing;
    j["surface"] = s;
  }
  return j;
}

}  // namespace volmesh::cli
