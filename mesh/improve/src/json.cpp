#include "volmesh/improve/json.hpp"

namespace volmesh::improve {

nlohmann::json to_json(const QualitySummary& q) {
  return {{"tets", q.tets},
          {"points", q.points},
          {"min_dihedral_deg", q.min_dihedral_deg},
          {"max_dihedral_deg", q.max_dihedral_deg},
          {"tets_below_10_deg", q.below_10_degrees},
          {"max_radius_edge", q.max_radius_edge},
          {"min_sine", q.min_quality}};
}

nlohmann::json to_json(const OperationCounts& o) {
  return {{"smoothed", o.smoothed},           {"slid", o.slid},
          {"flips_3_2", o.flips_3_2},         {"flips_4_4", o.flips_4_4},
          {"edge_removals", o.edge_removals}, {"flips_2_3", o.flips_2_3},
          {"face_removals", o.face_removals}, {"contractions", o.contractions},
          {"insertions", o.insertions}};
}

nlohmann::json stats_json(const ImproveStats& s) {
  return {{"before", to_json(s.before)},
          {"after", to_json(s.after)},
          {"operations", to_json(s.operations)},
          {"passes", s.passes},
          {"timed_out", s.timed_out}};
}

}  // namespace volmesh::improve
