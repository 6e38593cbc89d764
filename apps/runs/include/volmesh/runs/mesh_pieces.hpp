#pragma once
// Meshing on every rank under mpirun (docs/distributed.md): the staircase and cut-cell
// methods from the distributed octree (each rank its leaves and ghost layers) and the grid's
// hexahedra (each rank its stretch of the Morton curve). No rank holds the whole mesh.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "volmesh/domain/domain.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/partitioned_io.hpp"
#include "volmesh/meshers/registry.hpp"
#include "volmesh/octree_dist/rank_piece.hpp"

namespace volmesh::cli {

// Why `method` with the options `given` does not mesh on every rank ("" when it does): a
// method without pieces, an option the pieces do not take, a build without p4est.
std::string why_not_on_every_rank(const meshers::MesherInfo& method,
                                  const meshers::MethodOptions& given);

// Whether a run under mpirun meshes `method` on every rank, each solving on its piece:
// --partition octree (the default for cutcell, staircase and grid) for a method with pieces,
// written to a .pvtu (`output`, when the run writes one). Otherwise rank 0 meshes and METIS
// partitions, with a one-line note on rank 0's stderr when octree was asked for or is the
// default. False outside mpirun and for a mesh read from a file (`method` empty).
bool partition_in_pieces(const std::string& partition, const std::string& method,
                         const meshers::MethodOptions& given, const std::string& output);

struct RankMesh {
  RankPiece piece;
  double h = 0.0;  // the cell edge at the boundaries, as the method's MeshResult gives it
};

// The tags of the faces between pieces ("procBoundary<r>to<q>", part_boundary_name).
inline constexpr std::string_view kPieceBoundaryPrefix = "procBoundary";

// The boundary tags of every rank's piece but the faces between pieces, sorted: the serial
// mesh's tags, which the problems give conditions. Collective.
std::vector<std::string> boundary_tags_over_ranks(const PolyMesh& piece);

// This rank's piece, collective, the stage "mesh" (fem::stage): a failure on any rank makes
// every rank throw. Throws InputError on every rank when a rank would hold no cell.
RankMesh mesh_on_every_rank(const meshers::MesherInfo& method, const Domain& domain,
                            const meshers::MeshRequest& request);

// Rank `rank`'s piece of a .pvtu set: its mesh with the arrays `volmesh partition` writes
// ("GlobalCellIds", "partition", "GlobalPointIds") before `fields` (the piece's own values).
MeshPiece pvtu_piece(RankPiece piece, MeshFields fields, int rank);

// The whole mesh as the one piece of a set: every number its own.
RankPiece whole_mesh_piece(PolyMesh mesh);

// Every rank's piece written as one .pvtu set (write_pieces), collective.
void write_rank_piece(RankPiece piece, MeshFields fields, const std::filesystem::path& path);

}  // namespace volmesh::cli
