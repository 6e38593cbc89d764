// OpenFOAM polyMesh reader: our own cases read back as written, and a case written by
// OpenFOAM's blockMesh (Debian package openfoam) reads as the same hex grid.
#include <gtest/gtest.h>

#include <fstream>
#include <zlib.h>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volume_mesh_fixtures.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

TEST(FoamReader, ReadsBackWhatWriteFoamWrote) {
  TempDir tmp;
  for (const PolyMesh& mesh :
       {test::two_region_tets(), test::two_region_hexes(), test::split_face_mesh()}) {
    const fs::path dir = tmp / "case.foam";
    write_foam(mesh, dir);
    test::expect_same_mesh(mesh, read_mesh(dir));
    test::expect_same_mesh(mesh, read_mesh(dir / "case.foam"));  // ParaView's marker file
  }
}

TEST(FoamReader, ReadsGzippedFiles) {
  TempDir tmp;
  const fs::path dir = tmp / "gz.foam";
  const PolyMesh mesh = test::two_region_hexes();
  write_foam(mesh, dir);
  const fs::path points = dir / "constant/polyMesh/points";
  const std::string text = test::file_bytes(points);
  gzFile out = gzopen((points.string() + ".gz").c_str(), "wb");
  ASSERT_NE(out, nullptr);
  gzwrite(out, text.data(), static_cast<unsigned>(text.size()));
  gzclose(out);
  fs::remove(points);
  test::expect_same_mesh(mesh, read_foam(dir));
}

TEST(FoamReader, ReadsABlockMeshCase) {
  std::string out;
  ASSERT_EQ(test::run("command -v blockMesh", &out), 0)
      << "blockMesh not found: `make test` installs openfoam (Debian package)";
  TempDir tmp;
  const fs::path dir = tmp / "block.foam";
  write_foam(test::two_region_hexes(), dir);  // for system/controlDict
  std::ofstream(dir / "system/blockMeshDict") << R"(FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
convertToMeters 1;
vertices ((0 0 0) (2 0 0) (2 1 0) (0 1 0) (0 0 1) (2 0 1) (2 1 1) (0 1 1));
blocks (hex (0 1 2 3 4 5 6 7) (6 3 4) simpleGrading (1 1 1));
boundary
(
    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
    lids { type patch; faces ((0 3 2 1) (4 5 6 7)); }
);
)";
  ASSERT_EQ(test::run("cd '" + dir.string() +
                          "' && WM_PROJECT_DIR=\"${WM_PROJECT_DIR:-/usr/share/openfoam}\" "
                          "blockMesh -case . > log.blockMesh 2>&1",
                      &out),
            0)
      << test::file_bytes(dir / "log.blockMesh");
  const PolyMesh mesh = read_foam(dir);
  EXPECT_EQ(mesh.num_cells(), 6 * 3 * 4);
  EXPECT_EQ(mesh.num_points(), 7 * 4 * 5);
  const auto report = check_validity(mesh);
  EXPECT_TRUE(report.valid()) << (report.problems.empty() ? "" : report.problems.front());
  EXPECT_NEAR(report.total_volume, 2.0, 1e-12);
  ASSERT_EQ(mesh.tag_names, (std::vector<std::string>{"walls", "lids"}));
  Index walls = 0, lids = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_boundary(f)) ++(mesh.face_tag[f] == 0 ? walls : lids);
  EXPECT_EQ(walls, 2 * 3 * 4 + 2 * 6 * 4);
  EXPECT_EQ(lids, 2 * 6 * 3);
}

TEST(FoamReader, RefusesBrokenCases) {
  TempDir tmp;
  const fs::path dir = tmp / "bad.foam";
  write_foam(test::two_region_hexes(), dir);
  const fs::path owner = dir / "constant/polyMesh/owner";
  const std::string good = test::file_bytes(owner);
  const auto expect_error = [&](const std::string& text, const std::string& needle) {
    std::ofstream(owner, std::ios::binary) << text;
    try {
      read_foam(dir);
      ADD_FAILURE() << "accepted: " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  std::string binary = good;
  binary.replace(binary.find("ascii"), 5, "binary");
  expect_error(binary, "foamFormatConvert");
  // The first owner label replaced by another.
  const auto with_first_owner = [&](const std::string& label) {
    const std::size_t begin = good.find_first_of("0123456789", good.find('(', good.find('}')));
    const std::size_t end = good.find_first_not_of("0123456789", begin);
    return good.substr(0, begin) + label + good.substr(end);
  };
  expect_error(with_first_owner("-3"), "owner holds -3");
  expect_error(with_first_owner("99"), "cell 8 has fewer than 4 faces");
  expect_error(good.substr(0, good.size() / 2), "owner");
  std::ofstream(owner) << good;
  fs::remove(dir / "constant/polyMesh/faces");
  expect_error(good, "faces: no such file");
}

}  // namespace
}  // namespace volmesh
