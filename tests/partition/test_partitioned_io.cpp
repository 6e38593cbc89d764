// Partitioned output read back by third-party readers: the PVTU by VTK's own parallel reader
// (what ParaView uses) and by meshio piece by piece; the partitioned MSH by gmsh. Plus the
// set-wise atomicity of the PVTU and determinism.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "../support/unit_cube_meshes.hpp"
#include "partition_test_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/partitioned_io.hpp"
#include "volmesh/partition/part_mesh.hpp"
#include "volmesh/partition/partition.hpp"

namespace volmesh::test {
namespace {

namespace fs = std::filesystem;

// 6x6x6 hexes of the unit cube, the upper half (z > 0.5) region 2.
PolyMesh two_region_grid() {
  PolyMesh mesh = hex_grid(6, 6, 6);
  const CellFaces cf = build_cell_faces(mesh);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    double z = 0;
    for (Index f : cf.of(c))
      for (Index v : mesh.face(f)) z += mesh.points[v].z() / 24;
    if (z > 0.5) mesh.cell_region[c] = 2;
  }
  return mesh;
}

std::vector<MeshPiece> pieces_of(const PolyMesh& mesh, const std::vector<Index>& cell_part,
                                 Index parts) {
  std::vector<MeshPiece> pieces;
  for (PartMesh& part : split_mesh(mesh, cell_part, parts)) {
    MeshPiece& piece = pieces.emplace_back();
    piece.fields.cell_ints.push_back({"GlobalCellIds", part.global_cells});
    piece.fields.point.push_back(
        {"GlobalPointIds", 1, {part.global_points.begin(), part.global_points.end()}});
    piece.mesh = std::move(part.mesh);
  }
  return pieces;
}

std::string bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    names.insert(fs::relative(entry.path(), dir).string());
  return names;
}

// One JSON object per file, from meshio_pvtu.py.
std::vector<nlohmann::json> meshio_read(const std::vector<fs::path>& files) {
  std::vector<nlohmann::json> seen;
  if (!have_meshio()) return seen;
  std::string command = script("meshio_pvtu.py"), output;
  for (const auto& file : files) command += " '" + file.string() + "'";
  EXPECT_EQ(run(command, &output), 0) << output;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with("{")) seen.push_back(nlohmann::json::parse(line));
  EXPECT_EQ(seen.size(), files.size()) << output;
  return seen;
}

TEST(Pvtu, VtkReadsTheWholeMeshBack) {
  TempDir dir;
  const PolyMesh mesh = two_region_grid();
  const Partition p = partition_mesh(mesh, {.parts = 4});
  write_pvtu(pieces_of(mesh, p.cell_part, 4), dir / "parts.pvtu");
  EXPECT_EQ(listing(dir.path()),
            (std::set<std::string>{"parts.pvtu", "parts", "parts/parts_0.vtu", "parts/parts_1.vtu",
                                   "parts/parts_2.vtu", "parts/parts_3.vtu"}));

  vtkNew<vtkXMLPUnstructuredGridReader> reader;
  reader->SetFileName((dir / "parts.pvtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfCells(), mesh.num_cells());
  vtkDataArray* ids = grid->GetCellData()->GetArray("GlobalCellIds");
  vtkDataArray* region = grid->GetCellData()->GetArray("region");
  vtkDataArray* point_ids = grid->GetPointData()->GetArray("GlobalPointIds");
  ASSERT_TRUE(ids != nullptr && region != nullptr && point_ids != nullptr);
  EXPECT_EQ(ids->GetDataType(), VTK_INT);
  std::set<Index> seen;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    const auto global = static_cast<Index>(ids->GetTuple1(c));
    seen.insert(global);
    EXPECT_EQ(region->GetTuple1(c), mesh.cell_region[global]);
  }
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(mesh.num_cells()));
  for (vtkIdType v = 0; v < grid->GetNumberOfPoints(); ++v) {
    const Vec3& x = mesh.points[static_cast<Index>(point_ids->GetTuple1(v))];
    EXPECT_EQ(Vec3(grid->GetPoint(v)), x);
  }
}

