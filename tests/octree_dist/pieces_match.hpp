#pragma once
// What the piece tests check: the ranks' pieces make up the serial mesh, cell by cell (number,
// region, volume) and point by point (number, place), every piece valid.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gather.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/octree_dist/rank_piece.hpp"

namespace volmesh::test {

// Faces counted once over the pieces: a face between two ranks is in both.
inline double faces_once(const PolyMesh& piece) {
  double count = 0.0;
  for (Index f = 0; f < piece.num_faces(); ++f)
    count += piece.is_boundary(f) && piece.tag_names[piece.face_tag[f]].starts_with("procBoundary") ? 0.5 : 1.0;
  return count;
}

// Collective: every rank calls it with its piece.
inline void expect_pieces_make(const RankPiece& piece, const PolyMesh& serial) {
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
  std::vector<char> seen(serial.num_cells(), 0);
  int wrong = 0;
  for (std::size_t k = 0; k < all_cells.size(); k += 3) {
    const Index id = static_cast<Index>(all_cells[k]);
    wrong += seen[id]++ != 0 || all_cells[k + 1] != serial.cell_region[id] ||
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

}  // namespace volmesh::test
