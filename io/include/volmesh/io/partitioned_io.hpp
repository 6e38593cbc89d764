#pragma once
// Partitioned meshes: ParaView's PVTU (one VTU file per part and a summary file naming them)
// and Gmsh MSH 4.1 with partitioned entities. Each is written as a set: a failure leaves none
// of its files behind. A PVTU set is read back piece by piece (each process its own piece)
// and stitched by the pieces' global ids.
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

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


// A VTU file's cells as the file gives them, before their faces are matched (cells_to_poly):
// what one piece of a partitioned set holds, with the set's global ids, so that pieces read
// on different processes can be put together. Plain vectors, for sending between processes.
struct CellList {
  static constexpr Index kPolyhedron = -1;  // cell_kind of a cell given by its faces
  std::vector<Vec3> points;
  std::vector<Index> point_ids;  // per point: its global id ("GlobalPointIds")
  std::vector<Index> cell_ids;   // per cell: its global id ("GlobalCellIds")
  std::vector<Index> cell_region;
  std::vector<Index> cell_kind;      // a LinearCell, or kPolyhedron
  std::vector<Index> cell_begin{0};  // cell c's items: [cell_begin[c], cell_begin[c + 1])
  // A linear cell's corners; a polyhedron's faces as [n, v_1 .. v_n] each, outward. Point
  // indices into `points`.
  std::vector<Index> items;
  std::vector<std::string> tag_names;
  std::vector<Index> tagged_tag;         // per tagged face: its index in tag_names
  std::vector<Index> tagged_begin{0};    // tagged face t: tagged_vertices[begin[t], begin[t+1])
  std::vector<Index> tagged_vertices;
};

// The piece files a PVTU summary names, in piece order, as paths beside it. Throws InputError
// naming the file when it is not a PVTU of an unstructured grid or names no piece.
std::vector<std::filesystem::path> pvtu_piece_files(const std::filesystem::path& pvtu);

// One piece as `volmesh partition` writes it: a VTU whose cells carry "GlobalCellIds" and
// whose points carry "GlobalPointIds". Throws InputError naming the file when it cannot be
// read or lacks either array.
CellList read_vtu_piece(const std::filesystem::path& piece);

// The whole mesh from all the pieces of a set (piece i is part i): points and cells in the
// order of their global ids, which must each be 0 .. N-1 and be in some piece (cells in
// exactly one), a point shared by pieces at the same place in each. Boundary tags in order of
// first appearance over the pieces; the faces between parts become internal faces, and their
// "procBoundary<p>to<q>" tags go. cell_part (optional): each cell's piece. Throws InputError
// naming `source` when the pieces do not fit together.
PolyMesh stitch_pieces(std::span<const CellList> pieces, const std::string& source,
                       std::vector<Index>* cell_part = nullptr);

// A partitioned PVTU set read whole on one process: every piece, stitched.
PolyMesh read_pvtu(const std::filesystem::path& pvtu, std::vector<Index>* cell_part = nullptr);

}  // namespace volmesh