// meshio has no PVTU reader: it reads the pieces the summary names, which together hold the
// cells and volume meshio finds in the unpartitioned file.
TEST(Pvtu, MeshioFindsTheSameCellsAsInTheWholeMesh) {
  TempDir dir;
  const PolyMesh mesh = two_region_grid();
  const Partition p = partition_mesh(mesh, {.parts = 5});
  write_pvtu(pieces_of(mesh, p.cell_part, 5), dir / "parts.pvtu");
  write_vtu(mesh, dir / "whole.vtu");
  const auto seen = meshio_read({dir / "parts.pvtu", dir / "whole.vtu"});
  if (seen.size() != 2) return;
  EXPECT_EQ(seen[0]["cells"], seen[1]["cells"]);
  EXPECT_EQ(seen[0]["cells"]["hexahedron"], mesh.num_cells());
  EXPECT_NEAR(seen[0]["volume"].get<double>(), seen[1]["volume"].get<double>(), 1e-12);
  EXPECT_NEAR(seen[0]["volume"].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(seen[0]["files"], 5);
  EXPECT_EQ(seen[0]["partitions"], nlohmann::json(p.stats.part_cells));
  EXPECT_TRUE(seen[0]["cell_ids"].get<bool>());
  EXPECT_EQ(seen[0]["regions"], nlohmann::json(mesh.cell_region));
  EXPECT_EQ(seen[0]["point_ids"]["distinct"], mesh.num_points());
  EXPECT_TRUE(seen[0]["point_ids"]["consistent"].get<bool>());
  EXPECT_EQ(seen[0]["cell_data"], nlohmann::json({"GlobalCellIds", "region"}));
  EXPECT_EQ(seen[0]["point_data"], nlohmann::json({"GlobalPointIds"}));
}

// A piece holding a polyhedron is written with polyhedra only (as write_vtu does), the
// others with hexahedra. Piece 0 holds the big cube (13 vertices) before a small one (8):
// meshio puts each cell's data on it because write_vtu writes polyhedra by vertex count.
TEST(Pvtu, MeshioReadsPolyhedralPieces) {
  TempDir dir;
  write_pvtu(pieces_of(big_cube_next_to_four_small(true), {0, 1, 1, 0, 1}, 2), dir / "cubes.pvtu");
  const auto seen = meshio_read({dir / "cubes.pvtu"});
  if (seen.size() != 1) return;
  EXPECT_EQ(seen[0]["cells"],
            nlohmann::json({{"polyhedron13", 1}, {"polyhedron8", 1}, {"hexahedron", 3}}));
  EXPECT_NEAR(seen[0]["volume"].get<double>(), 1.5, 1e-12);
  EXPECT_EQ(seen[0]["partitions"], nlohmann::json({2, 3}));
  EXPECT_TRUE(seen[0]["cell_ids"].get<bool>());
  EXPECT_EQ(seen[0]["regions"], nlohmann::json({1, 2, 2, 2, 2}));
  EXPECT_EQ(seen[0]["point_ids"]["distinct"], 22);
  EXPECT_TRUE(seen[0]["point_ids"]["consistent"].get<bool>());
}

TEST(Pvtu, SameMeshSameBytes) {
  TempDir dir;
  const PolyMesh mesh = two_region_grid();
  const Partition p = partition_mesh(mesh, {.parts = 3});
  write_pvtu(pieces_of(mesh, p.cell_part, 3), dir / "a.pvtu");
  write_pvtu(pieces_of(mesh, partition_mesh(mesh, {.parts = 3}).cell_part, 3), dir / "b.pvtu");
  for (int i = 0; i < 3; ++i) {
    const std::string n = std::to_string(i);
    EXPECT_TRUE(bytes(dir / ("a/a_" + n + ".vtu")) == bytes(dir / ("b/b_" + n + ".vtu"))) << i;
  }
  std::string summary = bytes(dir / "a.pvtu");
  for (std::size_t at; (at = summary.find("\"a/a_")) != std::string::npos;)
    summary.replace(at, 5, "\"b/b_");
  EXPECT_EQ(summary, bytes(dir / "b.pvtu"));
}

// Each face by its vertex set: its two cells (internal) or its tag's name (boundary).
std::map<std::vector<Index>, std::string> faces_by_vertices(const PolyMesh& mesh) {
  std::map<std::vector<Index>, std::string> out;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto loop = mesh.face(f);
    std::vector<Index> key(loop.begin(), loop.end());
    std::sort(key.begin(), key.end());
    out[key] = mesh.is_boundary(f)
                   ? mesh.tag_names[mesh.face_tag[f]]
                   : std::to_string(std::min(mesh.owner[f], mesh.neighbour[f])) + "|" +
                         std::to_string(std::max(mesh.owner[f], mesh.neighbour[f]));
  }
  return out;
}

