// Gmsh MSH 4.1 writer and reader: round trips, determinism, gmsh and meshio as third-party
// readers, elements we do not write (prisms, pyramids), and clear errors on bad files.
#include <gtest/gtest.h>

#include <fstream>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volume_mesh_fixtures.hpp"

namespace volmesh::test {
namespace {

// Boundary faces and faces between regions: the triangles / quads an MSH file holds.
long surface_elements(const PolyMesh& mesh) {
  long n = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    n += mesh.is_boundary(f) ||
         mesh.cell_region[mesh.owner[f]] != mesh.cell_region[mesh.neighbour[f]];
  return n;
}

// Writes, reads back, compares; writing again, or writing the mesh read back, gives the
// same bytes.
void expect_round_trip(const PolyMesh& mesh, const TempDir& dir) {
  write_msh(mesh, dir / "a.msh");
  write_msh(mesh, dir / "b.msh");
  EXPECT_TRUE(file_bytes(dir / "a.msh") == file_bytes(dir / "b.msh")) << "bytes differ";
  const PolyMesh back = read_msh(dir / "a.msh");
  expect_same_mesh(mesh, back);
  EXPECT_TRUE(check_validity(back).valid());
  write_msh(back, dir / "c.msh");
  EXPECT_TRUE(file_bytes(dir / "a.msh") == file_bytes(dir / "c.msh")) << "bytes differ";
}

// Gmsh reads our file without a complaint and saves it again as MSH 4.1, and our reader
// finds the same mesh there: points, cells, regions and boundary tags.
void expect_gmsh_reads(const PolyMesh& mesh, const TempDir& dir) {
  if (!have_gmsh()) return;
  write_msh(mesh, dir / "in.msh");
  std::string log;
  const int status = run("/usr/bin/gmsh '" + (dir / "in.msh").string() +
                             "' -save -format msh41 -o '" + (dir / "out.msh").string() + "' 2>&1",
                         &log);
  ASSERT_EQ(status, 0) << log;
  EXPECT_EQ(log.find("Error"), std::string::npos) << log;
  EXPECT_EQ(log.find("Warning"), std::string::npos) << log;
  expect_same_mesh(mesh, read_msh(dir / "out.msh"));
}

TEST(Msh, TetsRoundTripWithRegionsAndTags) {
  TempDir dir;
  expect_round_trip(two_region_tets(), dir);
}

TEST(Msh, HexesRoundTripWithRegionsAndTags) {
  TempDir dir;
  expect_round_trip(two_region_hexes(), dir);
}

TEST(Msh, WritesPhysicalGroupsForRegionsTagsAndInterfaces) {
  TempDir dir;
  write_msh(two_region_hexes(), dir / "h.msh");
  const std::string text = file_bytes(dir / "h.msh");
  for (const char* group : {"2 1 \"xmin\"", "2 6 \"zmax\"", "2 7 \"interface_1_3\"",
                            "3 1 \"region_1\"", "3 3 \"region_3\""})
    EXPECT_NE(text.find(group), std::string::npos) << group;
  EXPECT_EQ(text.rfind("$MeshFormat\n4.1 0 8\n", 0), 0u);
}

TEST(Msh, GmshReadsTets) {
  TempDir dir;
  expect_gmsh_reads(two_region_tets(), dir);
}

TEST(Msh, GmshReadsHexes) {
  TempDir dir;
  expect_gmsh_reads(two_region_hexes(), dir);
}

// meshio also sees the boundary and interface faces, as triangles or quads.
TEST(Msh, MeshioReadsTetsAndHexes) {
  TempDir dir;
  const PolyMesh tets = two_region_tets(), hexes = two_region_hexes();
  write_msh(tets, dir / "t.msh");
  write_msh(hexes, dir / "h.msh");
  const auto seen = meshio_read({dir / "t.msh", dir / "h.msh"});
  auto expected = cell_type_counts(tets);
  expected["triangle"] = surface_elements(tets);
  expect_meshio_counts(expected, seen[0]);
  expected = cell_type_counts(hexes);
  expected["quad"] = surface_elements(hexes);
  expect_meshio_counts(expected, seen[1]);
}

// A tet mesh of the unit cube meshed by gmsh itself, with a named physical surface.
TEST(Msh, ReadsMeshGeneratedByGmsh) {
  if (!have_gmsh()) return;
  TempDir dir;
  write_text(dir / "box.geo",
             "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
             "Physical Volume(4) = {1};\nPhysical Surface(\"walls\") = {1, 2, 3, 4, 5, 6};\n"
             "Mesh.MeshSizeMax = 0.5;\n");
  std::string log;
  ASSERT_EQ(run("/usr/bin/gmsh -3 '" + (dir / "box.geo").string() + "' -format msh41 -o '" +
                    (dir / "box.msh").string() + "' 2>&1",
                &log),
            0)
      << log;
  const PolyMesh mesh = read_msh(dir / "box.msh");
  EXPECT_GT(mesh.num_cells(), 100);
  EXPECT_EQ(regions_of(mesh), std::vector<Index>{4});
  EXPECT_EQ(mesh.tag_names, std::vector<std::string>{"walls"});
  const ValidityReport report = check_validity(mesh);
  EXPECT_TRUE(report.valid()) << (report.problems.empty() ? "" : report.problems.front());
  EXPECT_NEAR(report.total_volume, 1.0, 1e-12);
}

TEST(Msh, PolyhedraAreRefused) {
  TempDir dir;
  const auto path = dir / "p.msh";
  try {
    write_msh(split_face_mesh(), path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() +
                                         ": cell 8 is a polyhedron with 9 faces; MSH 4.1 output "
                                         "takes tetrahedra and hexahedra only (write it with "
                                         "--decompose tets)");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir / ""));
}

TEST(Msh, TagNameWithQuoteIsRefused) {
  TempDir dir;
  PolyMesh mesh = two_region_hexes();
  mesh.tag_names[2] = "say \"hi\"";
  try {
    write_msh(mesh, dir / "q.msh");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("boundary tag 'say \"hi\"': quotes and line breaks"),
              std::string::npos)
        << e.what();
  }
}

