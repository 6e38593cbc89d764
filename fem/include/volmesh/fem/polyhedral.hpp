#pragma once
// The polyhedral space's cells (fem.hpp, Space::polyhedral): the sub-tessellation of
// geometry/cell_tessellation.hpp where a cell has a star centre, the virtual element below
// where it has none.
#include <optional>
#include <span>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/geometry/cell_tessellation.hpp"

namespace volmesh::fem {

// The lowest-order virtual element (Beirão da Veiga et al., 2013) of a cell with no star
// centre: u_h harmonic inside, linear on each face triangle above. The space needs of it the
// projection Π onto linear functions, Πφ_i(x) = 1/n + g_i·(x − vertex_average) with
// g_i = (1/|E|) ∫_∂E φ_i n for each of the cell's n distinct vertices; ∫_∂E is exact on the
// face triangles, so Π reproduces every linear function and the patch test holds.
struct VirtualElement {
  double volume = 0.0;
  Vec3 centroid, vertex_average;
  std::vector<Vec3> gradient;  // g_i, in the order of `vertices`
};

// The virtual element of cell c; `vertices` are its distinct vertices, sorted. Empty when the
// volume is not positive or a face is folded (FaceSplits): an inverted or folded cell, which
// no space can take.
std::optional<VirtualElement> virtual_element(const PolyMesh& mesh, const FaceSplits& splits,
                                              std::span<const Index> faces, Index c,
                                              std::span<const Index> vertices);

}  // namespace volmesh::fem