// The same points, cells and faces; face order, loop rotation and tag order may differ
// (the pieces' cells are written from each piece's own faces).
void expect_same_mesh(const PolyMesh& a, const PolyMesh& b) {
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.cell_region, b.cell_region);
  EXPECT_EQ(a.num_faces(), b.num_faces());
  EXPECT_EQ(faces_by_vertices(a), faces_by_vertices(b));
  EXPECT_EQ(std::set<std::string>(a.tag_names.begin(), a.tag_names.end()),
            std::set<std::string>(b.tag_names.begin(), b.tag_names.end()));
}

// The pieces stitched by their global ids are the mesh the whole file gives, hexahedra and
// polyhedra alike, and each cell's piece is its part.
TEST(Pvtu, StitchedPiecesAreTheWholeMesh) {
  TempDir dir;
  const PolyMesh grid = two_region_grid();
  const Partition p = partition_mesh(grid, {.parts = 3});
  struct Case {
    const char* name;
    PolyMesh mesh;
    std::vector<Index> cell_part;
  };
  for (const Case& c : {Case{"grid", grid, p.cell_part},
                        Case{"cubes", big_cube_next_to_four_small(true), {0, 1, 1, 0, 1}}}) {
    SCOPED_TRACE(c.name);
    const Index parts = *std::max_element(c.cell_part.begin(), c.cell_part.end()) + 1;
    const fs::path set = dir / (std::string(c.name) + ".pvtu"),
                   whole = dir / (std::string(c.name) + ".vtu");
    write_pvtu(pieces_of(c.mesh, c.cell_part, parts), set);
    write_vtu(c.mesh, whole);
    std::vector<Index> cell_part;
    expect_same_mesh(read_pvtu(set, &cell_part), read_vtu(whole));
    EXPECT_EQ(cell_part, c.cell_part);
    expect_same_mesh(read_mesh(set), read_vtu(whole));
  }
}

