#include "volmesh/runs/partition_run.hpp"

#include <algorithm>
#include <cctype>

#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/partitioned_io.hpp"
#include "volmesh/partition/part_mesh.hpp"

namespace volmesh::cli {

namespace {

// Each part as a VTU piece with the global ids of its cells and points (the names of VTK's
// vtkGenerateGlobalIds) and its part number.
std::vector<MeshPiece> pvtu_pieces(const PolyMesh& mesh, const std::vector<Index>& cell_part,
                                   Index parts) {
  std::vector<MeshPiece> pieces;
  Index p = 0;
  for (PartMesh& part : split_mesh(mesh, cell_part, parts)) {
    MeshPiece& piece = pieces.emplace_back();
    piece.fields.cell_ints.push_back({"GlobalCellIds", std::move(part.global_cells)});
    piece.fields.cell_ints.push_back({"partition", std::vector<Index>(part.mesh.num_cells(), p++)});
    // MeshFields has no integer point arrays: doubles hold these ids exactly.
    piece.fields.point.push_back(
        {"GlobalPointIds", 1, {part.global_points.begin(), part.global_points.end()}});
    piece.mesh = std::move(part.mesh);
  }
  return pieces;
}

}  // namespace

void write_partitioned(const PolyMesh& mesh, const std::vector<Index>& cell_part, Index parts,
                       const std::filesystem::path& output) {
  std::string ext = output.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (ext == ".pvtu") {
    write_pvtu(pvtu_pieces(mesh, cell_part, parts), output);
  } else if (ext == ".msh") {
    write_msh_partitioned(mesh, cell_part, parts, output);
  } else {
    MeshFields fields;
    fields.cell_ints.push_back({"partition", cell_part});
    write_vtu(mesh, output, fields);
  }
}

}  // namespace volmesh::cli
