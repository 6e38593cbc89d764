#pragma once
// How VTU files order their cells. Tets and hexes come in mesh order. Polyhedra come by
// their number of distinct vertices, then in mesh order: meshio (7.0) files polyhedra into
// blocks by that number in order of first appearance but splits the cell data by it in
// increasing order, so the two agree only on cells written in that order. The cell-data
// array "cell_id" gives each written cell's index in the mesh, and the VTU reader puts the
// cells back in that order. Shared by the VTU reader and writer.
#include <string_view>

namespace volmesh {

inline constexpr std::string_view kCellIdArray = "cell_id";

}  // namespace volmesh
