// Abaqus .inp writer: sets read back by meshio, element-face surfaces checked against the
// face numbering of the Abaqus manual.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "meshio_counts.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volume_mesh_fixtures.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::meshio_counts;
using test::TempDir;

// What the tests need of an .inp file: nodes, elements, surfaces, and every data field.
struct Inp {
  std::map<int, Vec3> nodes;
  std::map<int, std::vector<int>> elements;
  std::map<std::string, std::vector<std::pair<int, int>>> surfaces;  // (element, face S<k>)
  std::vector<std::string> node_fields;                              // coordinates as written
};

Inp parse_inp(const std::string& text) {
  Inp inp;
  std::istringstream lines(text);
  std::string section, surface;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("*", 0) == 0) {
      section = line.substr(1, line.find(',') - 1);
      if (section == "SURFACE") surface = line.substr(line.find("NAME=") + 5);
      continue;
    }
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string f; std::getline(in, f, ',');)
      fields.push_back(f.erase(0, f.find_first_not_of(' ')));
    if (section == "NODE") {
      inp.nodes[std::stoi(fields[0])] =
          Vec3(std::stod(fields[1]), std::stod(fields[2]), std::stod(fields[3]));
      inp.node_fields.insert(inp.node_fields.end(), fields.begin() + 1, fields.end());
    } else if (section == "ELEMENT") {
      auto& nodes = inp.elements[std::stoi(fields[0])];
      for (std::size_t k = 1; k < fields.size(); ++k) nodes.push_back(std::stoi(fields[k]));
    } else if (section == "SURFACE") {
      inp.surfaces[surface].emplace_back(std::stoi(fields[0]), std::stoi(fields[1].substr(1)));
    }
  }
  return inp;
}

// Abaqus manual, "Three-dimensional solid element library": the nodes of faces S1, S2, ...
// of C3D4 and C3D8, numbered counter-clockwise seen from inside the element.
const std::vector<std::vector<int>> kC3D4Faces{{1, 2, 3}, {1, 4, 2}, {2, 4, 3}, {3, 4, 1}};
const std::vector<std::vector<int>> kC3D8Faces{{1, 2, 3, 4}, {5, 8, 7, 6}, {1, 5, 6, 2},
                                               {2, 6, 7, 3}, {3, 7, 8, 4}, {4, 8, 5, 1}};

// Every face of surface `side` ("xmin" ... "zmax") lies on that side of the unit cube, and
// its normal by the manual's node order points into the element.
void expect_surface_on_side(const Inp& inp, const std::string& side, std::size_t faces) {
  const int axis = side[0] - 'x';
  const double plane = side.substr(1) == "max" ? 1.0 : 0.0;
  const auto it = inp.surfaces.find(side);
  ASSERT_NE(it, inp.surfaces.end()) << side;
  EXPECT_EQ(it->second.size(), faces) << side;
  for (const auto& [element, s] : it->second) {
    const std::vector<int>& nodes = inp.elements.at(element);
    const auto& table = nodes.size() == 4 ? kC3D4Faces : kC3D8Faces;
    ASSERT_LE(s, static_cast<int>(table.size()));
    std::vector<Vec3> p;
    for (int local : table[s - 1]) p.push_back(inp.nodes.at(nodes[local - 1]));
    for (const Vec3& q : p) EXPECT_EQ(q[axis], plane) << side << " element " << element;
    const Vec3 normal = (p[1] - p[0]).cross(p[2] - p[0]);
    const double outward = plane == 1.0 ? 1.0 : -1.0;
    EXPECT_LT(normal[axis] * outward, 0) << side << " element " << element << " S" << s;
  }
}

TEST(AbaqusWriter, HexesWithRegionSetsNodeSetsAndSurfaces) {
  TempDir tmp;
  const fs::path path = tmp / "hexes.inp";
  write_mesh(test::two_region_hexes(), path);

  auto m = meshio_counts(path);
  EXPECT_EQ(m["points"], 27);
  EXPECT_EQ(m["cells hexahedron"], 8);
  EXPECT_EQ(m["cellset region_1"], 4);
  EXPECT_EQ(m["cellset region_3"], 4);  // z > 0.5
  for (const char* side : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"})
    EXPECT_EQ(m[std::string("pointset ") + side], 9) << side;
  EXPECT_GT(m["minvolume hexahedron"], 0);
  EXPECT_NEAR(m["volume hexahedron"], 1.0, 1e-12);

  const Inp inp = parse_inp(test::file_bytes(path));
  for (const char* side : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"})
    expect_surface_on_side(inp, side, 4);
}

TEST(AbaqusWriter, TetsWithSurfacesInManualFaceNumbering) {
  TempDir tmp;
  const fs::path path = tmp / "tets.inp";
  write_abaqus(test::two_region_tets(), path);

  auto m = meshio_counts(path);
  EXPECT_EQ(m["cells tetra"], 48);
  EXPECT_EQ(m["cellset region_1"], 24);
  EXPECT_EQ(m["cellset region_2"], 24);
  EXPECT_EQ(m["pointset zmax"], 9);
  EXPECT_GT(m["minvolume tetra"], 0);
  EXPECT_NEAR(m["volume tetra"], 1.0, 1e-12);

  const Inp inp = parse_inp(test::file_bytes(path));
  std::set<int> faces_used;
  for (const char* side : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) {
    expect_surface_on_side(inp, side, 8);
    for (const auto& es : inp.surfaces.at(side)) faces_used.insert(es.second);
  }
  EXPECT_EQ(faces_used, (std::set<int>{1, 2, 3, 4}));  // every face number is exercised
}

TEST(AbaqusWriter, NamesAreSanitisedAndDistinctIgnoringCase) {
  TempDir tmp;
  const fs::path path = tmp / "names.inp";
  PolyMesh mesh = test::two_region_hexes();
  mesh.tag_names = {"outer wall", "Wall", "wall", "1st", "", "a/b"};
  write_abaqus(mesh, path);
  const Inp inp = parse_inp(test::file_bytes(path));
  std::set<std::string> names;
  for (const auto& entry : inp.surfaces) names.insert(entry.first);
  EXPECT_EQ(names,
            (std::set<std::string>{"outer_wall", "Wall", "wall_2", "tag_1st", "tag_", "a_b"}));
}

TEST(AbaqusWriter, CoordinatesFitTwentyCharactersAndKeepTheirPrecision) {
  TempDir tmp;
  const fs::path path = tmp / "small.inp";
  PolyMesh mesh = test::two_region_hexes();
  for (Vec3& p : mesh.points) p = p * (-1.0 / 3.0) * 1e-7 + Vec3(1.0 / 7.0, 0, 0);
  write_abaqus(mesh, path);
  const Inp inp = parse_inp(test::file_bytes(path));
  for (const std::string& field : inp.node_fields) EXPECT_LE(field.size(), 20u) << field;
  for (Index p = 0; p < mesh.num_points(); ++p)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(inp.nodes.at(p + 1)[k], mesh.points[p][k], 1e-13 * std::abs(mesh.points[p][k]));
}

TEST(AbaqusWriter, RefusesPolyhedraNamingTheFirst) {
  TempDir tmp;
  const fs::path path = tmp / "poly.inp";
  try {
    write_mesh(test::split_face_mesh(), path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() +
                  ": cell 8 is a polyhedron with 9 faces; Abaqus output takes tetrahedra and "
                  "hexahedra only (write it with --decompose tets)");
  }
  EXPECT_TRUE(fs::is_empty(path.parent_path()));
}

}  // namespace
}  // namespace volmesh
