#pragma once
// What the tests of meshing and solving in pieces share: whether the build has pieces, and
// the pieces of a .pvtu set read back whole against the serial mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pvtu_compare.hpp"
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

// A solve on the pieces (its --json) against the serial one's: partitioned by the octree, the
// same counts, the errors to the solver tolerance (norms below kRoundingErrors: not compared).
inline void expect_same_solve(const nlohmann::json& serial, const nlohmann::json& pieces) {
  EXPECT_EQ(pieces["partition"], "octree");
  for (const char* count : {"cells", "points", "dofs", "unknowns"}) EXPECT_EQ(pieces[count], serial[count]) << count;
  for (const char* norm : {"l2", "h1", "linf"}) {
    const double e = serial["errors"][norm].get<double>();
    if (e > kRoundingErrors)
      EXPECT_LE(relative(pieces["errors"][norm].get<double>(), e), kSolutionAgreement) << norm;
  }
}

// `solve ARGS --json -o u<ranks>.pvtu` in `dir` on `ranks` ranks against the serial solve's
// --json (expect_same_solve), one piece per rank. Returns the .pvtu.
inline std::filesystem::path expect_solve_on_ranks(const std::string& args, int ranks, const nlohmann::json& serial,
                                                   const std::filesystem::path& dir) {
  SCOPED_TRACE(ranks);
  const std::filesystem::path out = dir / ("u" + std::to_string(ranks) + ".pvtu");
  const auto r = run_mpi(ranks, "solve " + args + " --json -o " + out.string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return out;
  expect_same_solve(serial, nlohmann::json::parse(r.out));
  EXPECT_EQ(pvtu_piece_files(out).size(), std::size_t(ranks));
  return out;
}

// `run` (a command line ending in "-o ") twice on `ranks` ranks: every piece the same bytes.
inline void expect_same_bytes(const std::string& run, int ranks, const std::filesystem::path& dir) {
  SCOPED_TRACE(run);
  for (const std::string name : {"a", "b"})
    ASSERT_EQ(run_mpi(ranks, run + (dir / (name + ".pvtu")).string(), dir).exit_code, 0);
  for (int piece = 0; piece < ranks; ++piece) {
    const std::string a = slurp(dir / "a" / ("a_" + std::to_string(piece) + ".vtu"));
    EXPECT_FALSE(a.empty());
    EXPECT_TRUE(a == slurp(dir / "b" / ("b_" + std::to_string(piece) + ".vtu"))) << piece;
  }
}

}  // namespace volmesh::test
