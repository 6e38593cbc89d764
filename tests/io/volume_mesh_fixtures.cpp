#include "volume_mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <vector>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh::test {

namespace fs = std::filesystem;

namespace {

Vec3 cell_centroid(const PolyMesh& mesh, const CellFaces& cf, Index c) {
  Vec3 sum = Vec3::Zero();
  int n = 0;
  for (Index f : cf.of(c))
    for (Index v : mesh.face(f)) sum += mesh.points[v], ++n;
  return sum / n;
}

void set_regions(PolyMesh& mesh, int axis, Index region) {
  const CellFaces cf = build_cell_faces(mesh);
  for (Index c = 0; c < mesh.num_cells(); ++c)
    if (cell_centroid(mesh, cf, c)[axis] > 0.5) mesh.cell_region[c] = region;
}

Index point_at(const PolyMesh& mesh, const Vec3& x) {
  auto it = std::find(mesh.points.begin(), mesh.points.end(), x);
  EXPECT_NE(it, mesh.points.end()) << x.transpose();
  return static_cast<Index>(it - mesh.points.begin());
}

// Outward loops of each cell, each rotated to start at its smallest vertex, sorted.
std::vector<std::vector<std::vector<Index>>> canonical_cells(const PolyMesh& mesh) {
  const CellFaces cf = build_cell_faces(mesh);
  std::vector<std::vector<std::vector<Index>>> cells(mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    for (Index f : cf.of(c)) {
      std::vector<Index> loop(mesh.face(f).begin(), mesh.face(f).end());
      if (face_sign(mesh, f, c) < 0) std::reverse(loop.begin(), loop.end());
      std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
      cells[c].push_back(std::move(loop));
    }
    std::sort(cells[c].begin(), cells[c].end());
  }
  return cells;
}

std::map<std::vector<Index>, std::string> boundary_tags(const PolyMesh& mesh) {
  std::map<std::vector<Index>, std::string> tags;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f)) continue;
    std::vector<Index> key(mesh.face(f).begin(), mesh.face(f).end());
    std::sort(key.begin(), key.end());
    tags[key] = mesh.face_tag[f] >= 0 ? mesh.tag_names.at(mesh.face_tag[f]) : "<none>";
  }
  return tags;
}

}  // namespace

PolyMesh two_region_tets() {
  PolyMesh mesh = to_poly_mesh(kuhn_tet_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2}));
  set_regions(mesh, 0, 2);
  return mesh;
}

PolyMesh two_region_hexes() {
  PolyMesh mesh = to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2}));
  set_regions(mesh, 2, 3);
  return mesh;
}

PolyMesh split_face_mesh() {
  PolyMesh mesh = to_poly_mesh(structured_hex_mesh(Vec3(1, 0, 0), Vec3(2, 1, 1), {2, 2, 2}));
  const Index big = mesh.num_cells();
  // The small cubes' faces on x = 1 point in -x, into the big cell: they become internal.
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_boundary(f) && mesh.tag_names[mesh.face_tag[f]] == "xmin") {
      mesh.neighbour[f] = big;
      mesh.face_tag[f] = kNoIndex;
    }
  auto add_point = [&](double y, double z) {
    mesh.points.emplace_back(0.0, y, z);
    return mesh.num_points() - 1;
  };
  const Index a000 = add_point(0, 0), a010 = add_point(1, 0), a001 = add_point(0, 1),
              a011 = add_point(1, 1);
  auto b = [&](double y, double z) { return point_at(mesh, Vec3(1.0, y, z)); };
  const std::vector<std::pair<std::vector<Index>, std::string>> faces{
      {{a000, a001, a011, a010}, "xmin"},
      {{a000, b(0, 0), b(0, 0.5), b(0, 1), a001}, "ymin"},
      {{a010, a011, b(1, 1), b(1, 0.5), b(1, 0)}, "ymax"},
      {{a000, a010, b(1, 0), b(0.5, 0), b(0, 0)}, "zmin"},
      {{a001, b(0, 1), b(0.5, 1), b(1, 1), a011}, "zmax"}};
  for (const auto& [loop, tag] : faces) mesh.add_face(loop, big, kNoIndex, mesh.tag_index(tag));
  mesh.cell_region.push_back(2);
  return mesh;
}

void expect_same_mesh(const PolyMesh& expected, const PolyMesh& actual) {
  ASSERT_EQ(expected.num_points(), actual.num_points());
  for (Index p = 0; p < expected.num_points(); ++p)
    ASSERT_EQ(expected.points[p], actual.points[p]) << "point " << p;
  ASSERT_EQ(expected.num_cells(), actual.num_cells());
  EXPECT_EQ(expected.cell_region, actual.cell_region);
  EXPECT_EQ(expected.num_faces(), actual.num_faces());
  EXPECT_EQ(canonical_cells(expected), canonical_cells(actual));
  EXPECT_EQ(boundary_tags(expected), boundary_tags(actual));
  EXPECT_EQ(expected.tag_names, actual.tag_names);
}

std::map<std::string, long> cell_type_counts(const PolyMesh& mesh) {
  const CellFaces cf = build_cell_faces(mesh);
  std::map<std::string, long> counts{{"points", mesh.num_points()}};
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    switch (classify_cell(mesh, cf, c).shape) {
      case CellShape::Tetrahedron: ++counts["tetra"]; break;
      case CellShape::Hexahedron: ++counts["hexahedron"]; break;
      case CellShape::Polyhedron: {
        std::set<Index> vertices;
        for (Index f : cf.of(c)) vertices.insert(mesh.face(f).begin(), mesh.face(f).end());
        ++counts["polyhedron" + std::to_string(vertices.size())];
      }
    }
  }
  return counts;
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string read_mesh_error(const fs::path& path) {
  try {
    read_mesh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string run_meshio_script(const std::string& script, const std::string& args) {
  const fs::path dir = fs::path(VOLMESH_TEST_SOURCE) / "io" / "external";
  std::string output;
  if (run("/usr/bin/python3 -c 'import meshio'", &output) != 0) {
    ADD_FAILURE() << "/usr/bin/python3 cannot import meshio (`make test` installs python3-meshio): "
                  << output;
    return {};
  }
  const int status = run("/usr/bin/python3 '" + (dir / script).string() + "' " + args, &output);
  EXPECT_EQ(status, 0) << script << " " << args << ":\n" << output;
  return output;
}

namespace {

// One JSON object per file from a script that prints one line each.
std::vector<nlohmann::json> script_objects(const std::string& script, std::string args,
                                           const std::vector<fs::path>& files) {
  for (const auto& file : files) args += " '" + file.string() + "'";
  return json_lines(run_meshio_script(script, args), files.size());
}

}  // namespace

std::vector<nlohmann::json> meshio_read(const std::vector<fs::path>& files) {
  return script_objects("meshio_read.py", "", files);
}

std::vector<nlohmann::json> meshio_region_volumes(const std::vector<fs::path>& files,
                                                  const std::string& region_array) {
  return script_objects("meshio_region_volumes.py",
                        region_array.empty() ? "" : "--region-array '" + region_array + "'", files);
}

void expect_meshio_counts(std::map<std::string, long> expected, const nlohmann::json& seen) {
  EXPECT_EQ(seen.value("points", -1L), expected["points"]);
  expected.erase("points");
  EXPECT_EQ(seen.value("cells", nlohmann::json::object()).get<decltype(expected)>(), expected);
}

bool have_gmsh() {
  if (fs::exists("/usr/bin/gmsh")) return true;
  ADD_FAILURE() << "/usr/bin/gmsh is missing (`make test` installs gmsh)";
  return false;
}

}  // namespace volmesh::test
