#pragma once
// Partitioned mesh output: ParaView's PVTU (one VTU file per part and a summary file naming
// them) and Gmsh MSH 4.1 with partitioned entities. Each is written as a set: a failure
// leaves none of its files behind.
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {

// One part's mesh and the arrays written beside it; every piece carries the same arrays.
struct MeshPiece {
  PolyMesh mesh;
  MeshFields fields;
};

// Writes piece i with write_vtu as <dir>/<stem>/<stem>_<i>.vtu and the summary
// <dir>/<stem>.pvtu naming them, as VTK's and ParaView's parallel writers lay them out
// (vtkXMLPUnstructuredGridWriter with UseSubdirectory). The summary is written last, so the
// set is complete once it exists. An existing <stem>/ directory is replaced only if it holds
// nothing but <stem>_<n>.vtu files (an earlier run's pieces); otherwise InputError.
void write_pvtu(std::span<const MeshPiece> pieces, const std::filesystem::path& path);

class AtomicOutput;  // io/src/atomic_output.hpp

// write_pvtu's steps, for writers that each hold some of the pieces (the ranks of a
// distributed solve): one process makes the set, every writer puts its pieces in
// pieces_directory() (shared with them by name), and once all exist the set's maker commits
// it with the pieces' arrays and their count, writing the summary last. A set never
// committed leaves nothing behind.
class PvtuSet {
 public:
  // Throws InputError as write_pvtu does for the directory of the pieces.
  explicit PvtuSet(const std::filesystem::path& path);
  ~PvtuSet();
  PvtuSet(const PvtuSet&) = delete;
  PvtuSet& operator=(const PvtuSet&) = delete;
  const std::filesystem::path& pieces_directory() const;
  void commit(const MeshFields& arrays, std::size_t pieces);

 private:
  std::filesystem::path path_;
  std::string stem_;
  std::unique_ptr<AtomicOutput> pieces_, summary_;
};

// Piece i of the set `path`, into the set's pieces_directory.
void write_pvtu_piece(const MeshPiece& piece, std::size_t i,
                      const std::filesystem::path& pieces_directory,
                      const std::filesystem::path& path);

// Gmsh MSH 4.1 (ASCII) of a mesh whose cell c lies in part cell_part[c] (0 .. parts-1):
// $Entities holds the model entities write_msh writes (a volume and physical group per
// region, a surface per boundary tag and per region interface), $PartitionedEntities one
// entity per (part, model entity) with the parent's physical group, in Gmsh's partitions
// 1 .. parts. Elements keep write_msh's tags (cell c is element c + 1). A node lies on the
// volume entity of the first cell, in part order, that uses it: the lowest part owns it.
// Tetrahedra and hexahedra only, like write_msh.
void write_msh_partitioned(const PolyMesh& mesh, std::span<const Index> cell_part, Index parts,
                           const std::filesystem::path& path);

}  // namespace volmesh
