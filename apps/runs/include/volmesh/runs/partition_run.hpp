#pragma once
// `volmesh partition`'s outputs: a partitioned mesh as one VTU per part (PVTU), Gmsh
// partitioned entities (MSH), or one VTU with the cell array "partition".
#include <filesystem>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh::cli {

// By the extension of `output`: .pvtu, .msh, anything else a .vtu. cell_part: each cell's
// part in [0, parts).
void write_partitioned(const PolyMesh& mesh, const std::vector<Index>& cell_part, Index parts,
                       const std::filesystem::path& output);

}  // namespace volmesh::cli
