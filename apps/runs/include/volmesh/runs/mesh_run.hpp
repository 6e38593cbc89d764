#pragma once
// `volmesh mesh` between its arguments and its output: the registry's mesher, timed; the
// validity check every mesh passes before it is handed on; the figures of --json. Also the
// uniform request of `solve --method` and the studies.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "volmesh/core/validity.hpp"
#include "volmesh/meshers/registry.hpp"

namespace volmesh::cli {

// The mesher's result and its own wall time (`time_seconds`).
struct TimedMesh {
  meshers::MeshResult result;
  double seconds = 0.0;
};
TimedMesh mesh_timed(const meshers::MesherInfo& info, const Domain& domain,
                     const meshers::MeshRequest& request);

// The same depth inside as at the boundary (MeshRequest::uniform), as a solve on a method's
// mesh and a convergence study take it.
meshers::MeshRequest uniform_request(std::string domain_name, int level,
                                     meshers::MethodOptions options, Progress progress);

// The validity report of a mesher's mesh; throws std::runtime_error "METHOD produced an
// invalid mesh of DOMAIN (first problem); nothing written" when it fails (a bug in the mesher).
ValidityReport require_valid_output(const PolyMesh& mesh, const std::string& method,
                                    const std::string& domain);

// Cells and volume per region, as `mesh --json` reports them.
nlohmann::json region_summary(const PolyMesh& mesh, const ValidityReport& validity);

// The request's part of `volmesh mesh --json`'s object: the method, domain, level or size,
// octree options and the mesher's time.
nlohmann::json request_summary(const std::string& method, const meshers::MeshRequest& request,
                               double seconds);

// `volmesh mesh --json`'s object but its output file, total time and decomposition: the
// method, domain, level or size, octree options, time_seconds, regions, validity and the
// mesher's own figures.
// `mesher_summary` and `seconds`: the mesher's own figures and time (TimedMesh).
nlohmann::json mesh_summary(const std::string& method, const meshers::MeshRequest& request,
                            const PolyMesh& mesh, const nlohmann::json& mesher_summary,
                            double seconds, const ValidityReport& validity);

}  // namespace volmesh::cli
