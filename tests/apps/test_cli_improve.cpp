// volmesh improve end to end: a poor cube mesh in any readable format comes out better, valid,
// its boundary triangles, regions and tags the same, the same bytes for any thread count;
// with --surface its side points slide; bad meshes are refused with one line and no file.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "../improve/poor_meshes.hpp"
#include "../support/unit_cube_meshes.hpp"
#include "run_volmesh.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::count_lines;
using test::run_volmesh;

using Triangle = std::array<std::array<double, 3>, 3>;

// The boundary faces as coordinate triangles, each rotated to start at its smallest corner.
std::multiset<Triangle> boundary_triangles(const PolyMesh& m) {
  std::multiset<Triangle> out;
  for (Index f = 0; f < m.num_faces(); ++f) {
    if (!m.is_boundary(f)) continue;
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = m.points[m.face(f)[k]];
      t[k] = {p.x(), p.y(), p.z()};
    }
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.insert(t);
  }
  return out;
}

PolyMesh poor_two_region_cube() {
  return to_poly_mesh(test::poor_cube({.n = 4, .two_regions = true}));
}

TEST(CliImprove, PoorMeshGetsBetterInEveryReadableFormat) {
  const fs::path dir = test::scratch_dir("improve-formats");
  const PolyMesh input = poor_two_region_cube();
  for (const char* ext : {".vtu", ".msh", ".mesh"}) {
    const fs::path in = dir / (std::string("poor") + ext), out = dir / "better.vtu";
    write_mesh(input, in);
    const auto r = run_volmesh("improve " + in.string() + " -o " + out.string() + " --json", dir);
    ASSERT_EQ(r.exit_code, 0) << ext << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_GT(j["after"]["min_dihedral_deg"].get<double>(),
              j["before"]["min_dihedral_deg"].get<double>() + 5.0)
        << ext;
    EXPECT_LT(j["after"]["max_dihedral_deg"].get<double>(), j["before"]["max_dihedral_deg"].get<double>());
    EXPECT_LE(j["after"]["tets_below_10_deg"].get<int>(), j["before"]["tets_below_10_deg"].get<int>());
    EXPECT_GT(j["after"]["max_radius_edge"].get<double>(), 0.0);
    EXPECT_GT(j["operations"]["smoothed"].get<long>(), 0);
    const PolyMesh better = read_mesh(out);
    const ValidityReport report = check_validity(better);
    EXPECT_TRUE(report.valid()) << ext;
    EXPECT_EQ(boundary_triangles(better), boundary_triangles(input)) << ext;
    EXPECT_EQ(better.tag_names, input.tag_names) << ext;
    const ValidityReport before = check_validity(input);
    for (const auto& [region, volume] : before.region_volume)
      EXPECT_NEAR(report.region_volume.at(region), volume, 1e-12) << ext << " region " << region;
  }
}

TEST(CliImprove, SameBytesForAnyThreadCount) {
  const fs::path dir = test::scratch_dir("improve-threads");
  write_mesh(poor_two_region_cube(), dir / "poor.msh");
  std::vector<std::string> bytes;
  for (const char* threads : {"1", "2"}) {
    const fs::path out = dir / (std::string("out") + threads + ".msh");
    const auto r = run_volmesh("improve " + (dir / "poor.msh").string() + " -o " + out.string() +
                                   " --threads " + threads,
                               dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    bytes.push_back(test::slurp(out));
  }
  EXPECT_EQ(bytes[0], bytes[1]);
}

TEST(CliImprove, SidePointsSlideWithinTheSurface) {
  const fs::path dir = test::scratch_dir("improve-surface");
  write_mesh(to_poly_mesh(test::poor_cube({.n = 4, .jitter = 0.3, .face_jitter = 0.4})),
             dir / "poor.vtu");
  std::ofstream(dir / "cube.off") << "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n"
                                     "1 1 1\n0 1 1\n3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n"
                                     "3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n"
                                     "3 3 0 4\n3 3 4 7\n";
  const auto r = run_volmesh("improve " + (dir / "poor.vtu").string() + " -o " +
                                 (dir / "out.vtu").string() + " --json --surface " +
                                 (dir / "cube.off").string(),
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(r.out)["operations"]["slid"].get<long>(), 0);
  const PolyMesh out = read_mesh(dir / "out.vtu");
  const ValidityReport report = check_validity(out);
  EXPECT_TRUE(report.valid());
  EXPECT_NEAR(report.total_volume, 1.0, 1e-12);
  for (const Triangle& t : boundary_triangles(out))
    for (const auto& p : t)
      EXPECT_TRUE(std::count(p.begin(), p.end(), 0.0) + std::count(p.begin(), p.end(), 1.0) > 0);
}

TEST(CliImprove, BadMeshesAreRefusedWithOneLineAndNoFile) {
  const fs::path dir = test::scratch_dir("improve-bad");
  std::ofstream(dir / "inverted.mesh") << "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n"
                                          "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n"
                                          "1 3 2 4 1\nEnd\n";
  // Three tets on one face: not conforming.
  std::ofstream(dir / "three.node") << "6 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n"
                                       "4 0 0 -1\n5 0.2 0.2 1\n";
  std::ofstream(dir / "three.ele") << "3 4 0\n0 0 1 2 3\n1 0 2 1 4\n2 0 1 2 5\n";
  write_mesh(to_poly_mesh(test::unit_cube_hex()), dir / "hexes.vtu");
  std::ofstream(dir / "garbage.msh") << "this is no mesh\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"inverted.mesh", "inverted.mesh: invalid mesh"},
      {"three.ele", "three.ele: "},
      {"hexes.vtu", "hexes.vtu: "},
      {"garbage.msh", "garbage.msh: "},
      {"missing.vtu", "missing.vtu: no such file"},
  };
  for (const auto& [name, expected] : cases) {
    const fs::path out = dir / "out.vtu";
    const auto r = run_volmesh("improve " + (dir / name).string() + " -o " + out.string(), dir);
    EXPECT_EQ(r.exit_code, 1) << name << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << name;
  }
  const auto usage = run_volmesh("improve " + (dir / "hexes.vtu").string(), dir);
  EXPECT_EQ(usage.exit_code, 2);
}

}  // namespace
}  // namespace volmesh
