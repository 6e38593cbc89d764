// OpenFOAM polyMesh writer, checked by OpenFOAM's own checkMesh (Debian package openfoam).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <regex>
#include <sstream>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volume_mesh_fixtures.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

constexpr const char* kCheckMeshHint =
    "checkMesh not found: `make test` installs openfoam (Debian package)";

bool has_check_mesh() {
  std::string out;
  return test::run("command -v checkMesh", &out) == 0;
}

// checkMesh's report on the case `dir`. Debian's OpenFOAM finds its etc/ through
// WM_PROJECT_DIR, set here unless the user's OpenFOAM environment already sets it.
std::string check_mesh(const fs::path& dir) {
  std::string out;
  const int status =
      test::run("cd '" + dir.parent_path().string() +
                    "' && WM_PROJECT_DIR=\"${WM_PROJECT_DIR:-/usr/share/openfoam}\" checkMesh "
                    "-case '" +
                    dir.string() + "' 2>&1",
                &out);
  return out + "\n(exit status " + std::to_string(status) + ")";
}

// Swaps owner and neighbour of every internal face, reversing it, so that owner > neighbour.
void flip_internal_faces(PolyMesh& mesh) {
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.is_boundary(f)) continue;
    std::swap(mesh.owner[f], mesh.neighbour[f]);
    std::reverse(mesh.face_vertices.begin() + mesh.face_offsets[f],
                 mesh.face_vertices.begin() + mesh.face_offsets[f + 1]);
  }
}

// The labels of an OpenFOAM labelList file (owner, neighbour).
std::vector<long> label_list(const fs::path& path) {
  const std::string text = test::file_bytes(path);
  std::istringstream in(text.substr(text.find('}', text.find("FoamFile")) + 1));
  std::string token;
  long count = 0;
  // Skip the comment line after the header; the count precedes "(".
  while (in >> token && token != "(") {
    if (std::isdigit(static_cast<unsigned char>(token[0]))) count = std::stol(token);
  }
  std::vector<long> labels;
  for (long value; in >> value;) labels.push_back(value);
  EXPECT_EQ(static_cast<long>(labels.size()), count) << path;
  return labels;
}

struct Patch {
  std::string name, type;
  long faces, start;
  bool operator==(const Patch&) const = default;
};
std::ostream& operator<<(std::ostream& os, const Patch& p) {
  return os << p.name << " " << p.type << " " << p.faces << " " << p.start;
}

std::vector<Patch> patches(const fs::path& case_dir) {
  const std::string text = test::file_bytes(case_dir / "constant/polyMesh/boundary");
  static const std::regex entry(
      R"((\w+)\s*\{\s*type\s+(\w+);\s*nFaces\s+(\d+);\s*startFace\s+(\d+);\s*\})");
  std::vector<Patch> out;
  for (std::sregex_iterator it(text.begin(), text.end(), entry), end; it != end; ++it)
    out.push_back({(*it)[1], (*it)[2], std::stol((*it)[3]), std::stol((*it)[4])});
  return out;
}

// Internal faces are in upper-triangular order: owner < neighbour, sorted by both.
void expect_upper_triangular(const fs::path& case_dir) {
  const auto owner = label_list(case_dir / "constant/polyMesh/owner");
  const auto neighbour = label_list(case_dir / "constant/polyMesh/neighbour");
  ASSERT_LE(neighbour.size(), owner.size());
  for (std::size_t f = 0; f < neighbour.size(); ++f) {
    EXPECT_LT(owner[f], neighbour[f]) << "face " << f;
    if (f > 0) {
      EXPECT_LE(std::pair(owner[f - 1], neighbour[f - 1]), std::pair(owner[f], neighbour[f]))
          << "face " << f;
    }
  }
}

TEST(FoamWriter, HexCubePassesCheckMesh) {
  ASSERT_TRUE(has_check_mesh()) << kCheckMeshHint;
  TempDir tmp;
  const fs::path dir = tmp / "cube.foam";
  HexMesh hex = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {3, 3, 3});
  for (Index c = 0; c < hex.num_cells(); ++c) hex.cell_region[c] = c % 3 == 0 ? 1 : 2;  // x < 1/3
  write_mesh(to_poly_mesh(hex), dir);

  const std::string report = check_mesh(dir);
  EXPECT_NE(report.find("Mesh OK."), std::string::npos) << report;
  // 3 × 18 internal faces, then one patch of 9 quads per side.
  const std::vector<std::string> sides{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  std::vector<Patch> expected;
  for (std::size_t i = 0; i < sides.size(); ++i)
    expected.push_back({sides[i], "patch", 9, static_cast<long>(54 + 9 * i)});
  EXPECT_EQ(patches(dir), expected);
  EXPECT_EQ(label_list(dir / "constant/polyMesh/owner").size(), 108u);
  expect_upper_triangular(dir);

  for (const char* file : {"system/controlDict", "system/fvSchemes", "system/fvSolution",
                           "cube.foam", "constant/polyMesh/points", "constant/polyMesh/faces"})
    EXPECT_TRUE(fs::is_regular_file(dir / file)) << file;
  EXPECT_EQ(fs::file_size(dir / "cube.foam"), 0u);
  const std::string zones = test::file_bytes(dir / "constant/polyMesh/cellZones");
  EXPECT_NE(zones.find("region_1\n{\n    type cellZone;\n    cellLabels List<label>\n9\n"),
            std::string::npos)
      << zones;
  EXPECT_NE(zones.find("region_2\n{\n    type cellZone;\n    cellLabels List<label>\n18\n"),
            std::string::npos);
}

