#include "volmesh/runs/improve_run.hpp"

#include <string_view>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/improve/json.hpp"

namespace volmesh::cli {

namespace {

std::string first_problem(const ValidityReport& r) {
  return r.problems.empty() ? std::string("see volmesh check") : r.problems.front();
}

}  // namespace

TetMesh tet_mesh_to_improve(const PolyMesh& poly, const std::string& name) {
  const ValidityReport validity = check_validity(poly);
  if (!validity.valid()) throw InputError(name + ": invalid mesh (" + first_problem(validity) + ")");
  TetMesh mesh;
  try {
    mesh = to_tet_mesh(poly);
  } catch (const InputError& e) {
    // "mesh: cell N is not a tetrahedron (...)", said of the file.
    std::string what = e.what();
    constexpr std::string_view kPrefix = "mesh: ";
    if (what.starts_with(kPrefix)) what.erase(0, kPrefix.size());
    throw InputError(name + ": " + what);
  }
  improve::require_positive_tets(mesh, name);
  return mesh;
}

Improved improve_checked(TetMesh mesh, const TriSurface& surface, double max_seconds,
                         const std::string& name, const Progress& progress) {
  improve::ImproveOptions options;
  options.max_seconds = max_seconds;
  if (surface.num_triangles() > 0) options.slides = improve::slides_on_surface(mesh, surface);
  options.progress = progress;
  Improved out;
  out.stats = improve::improve_tet_mesh(mesh, options);
  out.mesh = to_poly_mesh(mesh);
  const ValidityReport validity = check_validity(out.mesh);
  if (!validity.valid())
    throw InputError(name + ": the improved mesh fails the check (" + first_problem(validity) +
                     "), not written");
  return out;
}

nlohmann::json improve_summary(const improve::ImproveStats& stats) {
  nlohmann::json j = improve::stats_json(stats);
  j["improve_seconds"] = stats.seconds;
  return j;
}

}  // namespace volmesh::cli
