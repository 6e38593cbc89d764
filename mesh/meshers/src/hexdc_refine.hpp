#pragma once
// The hexdc mesher's local refinement options (--refine-boundary, --refine-box): which nodes they
// mark for refine_hexes, and its figures for the summary.
#include <nlohmann/json.hpp>
#include <optional>

#include <Eigen/Geometry>

#include "volmesh/hexdc/refine.hpp"
#include "volmesh/meshers/options.hpp"

namespace volmesh::meshers {

// The deepest --refine-boundary: each layer multiplies the hexes near the surface by 27.
inline constexpr int kMaxRefineLayers = 4;

struct HexdcRefinement {
  int boundary_layers = 0;
  std::optional<Eigen::AlignedBox3d> box;
};

// The options as given. Throws InputError for a --refine-box that is not six numbers
// x0,y0,z0,x1,y1,z1 with x0 < x1, y0 < y1, z0 < z1.
HexdcRefinement hexdc_refinement(const MethodOptions& options);

// Refines the nodes of the boundary layers and those inside the box (either may be empty).
RefineStats refine_hexdc(HexMesh& mesh, const HexdcRefinement& refinement);

nlohmann::json refinement_summary(const RefineStats& stats);

}  // namespace volmesh::meshers
