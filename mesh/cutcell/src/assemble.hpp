#pragma once
// The PolyMesh of the final pass.
#include <vector>

#include "cut_grid.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/poly_mesh.hpp"

namespace volmesh::cutcell {

struct AssemblyStats {
  Index cut_cells = 0;
  std::vector<Index> cell_leaf;  // the leaf of each cell
};

// cuts[cut_of[leaf]] is the split of a cut leaf (cut_of = kNoIndex for whole leaves).
PolyMesh assemble(const Grid& grid, const std::vector<LeafCut>& cuts,
                  const std::vector<Index>& cut_of, AssemblyStats& stats);

}  // namespace volmesh::cutcell
