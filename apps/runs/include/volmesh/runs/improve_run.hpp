#pragma once
// `volmesh improve` between reading and writing: a mesh taken as tetrahedra, improved, checked
// again; its --json figures.
#include <nlohmann/json.hpp>
#include <string>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/tri_surface.hpp"
#include "volmesh/improve/improve.hpp"

namespace volmesh::cli {

// The mesh as tetrahedra, or InputError "NAME: ..." saying why it is none (invalid, a cell
// that is not a tetrahedron, an inverted one).
TetMesh tet_mesh_to_improve(const PolyMesh& mesh, const std::string& name);

// Improves `mesh` in place (its boundary points sliding on `surface` when it has triangles)
// and returns it as a PolyMesh; throws InputError "NAME: the improved mesh fails the check
// (...), not written" should it fail the validity check.
struct Improved {
  PolyMesh mesh;
  improve::ImproveStats stats;
};
Improved improve_checked(TetMesh mesh, const TriSurface& surface, double max_seconds,
                         const std::string& name, const Progress& progress = {});

// `volmesh improve --json`'s figures but its files and total time: before, after,
// operations, passes, timed_out, improve_seconds.
nlohmann::json improve_summary(const improve::ImproveStats& stats);

}  // namespace volmesh::cli
