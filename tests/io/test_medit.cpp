// MEDIT .mesh writer, read back by meshio (Debian's python3-meshio).
#include <gtest/gtest.h>

#include "meshio_counts.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volume_mesh_fixtures.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::meshio_counts;
using test::TempDir;

// Volume bounded by the faces with references first..last, by the divergence theorem:
// positive when their normals point outward.
double enclosed(std::map<std::string, double>& m, int first, int last) {
  double sum = 0;
  for (int ref = first; ref <= last; ++ref) sum += m["enclosed " + std::to_string(ref)];
  return sum;
}

TEST(MeditWriter, HexesWithRegionBoundaryAndInterfaceReferences) {
  TempDir tmp;
  const fs::path path = tmp / "hexes.mesh";
  write_mesh(test::two_region_hexes(), path);

  auto m = meshio_counts(path);
  EXPECT_EQ(m["points"], 27);
  EXPECT_EQ(m["cells hexahedron"], 8);
  EXPECT_EQ(m["ref hexahedron 1"], 4);
  EXPECT_EQ(m["ref hexahedron 3"], 4);  // z > 0.5
  // Boundary quads carry tag + 1 (xmin = 1 ... zmax = 6); the 4 quads between regions 1 and
  // 3 come next, with reference 7.
  for (int ref = 1; ref <= 7; ++ref) EXPECT_EQ(m["ref quad " + std::to_string(ref)], 4) << ref;
  EXPECT_EQ(m["cells quad"], 28);
  EXPECT_EQ(m.count("cells tetra"), 0u);
  EXPECT_GT(m["minvolume hexahedron"], 0);  // MEDIT's hex corner order is VTK's
  EXPECT_NEAR(m["volume hexahedron"], 1.0, 1e-12);
  EXPECT_NEAR(enclosed(m, 1, 6), 1.0, 1e-12);  // boundary normals point outward
  // The interface z = 1/2 points from region 1 to region 3 (+z): z * area / 3 = 1/6.
  EXPECT_NEAR(enclosed(m, 7, 7), 1.0 / 6.0, 1e-12);

  const std::string text = test::file_bytes(path);
  EXPECT_EQ(text.rfind("MeshVersionFormatted 2\n", 0), 0u);
  EXPECT_NE(text.find("# 1 boundary xmin\n"), std::string::npos) << text;
  EXPECT_NE(text.find("# 7 interface between regions 1 and 3\n"), std::string::npos) << text;
}

TEST(MeditWriter, TetsArePositivelyOriented) {
  TempDir tmp;
  const fs::path path = tmp / "tets.mesh";
  PolyMesh mesh = test::two_region_tets();
  // Region 2 on the left (x < 1/2), where the owners of the interface faces are.
  for (Index& r : mesh.cell_region) r = 3 - r;
  write_medit(mesh, path);

  auto m = meshio_counts(path);
  EXPECT_EQ(m["cells tetra"], 48);
  EXPECT_EQ(m["ref tetra 1"], 24);
  EXPECT_EQ(m["ref tetra 2"], 24);
  // MMG, like VTK, calls a tet positive when det(p1-p0, p2-p0, p3-p0) > 0; meshio reads the
  // corners as written and finds every tet positive.
  EXPECT_GT(m["minvolume tetra"], 0);
  EXPECT_NEAR(m["volume tetra"], 1.0, 1e-12);
  EXPECT_EQ(m["cells triangle"], 48 + 8);  // 8 per side, 8 on the interface x = 1/2
  EXPECT_NEAR(enclosed(m, 1, 6), 1.0, 1e-12);
  // The interface x = 1/2 points from region 1 to region 2 (-x), against its owners.
  EXPECT_NEAR(enclosed(m, 7, 7), -0.5 / 3.0, 1e-12);
}

TEST(MeditWriter, RefusesPolyhedraNamingTheFirstAndLeavesNoFile) {
  TempDir tmp;
  const fs::path path = tmp / "poly.mesh";
  try {
    write_medit(test::split_face_mesh(), path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() +
                  ": cell 8 is a polyhedron with 9 faces; MEDIT output takes tetrahedra and "
                  "hexahedra only (write it with --decompose tets)");
  }
  EXPECT_TRUE(fs::is_empty(path.parent_path()));
}

}  // namespace
}  // namespace volmesh
