#pragma once
// Schneiders' 3-refinement templates (refine.hpp) as hexes on the lattice of a parent hex's
// parameter cube, turned onto any closed corner mask by the cube's symmetries.
#include <array>
#include <vector>

#include "volmesh/hexdc/refine.hpp"

namespace volmesh::hexdc_detail {

// Lattice points in sixths of the parameter cube: thirds for the 3 x 3 x 3 split and halves of a
// third for the face template's lifted inner nodes.
inline constexpr int kLatticeSteps = 6;
using LatticePoint = std::array<int, 3>;
using TemplateHex = std::array<LatticePoint, 8>;  // VTK corner order

// The parent's VTK corner c as a lattice point.
LatticePoint corner_point(int c);

// Bit c set when the node at VTK corner c of `cell` is marked.
unsigned corner_mask(const std::array<Index, 8>& cell, const std::vector<char>& marked);

// The smallest supported mask containing `mask` (see refine.hpp's closure rule).
unsigned closed_mask(unsigned mask);

// The hexes replacing a parent whose closed corner mask is `mask`, positively oriented when the
// parent is; {the parent itself} for 0. Throws std::logic_error for a mask that is not closed.
const std::vector<TemplateHex>& template_hexes(unsigned mask);

}  // namespace volmesh::hexdc_detail
