#pragma once
// The cells of each part as a mesh of their own, for one file per part.
#include <span>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// Local cells and points keep the global order; global_cells / global_points map them back.
// Faces shared with another part q become boundary faces, oriented outward from this part,
// tagged "procBoundary<p>to<q>" as OpenFOAM's decomposePar names them; boundary tags that no
// face of the part uses are dropped.
struct PartMesh {
  PolyMesh mesh;
  std::vector<Index> global_cells;
  std::vector<Index> global_points;
};

std::string part_boundary_name(Index part, Index other);

// One PartMesh per part 0 .. parts-1, in one pass over the faces.
std::vector<PartMesh> split_mesh(const PolyMesh& mesh, std::span<const Index> cell_part,
                                 Index parts);

}  // namespace volmesh
