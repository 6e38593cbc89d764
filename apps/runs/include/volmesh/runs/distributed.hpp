#pragma once
// What `solve` and `study` do differently when mpirun starts them (fem/parallel.hpp): rank 0
// meshes (meshing is serial) and sends the mesh to every rank, rank 0 partitions it with
// METIS into one part per rank and sends the cell → part array (or the ranks read the pieces
// of a partitioned PVTU, one each, and take its parts as theirs), and the output is written
// by rank 0 (.vtu) or by every rank, one piece each (.pvtu). Every rank holds the whole
// mesh: the solve's matrix, preconditioner and vectors are distributed, the mesh is not.
// Each step is a stage of fem::stage ("mesh", "partition", "write"): a failure on any rank
// makes every rank throw.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/fem/parallel.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/partitioned_io.hpp"
#include "volmesh/octree_dist/rank_piece.hpp"

namespace volmesh::cli {

// Rank 0's result of make() on every rank, with rank 0's `numbers` (what else make() found
// that the others need, e.g. the mesh size h). The stage "mesh" (fem::stage): when make()
// throws on rank 0, every rank throws its message. One rank: make() alone.
PolyMesh mesh_on_rank_zero(const std::function<PolyMesh()>& make,
                           std::vector<double>* numbers = nullptr);

// A partitioned mesh written once (`volmesh partition MESH --parts P -o parts.pvtu`), read
// by the ranks: rank r reads piece r alone, the ranks exchange the pieces, and every rank
// stitches the whole mesh by the pieces' global ids (stitch_pieces); cell_rank: each cell's
// piece, which is its rank (no METIS at run time). Throws InputError on every rank when the
// number of pieces is not the number of ranks, or a piece is missing, unreadable, without
// global ids, or does not fit the others.
PolyMesh read_pieces_on_ranks(const std::filesystem::path& pvtu, std::vector<Index>& cell_rank);

// Throws InputError when a mesh of `cells` cells leaves a rank without one.
void require_cell_per_rank(std::int64_t cells);

// Each cell's rank: rank 0 partitions with METIS (one part per rank) and shares the array.
// Throws InputError on every rank when there are more ranks than cells.
std::vector<Index> partition_for_ranks(const PolyMesh& mesh);

// Writes the solution: a .vtu by rank 0, a .pvtu as one piece per rank (part r's cells with
// their global "global_cell" and "global_point" ids, the same arrays as the .vtu), rank 0
// writing the summary after every piece exists. cell_rank empty: one rank writes it all.
// Any rank's failure makes every rank throw.
void write_solution(const PolyMesh& mesh, const MeshFields& fields,
                    const std::vector<Index>& cell_rank, const std::filesystem::path& path);

// Writes a solution solved on the ranks' pieces (--partition octree): each rank its piece
// with `fields` and the "global_cell" and "global_point" numbers, as write_solution does.
void write_piece_solution(const PolyMesh& piece, MeshFields fields, const RankPiece& numbers,
                          const std::filesystem::path& path);

// Writes a .pvtu set of `pieces` pieces (fem::ranks(), or 1 on one rank), each rank its own
// piece, rank 0 the summary once every piece exists (the stage "write"); every piece carries
// the same arrays.
void write_pieces(MeshPiece mine, const std::filesystem::path& path, int pieces);

// The command line as volmesh's parser sees it (PETSc's options taken off), kept by main for
// a re-launch.
void remember_command_line(int argc, char** argv);

// `--np P` of a serial run: runs this very command line again as `mpirun -np P volmesh ...`,
// without `--np`, and returns its exit code. mpirun gets --oversubscribe (more ranks than
// cores are allowed) and, when run as root, --allow-run-as-root. Throws InputError when
// mpirun cannot be started or the build has no PETSc.
int relaunch_under_mpirun(int ranks);

}  // namespace volmesh::cli
