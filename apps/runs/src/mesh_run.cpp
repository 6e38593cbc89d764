#include "volmesh/runs/mesh_run.hpp"

#include <map>
#include <stdexcept>

#include "volmesh/core/stopwatch.hpp"
#include "volmesh/octree/octree.hpp"
#include "volmesh/runs/reports.hpp"

namespace volmesh::cli {

TimedMesh mesh_timed(const meshers::MesherInfo& info, const Domain& domain,
                     const meshers::MeshRequest& request) {
  const Clock::time_point start = Clock::now();
  TimedMesh out{meshers::mesh(info, domain, request)};
  out.seconds = seconds_since(start);
  return out;
}

meshers::MeshRequest uniform_request(std::string domain_name, int level,
                                     meshers::MethodOptions options, Progress progress) {
  meshers::MeshRequest request;
  request.domain_name = std::move(domain_name);
  request.level = level;
  request.uniform = true;
  request.options = std::move(options);
  request.progress = std::move(progress);
  return request;
}

ValidityReport require_valid_output(const PolyMesh& mesh, const std::string& method,
                                    const std::string& domain) {
  ValidityReport validity = check_validity(mesh);
  if (!validity.valid())
    throw std::runtime_error(method + " produced an invalid mesh of " + domain + " (" +
                             (validity.problems.empty() ? std::string("see volmesh check")
                                                        : validity.problems.front()) +
                             "); nothing written");
  return validity;
}

nlohmann::json region_summary(const PolyMesh& mesh, const ValidityReport& validity) {
  std::map<Index, Index> cells;
  for (const Index r : mesh.cell_region) ++cells[r];
  nlohmann::json regions = nlohmann::json::object();
  for (const auto& [region, count] : cells) {
    const auto volume = validity.region_volume.find(region);
    regions[std::to_string(region)] = {
        {"cells", count},
        {"volume", volume == validity.region_volume.end() ? 0.0 : volume->second}};
  }
  return regions;
}

nlohmann::json request_summary(const std::string& method, const meshers::MeshRequest& request,
                               double seconds) {
  nlohmann::json j{{"method", method},
                   {"domain", request.domain_name},
                   {"base_level", meshers::given<std::int64_t>(request.options, "base-level")
                                      .value_or(OctreeOptions{}.base_level)},
                   {"cells_between_levels",
                    meshers::given<std::int64_t>(request.options, "cells-between-levels")
                        .value_or(OctreeOptions{}.cells_between_levels)},
                   {"time_seconds", seconds}};
  if (request.level) j["level"] = *request.level;
  if (request.size) j["size"] = *request.size;
  return j;
}

nlohmann::json mesh_summary(const std::string& method, const meshers::MeshRequest& request,
                            const PolyMesh& mesh, const nlohmann::json& mesher_summary,
                            double seconds, const ValidityReport& validity) {
  nlohmann::json j = request_summary(method, request, seconds);
  j["regions"] = region_summary(mesh, validity);
  j["validity"] = to_json(validity);
  j.update(mesher_summary);
  return j;
}

}  // namespace volmesh::cli
