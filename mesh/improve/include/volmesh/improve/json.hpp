#pragma once
// The improver's figures as JSON, named alike wherever they are reported (`volmesh improve
// --json`, tet-front's and tet-projection's `improve` blocks).
#include <nlohmann/json.hpp>

#include "volmesh/improve/improve.hpp"

namespace volmesh::improve {

nlohmann::json to_json(const QualitySummary& q);
nlohmann::json to_json(const OperationCounts& o);

// before, after, operations, passes and timed_out; the caller adds its own timing.
nlohmann::json stats_json(const ImproveStats& s);

}  // namespace volmesh::improve