TEST(FoamWriter, SplitFacePolyhedronPassesCheckMeshAfterReorientingFaces) {
  ASSERT_TRUE(has_check_mesh()) << kCheckMeshHint;
  TempDir tmp;
  const fs::path dir = tmp / "split.foam";
  PolyMesh mesh = test::split_face_mesh();
  flip_internal_faces(mesh);  // every owner > neighbour: the writer must swap them back
  write_foam(mesh, dir);

  const std::string report = check_mesh(dir);
  EXPECT_NE(report.find("Mesh OK."), std::string::npos) << report;
  EXPECT_NE(report.find("polyhedra:     1"), std::string::npos) << report;
  // 16 internal faces: 12 among the 8 small cubes, 4 between them and the big cube.
  const std::vector<Patch> expected{{"xmin", "patch", 1, 16}, {"xmax", "patch", 4, 17},
                                    {"ymin", "patch", 5, 21}, {"ymax", "patch", 5, 26},
                                    {"zmin", "patch", 5, 31}, {"zmax", "patch", 5, 36}};
  EXPECT_EQ(patches(dir), expected);
  expect_upper_triangular(dir);
  const std::string zones = test::file_bytes(dir / "constant/polyMesh/cellZones");
  EXPECT_NE(zones.find("region_2\n{\n    type cellZone;\n    cellLabels List<label>\n1\n(\n8\n)"),
            std::string::npos)
      << zones;
}

TEST(FoamWriter, TwoRegionsTwoPatchesPassCheckMesh) {
  ASSERT_TRUE(has_check_mesh()) << kCheckMeshHint;
  TempDir tmp;
  const fs::path dir = tmp / "regions.foam";
  PolyMesh mesh = test::two_region_tets();
  // xmin becomes "inlet", every other side "outer wall" (not an OpenFOAM word as it is).
  for (Index& tag : mesh.face_tag)
    if (tag > 0) tag = 1;
  mesh.tag_names = {"inlet", "outer wall"};
  write_foam(mesh, dir);

  const std::string report = check_mesh(dir);
  EXPECT_NE(report.find("Mesh OK."), std::string::npos) << report;
  // 48 tets: (4 × 48 − 48 boundary) / 2 = 72 internal faces.
  const std::vector<Patch> expected{{"inlet", "patch", 8, 72}, {"outer_wall", "patch", 40, 80}};
  EXPECT_EQ(patches(dir), expected);
  const std::string zones = test::file_bytes(dir / "constant/polyMesh/cellZones");
  EXPECT_NE(zones.find("\n2\n(\nregion_1\n"), std::string::npos) << zones;
  EXPECT_NE(zones.find("region_2\n{\n    type cellZone;\n    cellLabels List<label>\n24\n"),
            std::string::npos)
      << zones;
}

TEST(FoamWriter, RewritingAnExistingCaseReplacesOnlyThePolyMesh) {
  TempDir tmp;
  const fs::path dir = tmp / "case";
  write_foam(test::two_region_tets(), dir);
  EXPECT_TRUE(fs::is_regular_file(dir / "case.foam"));
  fs::create_directory(dir / "0");
  std::ofstream(dir / "0" / "T") << "user field\n";
  std::ofstream(dir / "system" / "controlDict") << "user settings\n";
  fs::create_directory(dir / "constant/polyMesh/sets");  // stale: belongs to the old mesh

  write_foam(test::split_face_mesh(), dir / "");  // a trailing separator names the same case
  EXPECT_EQ(test::file_bytes(dir / "0" / "T"), "user field\n");
  EXPECT_EQ(test::file_bytes(dir / "system" / "controlDict"), "user settings\n");
  EXPECT_FALSE(fs::exists(dir / "constant/polyMesh/sets"));
  EXPECT_NE(test::file_bytes(dir / "constant/polyMesh/owner").find("nCells:9 "), std::string::npos);
  // No temporary left beside the case or the polyMesh.
  std::vector<std::string> entries;
  for (const auto& e : fs::directory_iterator(dir.parent_path()))
    entries.push_back(e.path().filename());
  for (const auto& e : fs::directory_iterator(dir / "constant"))
    entries.push_back(e.path().filename());
  EXPECT_EQ(entries, (std::vector<std::string>{"case", "polyMesh"}));
}

}  // namespace
}  // namespace volmesh
