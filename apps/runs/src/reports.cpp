#include "volmesh/runs/reports.hpp"

#include <iomanip>

namespace volmesh::cli {

namespace {

void print_nonzero(std::ostream& os, std::initializer_list<std::pair<const char*, Index>> counts) {
  for (const auto& [what, n] : counts)
    if (n > 0) os << "  " << what << ": " << n << "\n";
}

}  // namespace

nlohmann::json to_json(const Box& b) {
  return {{"min", {b.lo.x(), b.lo.y(), b.lo.z()}},
          {"max", {b.hi.x(), b.hi.y(), b.hi.z()}},
          {"diagonal", b.diagonal()}};
}

nlohmann::json to_json(const ValidityReport& r) {
  nlohmann::json regions = nlohmann::json::object();
  for (const auto& [region, volume] : r.region_volume) regions[std::to_string(region)] = volume;
  return {{"valid", r.valid()},
          {"cells", r.cells},
          {"faces", r.faces},
          {"points", r.points},
          {"boundary_faces", r.boundary_faces},
          {"bad_indices", r.bad_indices},
          {"degenerate_faces", r.degenerate_faces},
          {"open_cells", r.open_cells},
          {"unmatched_cell_edges", r.unmatched_cell_edges},
          {"non_positive_cells", r.non_positive_cells},
          {"duplicate_faces", r.duplicate_faces},
          {"bad_face_order", r.bad_face_order},
          {"open_region_boundary_edges", r.open_region_boundary_edges},
          {"unused_points", r.unused_points},
          {"total_volume", r.total_volume},
          {"min_cell_volume", r.min_cell_volume},
          {"max_cell_volume", r.max_cell_volume},
          {"max_closedness", r.max_closedness},
          {"region_volume", regions},
          {"problems", r.problems}};
}

nlohmann::json to_json(const SurfaceReport& r) {
  nlohmann::json pairs = nlohmann::json::array();
  for (const auto& [a, b] : r.self_intersections) pairs.push_back({a, b});
  return {{"points", r.points},
          {"triangles", r.triangles},
          {"components", r.components},
          {"unused_points", r.unused_points},
          {"closed", true},
          {"manifold", true},
          {"flipped", r.flipped},
          {"area", r.area},
          {"volume", r.volume},
          {"self_intersections", pairs},
          {"self_intersections_truncated", r.self_intersections_truncated},
          {"warnings", r.warnings}};
}

nlohmann::json to_json(const QualityReport& r) {
  nlohmann::json metrics = nlohmann::json::object();
  for (const MetricSummary& m : r.metrics)
    metrics[m.name] = {{"count", m.count},
                       {"min", m.min},
                       {"max", m.max},
                       {"mean", m.mean},
                       {"histogram",
                        {{"lo", m.histogram.lo}, {"hi", m.histogram.hi}, {"counts", m.histogram.counts}}}};
  return {{"cells", r.cells},
          {"tets", r.tets},
          {"hexes", r.hexes},
          {"polyhedra", r.polyhedra},
          {"inverted_tets", r.inverted_tets},
          {"inverted_hexes", r.inverted_hexes},
          {"degenerate_hexes", r.degenerate_hexes},
          {"non_positive_cells", r.non_positive_cells},
          {"severely_non_orthogonal_faces", r.severely_non_orthogonal_faces},
          {"highly_skewed_faces", r.highly_skewed_faces},
          {"non_orthogonality_errors", r.non_orthogonality_errors},
          {"inverted_face_pyramids", r.inverted_face_pyramids},
          {"min_volume", r.min_volume},
          {"max_neighbour_volume_ratio", r.max_neighbour_volume_ratio},
          {"metrics", metrics}};
}

nlohmann::json surface_info(const SurfaceReport& report, const TriSurface& surface) {
  return {{"kind", "surface"},
          {"surface", to_json(report)},
          {"bounding_box", to_json(bounding_box(surface.points))}};
}

void print_quality(std::ostream& os, const QualityReport& r) {
  os << "quality: " << r.tets << " tets, " << r.hexes << " hexes, " << r.polyhedra
     << " polyhedra\n";
  print_nonzero(os, {{"inverted tets", r.inverted_tets},
                     {"inverted hexes", r.inverted_hexes},
                     {"degenerate hexes", r.degenerate_hexes},
                     {"faces non-orthogonal beyond 70 degrees", r.severely_non_orthogonal_faces},
                     {"faces with skewness above 4", r.highly_skewed_faces},
                     {"faces non-orthogonal at 90 degrees or more (checkMesh fails)",
                      r.non_orthogonality_errors},
                     {"inverted face pyramids, a cell centre behind a face (checkMesh's incorrectly "
                      "oriented faces: fails)",
                      r.inverted_face_pyramids}});
  os << std::setprecision(6);
  for (const MetricSummary& m : r.metrics) {
    if (m.count == 0) continue;
    os << "  " << std::left << std::setw(28) << m.name << std::right << " min " << std::setw(12)
       << m.min << "  max " << std::setw(12) << m.max << "  mean " << std::setw(12) << m.mean
       << "  (" << m.count << ")\n";
  }
}

void print_validity(std::ostream& os, const ValidityReport& r) {
  os << "cells " << r.cells << ", faces " << r.faces << " (" << r.boundary_faces
     << " on the boundary), points " << r.points << "\n";
  os << std::setprecision(12) << "volume " << r.total_volume << " (cells from "
     << r.min_cell_volume << " to " << r.max_cell_volume << ")\n";
  for (const auto& [region, volume] : r.region_volume)
    os << "  region " << region << ": volume " << volume << "\n";
  os << "validity: " << (r.valid() ? "OK" : "INVALID") << "\n";
  print_nonzero(os, {{"indices out of range", r.bad_indices},
                     {"degenerate faces", r.degenerate_faces},
                     {"open cells", r.open_cells},
                     {"cells with unmatched edges", r.unmatched_cell_edges},
                     {"cells with volume <= 0", r.non_positive_cells},
                     {"duplicate faces", r.duplicate_faces},
                     {"faces with owner == neighbour", r.bad_face_order},
                     {"open edges of region boundaries", r.open_region_boundary_edges},
                     {"unused points (not an error)", r.unused_points}});
  for (const auto& p : r.problems) os << "  - " << p << "\n";
}

void print_surface(std::ostream& os, const SurfaceReport& r) {
  os << "triangles " << r.triangles << ", points " << r.points << ", components "
     << r.components << "\n";
  os << "closed, manifold, consistently oriented" << (r.flipped ? " (was inward: flipped)" : "")
     << "\n";
  os << std::setprecision(12) << "area " << r.area << ", enclosed volume " << r.volume << "\n";
  if (r.self_intersections.empty()) {
    os << "no self-intersections\n";
  } else {
    os << "self-intersections" << (r.self_intersections_truncated ? " (first ones)" : "") << ":";
    for (const auto& [a, b] : r.self_intersections)
      os << " triangles " << a << " and " << b << ";";
    os << "\n";
  }
  for (const auto& w : r.warnings) os << "warning: " << w << "\n";
}

}  // namespace volmesh::cli
