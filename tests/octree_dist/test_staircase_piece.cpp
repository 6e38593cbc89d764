// The ranks' staircase pieces against staircase_mesh (run under mpirun -np 1, 2 and 4): the
// same cells with the same numbers, regions and volumes, the same points, every piece valid.
#include <gtest/gtest.h>
#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "gather.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/octree/staircase.hpp"
#include "volmesh/octree_dist/staircase_piece.hpp"

namespace volmesh {
namespace {

struct Case {
  std::string domain;
  int level, base_level, cells_between_levels;
};

// Faces counted once over the pieces: a face between two ranks is in both.
double faces_once(const PolyMesh& piece) {
  double count = 0.0;
  for (Index f = 0; f < piece.num_faces(); ++f)
    count += piece.is_boundary(f) && piece.tag_names[piece.face_tag[f]].starts_with("procBoundary") ? 0.5 : 1.0;
  return count;
}

TEST(StaircasePiece, PiecesMakeTheSerialMesh) {
  const std::vector<Case> cases{{"builtin:ball", 5, 3, 1}, {"builtin:primitives", 5, 3, 2},
                                {"builtin:cube-inclusion", 4, 2, 1}, {"builtin:ball", 4, 1, 3}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.domain + " level " + std::to_string(c.level));
    const std::unique_ptr<Domain> domain = open_domain(c.domain);
    StaircaseOptions options;
    options.octree.level = c.level;
    options.octree.base_level = c.base_level;
    options.octree.cells_between_levels = c.cells_between_levels;
    const StaircasePiece piece = staircase_piece(build_distributed_octree(*domain, options.octree), *domain);
    const PolyMesh serial = staircase_mesh(*domain, options);

    const ValidityReport report = check_validity(piece.mesh);
    EXPECT_TRUE(report.valid()) << (report.problems.empty() ? "" : report.problems.front());
    ASSERT_EQ(piece.global_cell_count, serial.num_cells());
    ASSERT_EQ(piece.global_point_count, serial.num_points());
    double faces = faces_once(piece.mesh);
    MPI_Allreduce(MPI_IN_PLACE, &faces, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(faces, serial.num_faces());

    // Cell by cell, by global number: region and volume as the serial cell's.
    const MeshGeometry geometry = mesh_geometry(piece.mesh, build_cell_faces(piece.mesh));
    std::vector<double> cells;  // (number, region, volume) per cell
    for (Index k = 0; k < piece.mesh.num_cells(); ++k)
      cells.insert(cells.end(), {static_cast<double>(piece.global_cells[k]), static_cast<double>(piece.mesh.cell_region[k]),
                                 geometry.cells[k].volume});
    const std::vector<double> all_cells = test::gather_to_all(cells, MPI_DOUBLE);
    ASSERT_EQ(all_cells.size(), 3u * serial.num_cells());
    const MeshGeometry serial_geometry = mesh_geometry(serial, build_cell_faces(serial));
    int wrong = 0;
    for (std::size_t k = 0; k < all_cells.size(); k += 3) {
      const Index id = static_cast<Index>(all_cells[k]);
      wrong += id != static_cast<Index>(k / 3) || all_cells[k + 1] != serial.cell_region[id] ||
               std::abs(all_cells[k + 2] - serial_geometry.cells[id].volume) > 1e-12 * serial_geometry.cells[id].volume;
    }
    EXPECT_EQ(wrong, 0);

    // Points: each number once over 0 .. N-1, at one place on every rank holding it, the
    // serial mesh's places.
    std::vector<double> points;  // (number, x, y, z) per point
    for (Index p = 0; p < piece.mesh.num_points(); ++p)
      points.insert(points.end(), {static_cast<double>(piece.global_points[p]), piece.mesh.points[p].x(),
                                   piece.mesh.points[p].y(), piece.mesh.points[p].z()});
    const std::vector<double> all_points = test::gather_to_all(points, MPI_DOUBLE);
    std::vector<Vec3> at(serial.num_points(), Vec3::Constant(std::nan("")));
    int clashes = 0;
    for (std::size_t k = 0; k < all_points.size(); k += 4) {
      const Vec3 x(all_points[k + 1], all_points[k + 2], all_points[k + 3]);
      Vec3& seen = at[static_cast<std::size_t>(all_points[k])];
      clashes += !std::isnan(seen.x()) && seen != x;
      seen = x;
    }
    EXPECT_EQ(clashes, 0);
    std::vector<Vec3> places(at), serial_places(serial.points);
    const auto before = [](const Vec3& a, const Vec3& b) { return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end()); };
    std::sort(places.begin(), places.end(), before);
    std::sort(serial_places.begin(), serial_places.end(), before);
    EXPECT_TRUE(places == serial_places);
  }
}

}  // namespace
}  // namespace volmesh
