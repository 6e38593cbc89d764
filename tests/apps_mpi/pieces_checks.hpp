#pragma once
// What the tests of meshing and solving in pieces share: whether the build has pieces, and
// the pieces of a .pvtu set read back whole against the serial mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "run_mpi.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/partitioned_io.hpp"

namespace volmesh::test {

inline const std::vector<int> kRankCounts{1, 2, 4};
// Volumes summed in another order agree to rounding.
inline constexpr double kVolumeAgreement = 1e-10;
// Error norms below this are rounding (a patch test's): compared point by point only.
inline constexpr double kRoundingErrors = 1e-8;

inline bool pieces_built(const std::filesystem::path& dir) {
  const std::string version = run_volmesh("--version", dir).out;
  return petsc_built(dir) && version.find("p4est 2") != std::string::npos;
}

inline double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// The pieces stitched by their global ids (VTK's XML reader, one piece at a time): valid, the
// serial mesh's counts, volume and region volumes.
inline void expect_same_mesh(const PolyMesh& serial, const std::filesystem::path& pvtu, int ranks) {
  EXPECT_EQ(pvtu_piece_files(pvtu).size(), std::size_t(ranks));
  const PolyMesh whole = read_mesh(pvtu);  // the pieces stitched by their global ids
  const ValidityReport a = check_validity(serial), b = check_validity(whole);
  EXPECT_TRUE(b.valid()) << (b.problems.empty() ? "" : b.problems.front());
  EXPECT_EQ(whole.num_cells(), serial.num_cells());
  EXPECT_EQ(whole.num_points(), serial.num_points());
  EXPECT_EQ(whole.num_faces(), serial.num_faces());
  EXPECT_LE(relative(b.total_volume, a.total_volume), kVolumeAgreement);
  ASSERT_EQ(b.region_volume.size(), a.region_volume.size());
  for (const auto& [region, volume] : a.region_volume)
    EXPECT_LE(relative(b.region_volume.at(region), volume), kVolumeAgreement) << region;
}

}  // namespace volmesh::test
