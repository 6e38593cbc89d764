// TetGen .node/.ele reader: a mesh written in TetGen's layout (regions as the first
// attribute, boundary markers in .face) reads back the same by either name; bad files are
// refused with one line.
#include <gtest/gtest.h>

#include <fstream>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volume_mesh_fixtures.hpp"

namespace volmesh::test {
namespace {

namespace fs = std::filesystem;

// The files `tetgen -A` writes for `mesh`, points numbered from `first`; boundary tag t has
// marker t + 1.
void write_tetgen(const PolyMesh& poly, const fs::path& base, int first) {
  const TetMesh mesh = to_tet_mesh(poly);
  std::ofstream node(base.string() + ".node"), ele(base.string() + ".ele"),
      face(base.string() + ".face");
  node.precision(17);
  node << mesh.num_points() << "  3  0  0\n";
  for (Index p = 0; p < mesh.num_points(); ++p)
    node << p + first << " " << mesh.points[p].x() << " " << mesh.points[p].y() << " "
         << mesh.points[p].z() << "\n";
  ele << "# tets, corners, attributes\n" << mesh.num_cells() << "  4  1\n";
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    ele << c + first;
    for (const Index v : mesh.cells[c]) ele << " " << v + first;
    ele << " " << mesh.cell_region[c] << "\n";
  }
  face << mesh.boundary_faces.size() << " 1\n";
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    face << f + first;
    for (const Index v : mesh.boundary_faces[f]) face << " " << v + first;
    face << " " << mesh.boundary_tag[f] + 1 << "\n";
  }
}

PolyMesh with_marker_names(PolyMesh mesh) {
  for (std::size_t t = 0; t < mesh.tag_names.size(); ++t)
    mesh.tag_names[t] = "marker_" + std::to_string(t + 1);
  return mesh;
}

TEST(TetgenReader, RoundTripsByEitherNameFromZeroOrOne) {
  TempDir dir;
  const PolyMesh mesh = two_region_tets();
  for (const int first : {0, 1}) {
    write_tetgen(mesh, dir / "cube.1", first);
    expect_same_mesh(with_marker_names(mesh), read_mesh(dir / "cube.1.node"));
    expect_same_mesh(with_marker_names(mesh), read_mesh(dir / "cube.1.ele"));
  }
}

TEST(TetgenReader, WithoutAttributesOrFacesOneRegionOneTag) {
  TempDir dir;
  write_text(dir / "t.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  write_text(dir / "t.ele", "1 4 0\n1 1 2 3 4\n");
  const PolyMesh mesh = read_mesh(dir / "t.ele");
  EXPECT_EQ(mesh.cell_region, std::vector<Index>{1});
  EXPECT_EQ(mesh.tag_names, std::vector<std::string>{"boundary"});
  EXPECT_NEAR(check_validity(mesh).total_volume, 1.0 / 6.0, 1e-15);
}

TEST(TetgenReader, RefusesBadFilesWithOneLine) {
  TempDir dir;
  const std::string node = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  struct Case {
    std::string node, ele, expected;
  };
  const std::vector<Case> cases{
      {node, "1 4 0\n1 1 2 3 5\n", "t.ele: line 2: tetrahedron 1: point 5 out of range (points 1..4)"},
      {node, "1 4 1\n1 1 2 3 4 1.5\n", "tetrahedron 1: region attribute 1.5"},
      {node, "1 6 0\n1 1 2 3 4 1 1\n", "tetrahedra with 6 nodes"},
      {"4 2" + node.substr(3), "", "t.node: line 1: only 3D points are read"},
      {"4 3 0 0\n1 0 0 0\n3 1 0 0\n3 0 1 0\n4 0 0 1\n", "",
       "t.node: line 3: point 3 out of order (2 expected)"},
      {"4 3 0 0\n1 0.0000 0.0000 0.0000\n2 1.0000 0.0000 0.0000\n3 0.0000\n", "",
       "t.node: line 5: unexpected end of file"},
      {"400000000 3 0 0\n", "", "implausible number of points"},
      {node, "", "t.ele: line 1: unexpected end of file"},
  };
  for (const Case& c : cases) {
    write_text(dir / "t.node", c.node);
    write_text(dir / "t.ele", c.ele);
    const std::string error = read_mesh_error(dir / "t.node");
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.expected << " in: " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
  // An inverted tet reads as it is: the validity check (behind `check` and `improve`) tells.
  write_text(dir / "t.node", node);
  write_text(dir / "t.ele", "1 4 0\n1 1 3 2 4\n");
  EXPECT_EQ(check_validity(read_mesh(dir / "t.ele")).non_positive_cells, 1);
  fs::remove(dir / "t.ele");
  EXPECT_NE(read_mesh_error(dir / "t.node").find("t.ele: cannot open"), std::string::npos);
}

}  // namespace
}  // namespace volmesh::test
