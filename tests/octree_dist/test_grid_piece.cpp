// The ranks' grid pieces against structured_hex_mesh (run under mpirun -np 1, 2 and 4): the
// same cells with the same numbers and volumes, the same points, every piece valid, and the
// pieces the even split of the Morton curve.
#include <gtest/gtest.h>
#include <mpi.h>

#include "pieces_match.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/octree_dist/grid_piece.hpp"

namespace volmesh {
namespace {

TEST(GridPiece, PiecesMakeTheSerialGrid) {
  const Box3 box{Vec3(-1.0, 0.0, 0.5), Vec3(2.0, 0.25, 1.5)};
  for (const int level : {1, 3, 4}) {
    SCOPED_TRACE("level " + std::to_string(level));
    const Index n = Index{1} << level;
    const RankPiece piece = grid_piece(box, level);
    test::expect_pieces_make(piece, to_poly_mesh(structured_hex_mesh(box.lo, box.hi, {n, n, n})));
    int ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    const std::int64_t cells = piece.mesh.num_cells(), even = std::int64_t{n} * n * n / ranks;
    EXPECT_GE(cells, even);
    EXPECT_LE(cells, even + 1);
  }
}

}  // namespace
}  // namespace volmesh
