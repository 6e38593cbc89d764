// The ranks' cut-cell pieces against cutcell_mesh (run under mpirun -np 1, 2 and 4): every
// piece valid, each global cell and point number once, and over the ranks the serial mesh's
// cells, points, faces and region volumes, each shared point at one place.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gather.hpp"
#include "octree_case.hpp"
#include "pieces_match.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/octree_dist/cutcell_piece.hpp"

namespace volmesh {
namespace {

// Region volumes summed in another order agree to rounding.
constexpr double kVolumeAgreement = 1e-10;

using test::Case;

// Every number in 0 .. count - 1 exactly once over the ranks (a point: once per owner).
bool numbered_once(const std::vector<std::int64_t>& mine, std::int64_t count) {
  const std::vector<std::int64_t> all = test::gather_to_all(mine, MPI_INT64_T);
  std::vector<int> seen(count, 0);
  for (const std::int64_t id : all) {
    if (id < 0 || id >= count) return false;
    ++seen[id];
  }
  return std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; });
}

TEST(CutcellPiece, PiecesMakeTheSerialMesh) {
  const std::vector<Case> cases{{"builtin:ball", 5, 3, 1},
                                {"builtin:primitives", 4, 2, 1},
                                {"builtin:cube-inclusion", 4, 2, 2},
                                {std::string(VOLMESH_CGAL_DATA) + "/meshes/fandisk.off", 5, 3, 1}};
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.domain + " level " + std::to_string(c.level));
    const std::unique_ptr<Domain> domain = open_domain(c.domain);
    CutcellOptions options;
    options.octree = test::options_of(c);
    const RankPiece piece = cutcell_piece(*domain, options);
    const PolyMesh serial = cutcell_mesh(*domain, options);

    const ValidityReport report = check_validity(piece.mesh);
    EXPECT_TRUE(report.valid()) << (report.problems.empty() ? "" : report.problems.front());
    ASSERT_EQ(piece.global_cell_count, serial.num_cells());
    ASSERT_EQ(piece.global_point_count, serial.num_points());
    double faces = test::faces_once(piece.mesh);
    MPI_Allreduce(MPI_IN_PLACE, &faces, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(faces, serial.num_faces());
    EXPECT_TRUE(numbered_once(piece.global_cells, piece.global_cell_count));
    std::vector<std::int64_t> owned;
    for (Index p = 0; p < piece.mesh.num_points(); ++p)
      if (piece.point_owner[p] == rank) owned.push_back(piece.global_points[p]);
    EXPECT_TRUE(numbered_once(owned, piece.global_point_count));

    const ValidityReport whole = check_validity(serial);
    for (const auto& [region, volume] : whole.region_volume) {
      double sum = report.region_volume.count(region) ? report.region_volume.at(region) : 0.0;
      MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
      EXPECT_LE(std::abs(sum - volume), kVolumeAgreement * volume) << "region " << region;
    }
  }
}

}  // namespace
}  // namespace volmesh
