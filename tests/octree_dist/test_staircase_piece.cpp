// The ranks' staircase pieces against staircase_mesh (run under mpirun -np 1, 2 and 4): the
// same cells with the same numbers, regions and volumes, the same points, every piece valid.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "octree_case.hpp"
#include "pieces_match.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/octree/staircase.hpp"
#include "volmesh/octree_dist/staircase_piece.hpp"

namespace volmesh {
namespace {

using test::Case;

TEST(StaircasePiece, PiecesMakeTheSerialMesh) {
  const std::vector<Case> cases{{"builtin:ball", 5, 3, 1}, {"builtin:primitives", 5, 3, 2},
                                {"builtin:cube-inclusion", 4, 2, 1}, {"builtin:ball", 4, 1, 3}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.domain + " level " + std::to_string(c.level));
    const std::unique_ptr<Domain> domain = open_domain(c.domain);
    StaircaseOptions options;
    options.octree = test::options_of(c);
    const RankPiece piece = staircase_piece(build_distributed_octree(*domain, options.octree), *domain);
    const PolyMesh serial = staircase_mesh(*domain, options);

    test::expect_pieces_make(piece, serial);
  }
}

}  // namespace
}  // namespace volmesh
