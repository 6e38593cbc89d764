// OpenVDB's mesh-to-level-set on the grid of a volmesh .rawiv, for the side-by-side in
// run.sh: the same voxel size and sample positions; bands that reach, from the surface, as
// far out and in as the grid's farthest samples (a dense field, as volmesh computes; it
// covers a region around the surface somewhat larger than the grid's cube), or a narrow
// band of BAND_VOXELS when asked. Prints one JSON line: the time, the active voxels, and how
// far OpenVDB's values are from volmesh's exact ones at the samples it computed (OpenVDB is
// negative inside, volmesh positive).
//   vdb_mesh_to_sdf SURFACE GRID.rawiv [BAND_VOXELS]
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "volmesh/io/surface_io.hpp"
#include "volmesh/io/voxel_grid_io.hpp"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: vdb_mesh_to_sdf SURFACE GRID.rawiv [BAND_VOXELS]\n";
    return 2;
  }
  openvdb::initialize();
  const volmesh::TriSurface mesh = volmesh::read_surface(argv[1]);
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  for (const volmesh::Vec3& p : mesh.points) points.emplace_back(p.x(), p.y(), p.z());
  for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  const volmesh::VoxelGrid grid = volmesh::read_rawiv(argv[2]);
  const int n = grid.dims[0];
  const auto [lo, hi] = std::minmax_element(grid.values.begin(), grid.values.end());
  const double h = grid.spacing.x();
  const float exterior = argc > 3 ? std::stof(argv[3]) : std::ceil(-*lo / h) + 1.0;
  const float interior = argc > 3 ? std::stof(argv[3]) : std::ceil(*hi / h) + 1.0;

  auto xform = openvdb::math::Transform::createLinearTransform(h);
  xform->postTranslate(openvdb::Vec3d(grid.origin.x(), grid.origin.y(), grid.origin.z()));
  const auto start = std::chrono::steady_clock::now();
  const openvdb::FloatGrid::Ptr sdf = openvdb::tools::meshToSignedDistanceField<openvdb::FloatGrid>(
      *xform, points, triangles, std::vector<openvdb::Vec4I>(), exterior, interior);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Compare at the samples inside the computed band.
  const auto accessor = sdf->getConstAccessor();
  double worst = 0.0, sum = 0.0;
  std::size_t compared = 0, signs = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const openvdb::Coord c(i, j, k);
        if (!accessor.isValueOn(c)) continue;
        const double ours = grid.at(i, j, k), theirs = -accessor.getValue(c);
        const double error = std::abs(ours - theirs) / h;
        worst = std::max(worst, error);
        sum += error;
        ++compared;
        signs += (ours > 0) != (theirs > 0) && std::abs(ours) > 1e-6 * h;
      }
  std::printf(
      "{\"seconds\": %.3f, \"band_voxels\": [%.0f, %.0f], \"active\": %zu, \"samples\": %zu, "
      "\"max_error_voxels\": %.4g, \"mean_error_voxels\": %.4g, \"sign_mismatches\": %zu}\n",
      seconds, exterior, interior, static_cast<std::size_t>(sdf->activeVoxelCount()), compared,
      worst, compared ? sum / compared : 0.0, signs);
  return 0;
}
