#pragma once
// `volmesh check` without its printing: validity, quality, and the distance of the mesh
// boundary to a reference, a surface or an analytic domain's true surfaces; its --json object.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "volmesh/core/progress.hpp"
#include "volmesh/core/tri_surface.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/quality/measurements.hpp"
#include "volmesh/quality/report.hpp"
#include "volmesh/quality/surface_distance.hpp"

namespace volmesh::cli {

// What the mesh is compared with.
struct Reference {
  std::string name;  // the --surface argument, or the surface's name
  std::unique_ptr<ReferenceSurface> surface;
  double volume = 0.0;  // 0 where not known
  double diagonal = 0.0;
  SurfaceDistanceOptions options;
};

// --surface S: a surface file, or an analytic domain (builtin:ball, a .json of solids), its
// samples sized by the mesh's mean cell. Throws InputError for anything else.
Reference open_reference(const std::string& spec, const ValidityReport& validity);
// A surface given as data; checked (closed, manifold) as a surface file is.
Reference surface_reference(TriSurface surface, const std::string& name);

struct SurfaceComparison {
  std::string name;
  double volume = 0.0;  // the reference's, 0 where not known
  double volume_error = 0.0;  // relative, where the volume is known
  double diagonal = 0.0;
  TwoSidedDistance distance;
  std::optional<double> sample_spacing;  // a sampled (analytic) reference's
};

struct MeshCheck {
  ValidityReport validity;
  // Absent when faces point at vertices or cells that do not exist.
  std::optional<QualityMeasurements> measured;
  std::optional<QualityReport> quality;
  std::optional<SurfaceComparison> surface;
};

// Validity, then (with valid indices) quality and the comparison with the reference that
// `reference` opens once the validity is known (none when it is empty).
using ReferenceOpener = std::function<Reference(const ValidityReport&)>;
MeshCheck check_mesh(const PolyMesh& mesh, const ReferenceOpener& reference,
                     const Progress& progress = {});

// `volmesh check --json`'s object; `file` names the mesh.
nlohmann::json to_json(const MeshCheck& check, const PolyMesh& mesh, const std::string& file);

}  // namespace volmesh::cli
