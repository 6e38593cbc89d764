#pragma once
// Reports shared by `info` and `check`: JSON objects for --json and readable text.
#include <nlohmann/json.hpp>
#include <ostream>

#include "volmesh/runs/mesh_input.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/quality/report.hpp"

namespace volmesh::cli {

nlohmann::json to_json(const ValidityReport& r);
nlohmann::json to_json(const SurfaceReport& r);
nlohmann::json to_json(const Box& b);
nlohmann::json to_json(const QualityReport& r);

// `info --json`'s object of a checked surface but its file: kind, report, bounding box.
nlohmann::json surface_info(const SurfaceReport& report, const TriSurface& surface);

void print_validity(std::ostream& os, const ValidityReport& r);
void print_surface(std::ostream& os, const SurfaceReport& r);
void print_quality(std::ostream& os, const QualityReport& r);

}  // namespace volmesh::cli
