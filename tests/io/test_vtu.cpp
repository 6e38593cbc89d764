// VTU writer and reader: round trips, determinism, meshio as a third-party reader and
// writer, and clear errors on bad files.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#ifdef __SANITIZE_ADDRESS__
#include <sanitizer/lsan_interface.h>
#endif

#include "../support/unit_cube_meshes.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volume_mesh_fixtures.hpp"

namespace volmesh::test {
namespace {

// Writes, reads back, compares; a second write gives the same bytes, and so does writing
// the mesh read back.
void expect_round_trip(const PolyMesh& mesh, const TempDir& dir, const MeshFields& fields = {}) {
  const auto first = dir / "a.vtu", second = dir / "b.vtu", third = dir / "c.vtu";
  write_vtu(mesh, first, fields);
  write_vtu(mesh, second, fields);
  EXPECT_TRUE(file_bytes(first) == file_bytes(second)) << "bytes differ";
  const PolyMesh back = read_vtu(first);
  expect_same_mesh(mesh, back);
  EXPECT_TRUE(check_validity(back).valid());
  write_vtu(back, third, fields);
  EXPECT_TRUE(file_bytes(first) == file_bytes(third)) << "bytes differ";
}

MeshFields some_fields(const PolyMesh& mesh) {
  MeshFields fields;
  fields.cell_ints.push_back({"partition", std::vector<Index>(mesh.num_cells(), 1)});
  fields.cell.push_back({"quality", 1, std::vector<double>(mesh.num_cells(), 0.25)});
  fields.point.push_back({"u", 3, std::vector<double>(3 * mesh.num_points(), -1.5)});
  return fields;
}

TEST(Vtu, TetsRoundTripWithRegionsAndTags) {
  TempDir dir;
  expect_round_trip(two_region_tets(), dir);
}

TEST(Vtu, HexesRoundTripWithFields) {
  TempDir dir;
  const PolyMesh mesh = two_region_hexes();
  expect_round_trip(mesh, dir, some_fields(mesh));
}

TEST(Vtu, PolyhedronWithSplitFaceRoundTrips) {
  TempDir dir;
  const PolyMesh mesh = split_face_mesh();
  ASSERT_TRUE(check_validity(mesh).valid());
  expect_round_trip(mesh, dir);
  EXPECT_EQ(cell_type_counts(read_vtu(dir / "a.vtu")),
            (std::map<std::string, long>{{"points", 31}, {"hexahedron", 8}, {"polyhedron13", 1}}));
}

// With a polyhedron present every cell is written as a polyhedron: meshio cannot read a mix.
TEST(Vtu, MeshioReadsTetsHexesAndPolyhedra) {
  TempDir dir;
  const PolyMesh tets = two_region_tets(), hexes = two_region_hexes(), poly = split_face_mesh();
  write_vtu(tets, dir / "t.vtu");
  write_vtu(hexes, dir / "h.vtu", some_fields(hexes));
  write_vtu(poly, dir / "p.vtu");
  const auto seen = meshio_read({dir / "t.vtu", dir / "h.vtu", dir / "p.vtu"});
  expect_meshio_counts(cell_type_counts(tets), seen[0]);
  expect_meshio_counts(cell_type_counts(hexes), seen[1]);
  EXPECT_EQ(seen[1].value("cell_data", nlohmann::json::array()),
            nlohmann::json({"partition", "quality", "region"}));
  EXPECT_EQ(seen[1].value("point_data", nlohmann::json::array()), nlohmann::json({"u"}));
  expect_meshio_counts({{"points", 31}, {"polyhedron8", 8}, {"polyhedron13", 1}}, seen[2]);
}

// A polyhedral file lists its cells by vertex count, with "cell_id" back to the mesh's order:
// the big cube (13 vertices, cell 0) comes after the four small ones (8 each). meshio 7.0
// pairs every cell with its own region and data; our reader restores the mesh's order.
TEST(Vtu, PolyhedraComeByVertexCountWithTheirData) {
  TempDir dir;
  const PolyMesh mesh = big_cube_next_to_four_small(true);
  MeshFields fields;
  fields.cell_ints.push_back({"region_plus_4", {5, 6, 6, 6, 6}});
  fields.cell.push_back({"twice_region", 2, {2, 2, 4, 4, 4, 4, 4, 4, 4, 4}});
  fields.point.push_back({"x", 1, {}});
  for (const Vec3& p : mesh.points) fields.point.back().values.push_back(p.x());
  expect_round_trip(mesh, dir, fields);
  const PolyMesh back = read_vtu(dir / "a.vtu");
  EXPECT_EQ(back.cell_region, mesh.cell_region);

  const nlohmann::json expected = {{"1", 1.0}, {"2", 0.5}};
  const auto seen = meshio_region_volumes({dir / "a.vtu"});
  EXPECT_EQ(seen[0].value("cells", nlohmann::json()),
            nlohmann::json({{"polyhedron8", 4}, {"polyhedron13", 1}}));
  EXPECT_EQ(seen[0].value("regions", nlohmann::json()), expected);
  // The other cell arrays follow their cells: volumes by their values.
  const auto by = [&](const std::string& array) {
    return meshio_region_volumes({dir / "a.vtu"}, array)[0].value("regions", nlohmann::json());
  };
  EXPECT_EQ(by("region_plus_4"), nlohmann::json({{"5", 1.0}, {"6", 0.5}}));
  EXPECT_EQ(by("twice_region"), nlohmann::json({{"2", 1.0}, {"4", 0.5}}));
  EXPECT_EQ(by("cell_id"),
            nlohmann::json({{"0", 1.0}, {"1", 0.125}, {"2", 0.125}, {"3", 0.125}, {"4", 0.125}}));
}

// "cell_id" orders the cells; a user field of that name would be mistaken for it.
TEST(Vtu, CellIdIsReservedAndChecked) {
  TempDir dir;
  const PolyMesh mesh = big_cube_next_to_four_small(true);
  MeshFields fields;
  fields.cell_ints.push_back({"cell_id", {0, 1, 2, 3, 4}});
  EXPECT_THROW(write_vtu(mesh, dir / "a.vtu", fields), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "a.vtu"));
}

TEST(Vtu, ReadsMeshioWedgesAndPyramids) {
  TempDir dir;
  run_meshio_script("meshio_write.py", "'" + (dir / "m.vtu").string() + "'");
  const PolyMesh mesh = read_vtu(dir / "m.vtu");
  EXPECT_EQ(mesh.num_cells(), 3);
  EXPECT_EQ(mesh.cell_region, (std::vector<Index>{5, 5, 5}));
  EXPECT_EQ(mesh.num_faces(), 6 + 5 + 5 - 2);
  EXPECT_EQ(mesh.tag_names, std::vector<std::string>{"boundary"});
  const ValidityReport report = check_validity(mesh);
  EXPECT_TRUE(report.valid()) << (report.problems.empty() ? "" : report.problems.front());
  EXPECT_NEAR(report.total_volume, 1.0 + 1.0 / 6 + 0.25, 1e-12);
}

// "cell_id" puts the cells in its order; ids that are not each cell's own index are refused.
TEST(Vtu, CellIdsOrderTheCellsOrAreRefused) {
  TempDir dir;
  const auto path = (dir / "m.vtu").string();
  run_meshio_script("meshio_write.py", "'" + path + "' 2,0,1");
  const CellFaces cells = build_cell_faces(read_vtu(path));
  EXPECT_EQ(std::vector<std::size_t>({cells.of(0).size(), cells.of(1).size(), cells.of(2).size()}),
            std::vector<std::size_t>({5, 5, 6}));  // pyramid, wedge, hexahedron
  for (const auto& [ids, what] : std::vector<std::pair<std::string, std::string>>{
           {"0,2,0", ": cell data 'cell_id': cells 0 and 2 have the same id 0"},
           {"0,1,3", ": cell data 'cell_id': cell 2 has id 3 (ids are 0 .. 2)"}}) {
    run_meshio_script("meshio_write.py", "'" + path + "' " + ids);
    try {
      read_vtu(path);
      ADD_FAILURE() << ids << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), path + what);
    }
  }
}

