// MEDIT .mesh reader: what write_medit writes reads back as the same mesh (regions, boundary
// tags by name), files of other tools read, and bad files are refused with one line.
#include <gtest/gtest.h>

#include <fstream>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volume_mesh_fixtures.hpp"

namespace volmesh::test {
namespace {

// Two tets sharing the face x + y + z = 1 (volumes 1/6 and 1/3), as other tools write MEDIT:
// version 1, references 0, a comment, a keyword skipped.
constexpr const char* kTwoTets = R"(MeshVersionFormatted 1
# made by hand
Dimension
3
Vertices
5
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
1 1 1 0
Corners
1
1
Tetrahedra
2
1 2 3 4 0
2 3 4 5 0
Triangles
1
1 3 2 7
End
)";

TEST(MeditReader, RoundTripsTetsWithRegionsAndTags) {
  TempDir dir;
  const PolyMesh mesh = two_region_tets();
  write_medit(mesh, dir / "a.mesh");
  expect_same_mesh(mesh, read_mesh(dir / "a.mesh"));
}

TEST(MeditReader, RoundTripsHexes) {
  TempDir dir;
  const PolyMesh mesh = two_region_hexes();
  write_medit(mesh, dir / "h.mesh");
  expect_same_mesh(mesh, read_medit(dir / "h.mesh"));
}

TEST(MeditReader, ReadsUnlabelledCellsAsRegionOneAndNamesRefs) {
  TempDir dir;
  write_text(dir / "two.mesh", kTwoTets);
  const PolyMesh mesh = read_mesh(dir / "two.mesh");
  EXPECT_EQ(mesh.num_cells(), 2);
  EXPECT_EQ(mesh.cell_region, (std::vector<Index>{1, 1}));
  const ValidityReport report = check_validity(mesh);
  EXPECT_TRUE(report.valid());
  EXPECT_NEAR(report.total_volume, 0.5, 1e-15);
  // The one triangle names its tag; the other boundary faces get the default tag.
  ASSERT_EQ(mesh.tag_names.size(), 2u);
  EXPECT_EQ(mesh.tag_names[0], "ref_7");
}

TEST(MeditReader, RefusesBadFilesWithOneLine) {
  TempDir dir;
  const std::string good = kTwoTets;
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  const std::vector<std::pair<std::string, std::string>> cases{
      {"MeshVersion 1\n", "not a MEDIT mesh (no MeshVersionFormatted)"},
      {with("2 3 4 5 0", "2 3 4 9 0"), "line 18: Tetrahedra 2: vertex 9 out of range (5 vertices)"},
      {with("1 1 1 0", "1 nan 1 0"), "vertex 5: coordinate is not finite"},
      {with("1 1 1 0", "1 one 1 0"), "line 11: expected a number, found 'one'"},
      {with("Corners", "Prisms"), "unsupported keyword 'Prisms'"},
      {with("Dimension\n3", "Dimension\n2"), "only 3D meshes are read"},
      {with("2 3 4 5 0", "2 4 3 5 0"), "invert"},
      {good.substr(0, good.find("2 3 4 5")), "line 16: implausible number of elements 2"},
      {with("Tetrahedra\n2", "Tetrahedra\n2000000000"), "implausible number of elements"},
  };
  for (const auto& [text, expected] : cases) {
    const auto path = dir / "bad.mesh";
    write_text(path, text);
    const std::string error = read_mesh_error(path);
    EXPECT_NE(error.find(path.string() + ": "), std::string::npos) << error;
    EXPECT_NE(error.find(expected), std::string::npos) << expected << " in: " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace volmesh::test
