// The improvement pass (improve.hpp) on meshes the front made without it: it never lowers the
// minimum quality, keeps the volume, the surface points and every input triangle, leaves every
// tet positive by the exact test and the mesh conforming, and lifts the min dihedral angle
// above a measured floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "improve.hpp"
#include "min_sine.hpp"
#include "predicates.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/quality/tet_metrics.hpp"
#include "front_surfaces.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet {
namespace {

using Tri = std::array<Index, 3>;

using test::surfaces_of;

// Every input triangle in the mesh's numbering (the surfaces' points come first, in order).
std::vector<Tri> input_triangles(const std::vector<ProjectionSurface>& surfaces, Index& points) {
  std::vector<Tri> out;
  points = 0;
  for (const ProjectionSurface& s : surfaces) {
    for (const auto& t : s.surface.triangles) out.push_back({points + t[0], points + t[1], points + t[2]});
    points += s.surface.num_points();
  }
  return out;
}

Tri sorted(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
}

double min_quality(const TetMesh& m) {
  double q = 1.0;
  for (const auto& c : m.cells)
    q = std::min(q, front::min_sine(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]));
  return q;
}

double min_dihedral(const TetMesh& m) {
  double d = 180.0;
  for (const auto& c : m.cells)
    d = std::min(d, tet_metrics(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]])
                        .min_dihedral_deg);
  return d;
}

std::map<Index, double> region_volumes(const TetMesh& m) {
  std::map<Index, double> v;
  for (Index t = 0; t < m.num_cells(); ++t) {
    const auto& c = m.cells[t];
    v[m.cell_region[t]] += tet_volume(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]);
  }
  return v;
}

// Runs the pass on the unimproved mesh and checks what it must keep; returns the result.
TetMesh expect_improved(const std::vector<ProjectionSurface>& surfaces, FrontOptions options,
                        double min_dihedral_floor) {
  options.improve = false;
  const TetMesh before = tetrahedralize_by_front(surfaces, options).mesh;
  Index fixed = 0;
  const std::vector<Tri> kept = input_triangles(surfaces, fixed);
  TetMesh after = before;
  const ImproveStats s = front::improve_mesh(after, fixed, kept);

  EXPECT_GE(min_quality(after), min_quality(before));
  EXPECT_NEAR(s.min_dihedral_before, min_dihedral(before), 1e-12);
  EXPECT_NEAR(s.min_dihedral_after, min_dihedral(after), 1e-12);
  EXPECT_GE(s.min_dihedral_after, min_dihedral_floor);
  EXPECT_GT(s.flips_2_3 + s.flips_3_2 + s.flips_4_4 + s.edge_removals + s.nodes_moved, 0);

  // The surface points stay, the boundary faces and regions too, and so do the volumes.
  EXPECT_TRUE(std::equal(before.points.begin(), before.points.begin() + fixed, after.points.begin()));
  EXPECT_EQ(after.boundary_faces, before.boundary_faces);
  const auto vb = region_volumes(before), va = region_volumes(after);
  EXPECT_EQ(vb.size(), va.size());
  for (const auto& [region, volume] : vb)
    if (va.count(region)) {
      EXPECT_NEAR(va.at(region), volume, 1e-12 * volume);
    }

  // Every tet positive by the exact test; each face shared by two tets, but the outer
  // boundary's faces by one; every input triangle a face.
  std::map<Tri, int> uses;
  Index not_positive = 0;
  for (const auto& c : after.cells) {
    not_positive += !front::positive(after.points[c[0]], after.points[c[1]], after.points[c[2]],
                                     after.points[c[3]]);
    for (const auto& f : kTetFaces) ++uses[sorted({c[f[0]], c[f[1]], c[f[2]]})];
  }
  EXPECT_EQ(not_positive, 0);
  // Collapsed nodes are gone: every point is a corner of a tet.
  std::vector<char> used(after.points.size(), 0);
  for (const auto& c : after.cells)
    for (const Index p : c) used[p] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "points of no tet";
  std::map<Tri, int> expected_uses;
  for (const Tri& f : after.boundary_faces) expected_uses[sorted(f)] = 1;
  Index wrong = 0;
  for (const auto& [face, n] : uses) {
    const auto it = expected_uses.find(face);
    wrong += n != (it == expected_uses.end() ? 2 : 1);
  }
  EXPECT_EQ(wrong, 0) << "faces not shared by exactly two tets (one on the outer boundary)";
  Index lost = 0;
  for (const Tri& t : kept) lost += uses.count(sorted(t)) == 0;
  EXPECT_EQ(lost, 0) << "input triangles no longer faces";
  const ValidityReport v = check_validity(to_poly_mesh(after));
  EXPECT_TRUE(v.valid()) << (v.problems.empty() ? "" : v.problems.front());

  // Deterministic: the same mesh again gives the same bytes.
  TetMesh again = before;
  front::improve_mesh(again, fixed, kept);
  EXPECT_EQ(again.cells, after.cells);
  EXPECT_EQ(again.points, after.points);
  return after;
}

// The paper's example, two regions with the inner cube's triangles between them.
TEST(TetFrontImprove, CubeInclusion) {
  const auto surfaces = surfaces_of(builtin_surfaces("cube-inclusion"));
  const TetMesh m = expect_improved(surfaces, {.size = 2.0}, 25.0);
  EXPECT_EQ(std::set<Index>(m.cell_region.begin(), m.cell_region.end()).size(), 2u);
}

TEST(TetFrontImprove, Sphere) {
  const std::string file = VOLMESH_CGAL_DATA "/meshes/sphere.off";
  expect_improved(surfaces_of({LabelledSurface{read_surface(file), 0, file}}), {.size = 0.1}, 20.0);
}

// A front stopped early leaves most of the ball to the fallback's tets, on the surface points.
TEST(TetFrontImprove, FallbackCavity) {
  const std::string file = VOLMESH_CGAL_DATA "/meshes/sphere.off";
  expect_improved(surfaces_of({LabelledSurface{read_surface(file), 0, file}}),
                  {.size = 0.2, .stop_after = 30}, 25.0);
}

// Most of the ball left to the fallback at a finer size: its cavity mesh and the cones around
// it have short edges, which the collapses remove.
TEST(TetFrontImprove, FallbackShortEdges) {
  const std::string file = VOLMESH_CGAL_DATA "/meshes/sphere.off";
  expect_improved(surfaces_of({LabelledSurface{read_surface(file), 0, file}}),
                  {.size = 0.15, .stop_after = 100}, 25.0);
}

}  // namespace
}  // namespace volmesh::tet
