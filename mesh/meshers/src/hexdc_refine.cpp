#include "hexdc_refine.hpp"

#include <sstream>
#include <string>
#include <vector>

#include "volmesh/core/errors.hpp"

namespace volmesh::meshers {

namespace {

constexpr int kBoxNumbers = 6;

Eigen::AlignedBox3d parse_box(const std::string& text) {
  const std::string error = "hexdc: --refine-box " + text +
                            ": not six numbers x0,y0,z0,x1,y1,z1 with x0 < x1, y0 < y1, z0 < z1";
  std::vector<double> v;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    std::size_t used = 0;
    try {
      v.push_back(std::stod(item, &used));
    } catch (const std::exception&) {
      throw InputError(error);
    }
    if (used != item.size()) throw InputError(error);
  }
  if (v.size() != kBoxNumbers) throw InputError(error);
  const Vec3 lo(v[0], v[1], v[2]), hi(v[3], v[4], v[5]);
  if (!(lo.array() < hi.array()).all()) throw InputError(error);
  return {lo, hi};
}

}  // namespace

HexdcRefinement hexdc_refinement(const MethodOptions& options) {
  HexdcRefinement r;
  r.boundary_layers = static_cast<int>(given<std::int64_t>(options, "refine-boundary").value_or(0));
  if (const auto box = given<std::string>(options, "refine-box")) r.box = parse_box(*box);
  return r;
}

RefineStats refine_hexdc(HexMesh& mesh, const HexdcRefinement& refinement) {
  std::vector<char> marks = mark_boundary_layers(mesh, refinement.boundary_layers);
  if (refinement.box) {
    const std::vector<char> inside = mark_box(mesh, *refinement.box);
    for (std::size_t v = 0; v < marks.size(); ++v) marks[v] = static_cast<char>(marks[v] | inside[v]);
  }
  return refine_hexes(mesh, std::move(marks));
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

}  // namespace volmesh::meshers