// VTK does not escape array names; the writer encodes the tag names it puts there.
TEST(Vtu, TagNamesWithXmlCharactersRoundTrip) {
  TempDir dir;
  PolyMesh mesh = two_region_hexes();
  mesh.tag_names[0] = "a&b\"c<d>'e %41";
  mesh.tag_names[1] = "\xC3\xBCn\xC3\xAF";
  expect_round_trip(mesh, dir);
}

TEST(Vtu, FieldOfWrongSizeIsRefused) {
  TempDir dir;
  MeshFields fields;
  fields.cell.push_back({"quality", 1, {1.0, 2.0}});
  try {
    write_vtu(two_region_hexes(), dir / "f.vtu", fields);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell field 'quality': 2 values, expected 8"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "f.vtu"));
}

// The error is one line naming the file, and VTK prints nothing of its own on stderr.
TEST(Vtu, BadFilesGiveOneLineErrors) {
  TempDir dir;
  write_vtu(two_region_tets(), dir / "good.vtu");
  const std::string bytes = file_bytes(dir / "good.vtu");
  std::ofstream(dir / "truncated.vtu", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  std::string corrupt = bytes;  // zlib data of the first array
  corrupt[corrupt.find("<AppendedData encoding=\"base64\">\n   _") + 70] ^= 0x5A;
  std::ofstream(dir / "corrupt.vtu", std::ios::binary) << corrupt;
  std::ofstream(dir / "garbage.vtu") << "not xml at all\n";
  for (const char* name : {"truncated.vtu", "corrupt.vtu", "garbage.vtu", "missing.vtu"}) {
    const auto path = dir / name;
    ::testing::internal::CaptureStderr();
    try {
      read_vtu(path);
      ADD_FAILURE() << name << ": no error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << name;
  }
}

// VTK 9.1 leaks the arrays it has allocated when a cell array turns out to be cut short;
// LeakSanitizer does not count what is allocated while this is alive.
struct VtkLeaksIgnored {
#ifdef __SANITIZE_ADDRESS__
  VtkLeaksIgnored() { __lsan_disable(); }
  ~VtkLeaksIgnored() { __lsan_enable(); }
#endif
};

// Truncated or corrupted files (a sample of cut points, and flipped bytes in the compressed
// data) are clear errors or still read: never a crash or another exception.
TEST(Vtu, DamagedFilesAreHandled) {
  TempDir dir;
  write_vtu(split_face_mesh(), dir / "good.vtu");
  const std::string good = file_bytes(dir / "good.vtu");
  const auto path = dir / "damaged.vtu";
  auto expect_handled = [&](const std::string& bytes, const std::string& what_damage) {
    std::ofstream(path, std::ios::binary) << bytes;
    [[maybe_unused]] const VtkLeaksIgnored vtk_leaks;
    try {
      read_vtu(path);
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": ", 0), 0u) << what_damage;
    }
  };
  for (std::size_t size = 0; size < good.size(); size += 97)
    expect_handled(good.substr(0, size), "cut at " + std::to_string(size));
#ifndef __SANITIZE_ADDRESS__
  // Some flips hit a compression header, from which VTK allocates: the reader turns the
  // std::bad_alloc into an InputError, but ASan aborts on the allocation before it throws.
  const std::size_t data = good.find("<AppendedData");
  for (std::size_t at = data + 40; at < good.size(); at += 53) {
    std::string bytes = good;
    bytes[at] = static_cast<char>(bytes[at] ^ 0x5A);
    expect_handled(bytes, "byte flipped at " + std::to_string(at));
  }
#endif
}

}  // namespace
}  // namespace volmesh::test