// A set whose pieces are missing, lack their global ids, or come from two meshes is
// refused with the file named.
TEST(Pvtu, PiecesThatDoNotFitAreRefused) {
  TempDir dir;
  const PolyMesh mesh = two_region_grid();
  write_pvtu(pieces_of(mesh, partition_mesh(mesh, {.parts = 2}).cell_part, 2), dir / "a.pvtu");
  const PolyMesh other = hex_grid(4, 4, 4);
  write_pvtu(pieces_of(other, partition_mesh(other, {.parts = 2}).cell_part, 2), dir / "b.pvtu");
  const auto refused = [](const fs::path& path, const std::string& what) {
    try {
      read_pvtu(path);
      ADD_FAILURE() << path << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  std::string mixed = bytes(dir / "a.pvtu");
  mixed.replace(mixed.find("a/a_1.vtu"), 9, "b/b_1.vtu");
  std::ofstream(dir / "mixed.pvtu") << mixed;
  refused(dir / "mixed.pvtu", "mixed.pvtu: ");
  std::string missing = bytes(dir / "a.pvtu");
  missing.replace(missing.find("a/a_1.vtu"), 9, "a/a_7.vtu");
  std::ofstream(dir / "missing.pvtu") << missing;
  refused(dir / "missing.pvtu", "a_7.vtu: cannot open");
  write_pvtu(std::vector<MeshPiece>{{mesh, {}}}, dir / "bare.pvtu");
  refused(dir / "bare.pvtu", "bare_0.vtu: no point data 'GlobalPointIds'");
  write_vtu(mesh, dir / "whole.vtu");
  refused(dir / "whole.vtu.pvtu", "cannot open");
  fs::copy_file(dir / "whole.vtu", dir / "not.pvtu");
  refused(dir / "not.pvtu", "not.pvtu: not a PVTU file");
}

// A second run replaces the earlier pieces (4 become 2), but a directory holding anything
// else is left alone, and so is everything when a piece cannot be written.
TEST(Pvtu, WrittenAsASetOrNotAtAll) {
  TempDir dir;
  const PolyMesh mesh = two_region_grid();
  const auto pieces4 = pieces_of(mesh, partition_mesh(mesh, {.parts = 4}).cell_part, 4);
  const auto pieces2 = pieces_of(mesh, partition_mesh(mesh, {.parts = 2}).cell_part, 2);
  write_pvtu(pieces4, dir / "p.pvtu");
  write_pvtu(pieces2, dir / "p.pvtu");
  EXPECT_EQ(listing(dir.path()), (std::set<std::string>{"p.pvtu", "p", "p/p_0.vtu", "p/p_1.vtu"}));

  fs::create_directory(dir / "q");
  std::ofstream(dir / "q" / "notes.txt") << "mine\n";
  try {
    write_pvtu(pieces2, dir / "q.pvtu");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("q.pvtu: " + (dir / "q").string() + " holds notes.txt"),
              std::string::npos)
        << e.what();
  }

  std::vector<MeshPiece> bad = pieces2;
  for (MeshPiece& piece : bad)
    piece.fields.cell.push_back({"a<b", 1, std::vector<double>(piece.mesh.num_cells(), 0.0)});
  const std::string before = bytes(dir / "p.pvtu");
  try {
    write_pvtu(bad, dir / "p.pvtu");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {  // named where the piece was meant to go
    EXPECT_EQ(std::string(e.what()).rfind((dir / "p" / "p_0.vtu").string() + ": ", 0), 0u)
        << e.what();
  }
  try {
    write_pvtu(bad, dir / "r.pvtu");
    ADD_FAILURE() << "no error";
  } catch (const InputError&) {
  }
  EXPECT_EQ(bytes(dir / "p.pvtu"), before);
  EXPECT_EQ(listing(dir.path()),
            (std::set<std::string>{"p.pvtu", "p", "p/p_0.vtu", "p/p_1.vtu", "q", "q/notes.txt"}));
}

// gmsh reads the partitioned file and, saved as MSH 2.2, tags every element with its
// partition: the same cells per partition as ours. meshio reads that MSH 2.2 file with the
// same cells and volume as the mesh. (meshio 5 cannot read partitioned MSH 4.1 files at all,
// not even gmsh's own: it looks their partitioned entities up among the model entities.)
TEST(PartitionedMsh, GmshReadsThePartitions) {
  TempDir dir;
  if (!have_gmsh()) return;
  const PolyMesh mesh = two_region_grid();
  const Partition p = partition_mesh(mesh, {.parts = 3});
  write_msh_partitioned(mesh, p.cell_part, 3, dir / "p.msh");
  const std::string text = bytes(dir / "p.msh");
  EXPECT_NE(text.find("$EndEntities\n$PartitionedEntities\n3\n0\n0 0 "), std::string::npos);

  std::string output;
  const std::string gmsh = "/usr/bin/gmsh -nopopup '" + (dir / "p.msh").string() + "'";
  ASSERT_EQ(run(gmsh + " -check", &output, true), 0) << output;
  EXPECT_NE(output.find("3 partitions"), std::string::npos) << output;
  EXPECT_EQ(output.find("Error"), std::string::npos) << output;
  ASSERT_EQ(run(gmsh + " -0 -format msh22 -o '" + (dir / "p22.msh").string() + "'", &output, true),
            0)
      << output;
  const auto seen = meshio_read({dir / "p22.msh"});
  if (seen.empty()) return;
  nlohmann::json expected;
  for (Index part = 0; part < 3; ++part)
    expected[std::to_string(part + 1)] = p.stats.part_cells[part];
  EXPECT_EQ(seen[0]["partitions"], expected);
  EXPECT_EQ(seen[0]["cells"]["hexahedron"], mesh.num_cells());
  EXPECT_NEAR(seen[0]["volume"].get<double>(), 1.0, 1e-12);
}

TEST(PartitionedMsh, SameMeshSameBytes) {
  TempDir dir;
  const PolyMesh mesh = two_region_grid();
  const Partition p = partition_mesh(mesh, {.parts = 4});
  write_msh_partitioned(mesh, p.cell_part, 4, dir / "a.msh");
  write_msh_partitioned(mesh, partition_mesh(mesh, {.parts = 4}).cell_part, 4, dir / "b.msh");
  EXPECT_TRUE(bytes(dir / "a.msh") == bytes(dir / "b.msh"));
}

TEST(PartitionedMsh, PolyhedraAreRefusedWithoutAFile) {
  TempDir dir;
  try {
    write_msh_partitioned(big_cube_next_to_four_small(), std::vector<Index>{0, 0, 1, 1, 1}, 2,
                          dir / "c.msh");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind((dir / "c.msh").string() + ": cell 0", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
  EXPECT_THROW(write_msh_partitioned(hex_grid(2, 1, 1), std::vector<Index>{0, 2}, 2, dir / "d.msh"),
               InputError);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

}  // namespace
}  // namespace volmesh::test
