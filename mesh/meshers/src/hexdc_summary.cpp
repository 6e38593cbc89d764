#include "hexdc_summary.hpp"

#include <string>

namespace volmesh::meshers {
namespace {

// One column of the paper's Table 1: the mesh after a stage, and the stage's time.
nlohmann::json stage_row(const HexMeshStats& s, double seconds) {
  nlohmann::json valence = nlohmann::json::object();
  for (const auto& [hexes, nodes] : s.valence) valence[std::to_string(hexes)] = nodes;
  return {{"nodes", s.nodes},
          {"cells", s.cells},
          {"max_edge", s.max_edge},
          {"min_edge", s.min_edge},
          {"max_aspect_ratio", s.max_aspect_ratio},
          {"max_quad_distortion_deg", s.max_quad_distortion_deg},
          {"degenerate_hexes", s.degenerate},
          {"valence", valence},
          {"min_scaled_jacobian", s.min_scaled_jacobian},
          {"mean_scaled_jacobian", s.mean_scaled_jacobian},
          {"seconds", seconds}};
}

nlohmann::json refinement_summary(const RefineStats& stats) {
  const auto by_case = [&](RefineCase c) { return stats.hexes_by_case[static_cast<std::size_t>(c)]; };
  return {{"hexes_before", stats.hexes_before},
          {"hexes_after", stats.hexes_after},
          {"nodes_before", stats.nodes_before},
          {"nodes_after", stats.nodes_after},
          {"marked_nodes", stats.marked_given},
          {"marked_nodes_after_closure", stats.marked_after_closure},
          {"closure_passes", stats.closure_passes},
          {"hexes_by_template",
           {{"none", by_case(RefineCase::none)},
            {"node", by_case(RefineCase::node)},
            {"edge", by_case(RefineCase::edge)},
            {"face", by_case(RefineCase::face)},
            {"full", by_case(RefineCase::full)}}}};
}

// The automatic refinement of thin and curved parts; growth is the final mesh's hexes over what
// they would be without it (the buffer layer adds one hex per boundary quad).
nlohmann::json thin_summary(const ThinRefineStats& t, const ThinChoice& c) {
  const Index before = t.hexes_before + t.boundary_quads_before;
  return {{"tried", c.tried},
          {"kept", c.kept},
          {"min_scaled_jacobian_without", c.min_scaled_jacobian_without},
          {"min_scaled_jacobian_with", c.min_scaled_jacobian_with},
          {"thin_hexes", t.thin_hexes},
          {"thin_hexes_refined", t.thin_refined},
          {"curved_hexes", t.curved_hexes},
          {"curved_hexes_refined", t.curved_refined},
          {"skipped_collapsed", t.skipped_collapsed},
          {"hexes_before", t.hexes_before},
          {"hexes_after", t.hexes_after},
          {"boundary_quads_before", t.boundary_quads_before},
          {"boundary_quads_after", t.boundary_quads_after},
          {"growth", before > 0 ? static_cast<double>(t.hexes_after + t.boundary_quads_after) /
                                      static_cast<double>(before)
                                : 1.0},
          {"marked_nodes_after_closure", t.refinement.marked_after_closure}};
}

// The global optimiser's figures.
nlohmann::json optimisation_summary(const OptimiseStats& o) {
  return {{"boundary_nodes", o.boundary_nodes},
          {"crease_nodes", o.crease_nodes},
          {"corner_nodes", o.corner_nodes},
          {"held_off_surface", o.held_off_surface},
          {"features_released", o.features_released},
          {"reverted", o.reverted},
          {"untangle_rounds", o.untangle_rounds},
          {"untangle_iterations", o.untangle_iterations},
          {"quality_iterations", o.quality_iterations},
          {"negative_tets_before", o.invalid_tets_before},
          {"negative_tets_after", o.invalid_tets_after},
          {"untangle_energy_before", o.untangle_energy_before},
          {"untangle_energy_after", o.untangle_energy_after},
          {"quality_energy_before", o.quality_energy_before},
          {"quality_energy_after", o.quality_energy_after},
          {"min_tet_quality_before", o.min_quality_before},
          {"min_tet_quality_after", o.min_quality_after},
          {"min_scaled_jacobian_before", o.min_scaled_jacobian_before},
          {"min_scaled_jacobian_after", o.min_scaled_jacobian_after},
          {"seconds", o.seconds}};
}

// The input's creases and corners and how the buffer layer follows them (features.hpp).
nlohmann::json features_summary(const HexdcResult& r) {
  std::size_t chain_edges = 0;
  for (const FeatureChain& chain : r.feature_layer.chains) chain_edges += chain.nodes.size() - 1;
  return {{"creases", r.capture.creases},
          {"creases_captured", r.capture.captured},
          {"creases_captured_after_projection", r.capture_projected.captured},
          {"max_crease_distance_per_edge", r.capture.max_relative_distance},
          {"chains", r.feature_layer.chains.size()},
          {"chain_edges", chain_edges},
          {"pinned_nodes", r.feature_layer.pinned.size()},
          {"pinned_off_after_projection", r.projection.pinned_held_back},
          {"pinned_in_optimisation", r.optimisation.pinned_nodes},
          {"pinned_off_features", r.optimisation.pinned_off_features},
          {"patches_pillowed", r.feature_layer.patches_pillowed},
          {"strip_hexes", r.feature_layer.strip_hexes}};
}

}  // namespace

nlohmann::json hexdc_summary(const HexdcResult& r) {
  const PillowStats& pillow = r.pillow;
  const ProjectStats& projection = r.projection;
  nlohmann::json summary = {
      {"nodes_per_axis", r.contouring.nodes_per_axis},
      {"interior_vertices", r.contouring.interior_vertices},
      {"boundary_vertices", r.contouring.boundary_vertices},
      {"qef_fallbacks", r.contouring.qef_fallbacks},
      {"pillow",
       {{"copies", pillow.boundary_nodes},
        {"hexes", pillow.pillow_hexes},
        {"shrunk_copies", pillow.shrunk_copies},
        {"two_boundary_faces_before", pillow.multi_boundary_hexes_before},
        {"two_boundary_faces_after", pillow.multi_boundary_hexes_after},
        {"degenerate_after", pillow.invalid_hexes_after}}},
      {"refinement", refinement_summary(r.refinement)},
      {"thin_refinement", thin_summary(r.thin, r.thin_choice)},
      {"optimisation", optimisation_summary(r.optimisation)},
      {"projection",
       {{"nodes_projected", projection.projected},
        {"nodes_kept_on_features", projection.feature_nodes},
        {"nodes_held_back", projection.held_back},
        {"max_distance_before", projection.max_distance_before},
        {"max_distance_left", projection.max_distance_left},
        {"max_feature_distance", projection.max_feature_distance},
        {"min_scaled_jacobian_before", projection.min_scaled_jacobian_before},
        {"min_scaled_jacobian_after", projection.min_scaled_jacobian_after},
        {"seconds", r.project_seconds}}}};
  summary["features"] = features_summary(r);
  // The paper's Table 1 columns: uniform, refined (when asked), improved.
  nlohmann::json& stages = summary["stages"];
  stages["uniform"] = stage_row(r.uniform, r.contour_seconds);
  if (r.refined) stages["refined"] = stage_row(*r.refined, r.refine_seconds);
  stages["improved"] =
      stage_row(r.improved, r.pillow_seconds + r.project_seconds + r.optimisation.seconds);
  return summary;
}

}  // namespace volmesh::meshers