// A hexahedron with a pyramid on top and a prism beside it, in Gmsh's own node order, with
// a named physical surface on the pyramid's faces and nodes numbered from 10.
constexpr const char* kMixedCells = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
2
2 4 "roof"
3 7 "steel"
$EndPhysicalNames
$Entities
0 0 1 1
1 0 0 1 1 1 1.5 1 4 0
1 0 0 0 1.5 1 1.5 1 7 0
$EndEntities
$Nodes
1 11 10 20
3 1 0 11
10
11
12
13
14
15
16
17
18
19
20
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
0.5 0.5 1.5
1.5 0 0.5
1.5 1 0.5
$EndNodes
$Elements
4 7 1 7
3 1 5 1
1 10 11 12 13 14 15 16 17
3 1 7 1
2 14 15 16 17 18
3 1 6 1
3 11 15 19 12 16 20
2 1 2 4
4 14 15 18
5 15 16 18
6 16 17 18
7 17 14 18
$EndElements
)";

TEST(Msh, ReadsPrismsPyramidsAndPhysicalNames) {
  TempDir dir;
  write_text(dir / "mixed.msh", kMixedCells);
  const PolyMesh mesh = read_msh(dir / "mixed.msh");
  EXPECT_EQ(mesh.num_points(), 11);
  EXPECT_EQ(mesh.cell_region, (std::vector<Index>{7, 7, 7}));
  EXPECT_EQ(mesh.num_faces(), 6 + 5 + 5 - 2);
  EXPECT_EQ(mesh.tag_names, (std::vector<std::string>{"roof", "boundary"}));
  Index roof = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) roof += mesh.is_boundary(f) && mesh.face_tag[f] == 0;
  EXPECT_EQ(roof, 4);
  const ValidityReport report = check_validity(mesh);
  EXPECT_TRUE(report.valid()) << (report.problems.empty() ? "" : report.problems.front());
  EXPECT_NEAR(report.total_volume, 1.0 + 1.0 / 6 + 0.25, 1e-12);
}

struct BadFile {
  const char* name;
  std::string text;
  const char* message;
};

std::string with(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

TEST(Msh, BadFilesGiveOneLineErrors) {
  TempDir dir;
  const std::string good = kMixedCells;
  const BadFile cases[] = {
      {"empty.msh", "", "not a Gmsh MSH file"},
      {"v22.msh", with(good, "4.1 0 8", "2.2 0 8"),
       "line 2: MSH version 2.2 is not supported (4.1 expected)"},
      {"binary.msh", with(good, "4.1 0 8", "4.1 1 8"), "binary MSH is not supported"},
      {"truncated.msh", good.substr(0, good.find("7 17 14 18")), "unexpected end of file"},
      {"node_tag.msh", with(good, "2 14 15 16 17 18", "2 14 15 16 17 99"),
       "element 2: node tag 99 not defined in $Nodes"},
      {"range.msh", with(good, "\n20\n0 0 0", "\n21\n0 0 0"),
       "node tag 21 outside the announced range 10..20"},
      {"huge.msh", with(good, "4 7 1 7", "4 700000000 1 7"),
       "implausible number of elements 700000000"},
      {"letters.msh", with(good, "1.5 0 0.5", "1.5 zero 0.5"), "expected a number, found 'zero'"},
      {"type.msh", with(good, "3 1 5 1", "3 1 11 1"), "element type 11 is not supported"},
      {"shared.msh",
       with(good, "3 1 6 1\n3 11 15 19 12 16 20", "3 1 5 1\n3 10 11 12 13 14 15 16 17"),
       "cell 2: face shared with cells 0 and 1"},
  };
  for (const BadFile& bad : cases) {
    const auto path = dir / bad.name;
    write_text(path, bad.text);
    const std::string what = read_mesh_error(path);
    EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
    EXPECT_NE(what.find(bad.message), std::string::npos) << bad.name << ": " << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_NE(read_mesh_error(dir / "missing.msh"), "no error");
}

// Every truncation of a valid file either still reads (only the $EndElements line lost its
// tail) or is a clear error: never a crash or another exception.
TEST(Msh, EveryTruncationIsHandled) {
  TempDir dir;
  const std::string good = kMixedCells;
  const auto path = dir / "cut.msh";
  for (std::size_t size = 0; size < good.size(); ++size) {
    write_text(path, good.substr(0, size));
    const std::string what = read_mesh_error(path);
    if (what != "no error") {
      EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << size << ": " << what;
    }
  }
}

}  // namespace
}  // namespace volmesh::test
