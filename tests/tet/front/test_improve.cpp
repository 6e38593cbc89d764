// tet-front's last pass, the mesh improver (volmesh/improve), on the front's meshes: it never
// lowers the worst tet, keeps the regions, their volumes and every input triangle (whole, or
// covered exactly by the pieces the fallback split it into), leaves every tet positive by the
// exact test and the mesh conforming, lifts the min dihedral angle above a measured floor, and
// gives the same bytes for any thread count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "front_surfaces.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/quality/tet_metrics.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet {
namespace {

using Tri = std::array<Index, 3>;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

using test::surfaces_of;

K::Point_3 cg(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

Tri sorted(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
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

double area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

// Each face between two regions or on the boundary lies in one input triangle (its corners in
// the closed triangle, exactly), and the faces in each input triangle add up to its area.
void expect_input_covered(const std::vector<ProjectionSurface>& surfaces, const TetMesh& m) {
  std::vector<K::Triangle_3> input;
  std::vector<double> input_area;
  for (const ProjectionSurface& s : surfaces)
    for (const auto& t : s.surface.triangles) {
      const Vec3 &a = s.surface.points[t[0]], &b = s.surface.points[t[1]], &c = s.surface.points[t[2]];
      input.emplace_back(cg(a), cg(b), cg(c));
      input_area.push_back(area(a, b, c));
    }
  std::map<Tri, std::set<Index>> sides;  // by face: the regions of its tets
  for (Index t = 0; t < m.num_cells(); ++t)
    for (const auto& f : kTetFaces) {
      const auto& c = m.cells[t];
      sides[sorted({c[f[0]], c[f[1]], c[f[2]]})].insert(m.cell_region[t]);
    }
  std::set<Tri> surface_faces;
  for (const Tri& f : m.boundary_faces) surface_faces.insert(sorted(f));
  for (const auto& [face, regions] : sides)
    if (regions.size() == 2) surface_faces.insert(face);
  std::vector<double> covered(input.size(), 0.0);
  Index outside = 0;
  for (const Tri& f : surface_faces) {
    const auto within = [&](const K::Triangle_3& t) {
      return std::all_of(f.begin(), f.end(), [&](Index v) {
        const K::Point_3 p = cg(m.points[v]);
        return CGAL::coplanar(t[0], t[1], t[2], p) && t.has_on(p);
      });
    };
    const auto it = std::find_if(input.begin(), input.end(), within);
    if (it == input.end()) {
      ++outside;
      continue;
    }
    covered[it - input.begin()] += area(m.points[f[0]], m.points[f[1]], m.points[f[2]]);
  }
  EXPECT_EQ(outside, 0) << "boundary or interface faces in no input triangle";
  Index short_of = 0;
  for (std::size_t t = 0; t < input.size(); ++t)
    short_of += std::abs(covered[t] - input_area[t]) > 1e-12 * input_area[t];
  EXPECT_EQ(short_of, 0) << "input triangles not covered exactly by the mesh's faces";
}

FrontResult mesh_with_threads(const std::vector<ProjectionSurface>& surfaces,
                              const FrontOptions& options, int threads) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return tetrahedralize_by_front(surfaces, options);
}

// The front's mesh improved against the same without the pass; returns the improved one.
FrontResult expect_improved(const std::vector<ProjectionSurface>& surfaces, FrontOptions options,
                            double min_dihedral_floor, double max_dihedral_ceiling) {
  options.improve = false;
  const TetMesh before = tetrahedralize_by_front(surfaces, options).mesh;
  options.improve = true;
  FrontResult r = mesh_with_threads(surfaces, options, 1);
  const TetMesh& after = r.mesh;
  const improve::ImproveStats& s = r.stats.improve;

  EXPECT_NEAR(s.before.min_dihedral_deg, min_dihedral(before), 1e-12);
  EXPECT_NEAR(s.after.min_dihedral_deg, min_dihedral(after), 1e-12);
  EXPECT_GE(s.after.min_quality, s.before.min_quality);
  EXPECT_GE(s.after.min_dihedral_deg, min_dihedral_floor);
  EXPECT_LE(s.after.max_dihedral_deg, max_dihedral_ceiling);
  EXPECT_GT(s.passes, 0);

  // The surface points stay first and in place; the regions and their volumes stay.
  Index surface_points = 0;
  for (const ProjectionSurface& p : surfaces) surface_points += p.surface.num_points();
  EXPECT_TRUE(std::equal(before.points.begin(), before.points.begin() + surface_points,
                         after.points.begin()));
  const auto vb = region_volumes(before), va = region_volumes(after);
  EXPECT_EQ(vb.size(), va.size());
  for (const auto& [region, volume] : vb)
    if (va.count(region)) {
      EXPECT_NEAR(va.at(region), volume, 1e-12 * volume);
    }

  // Every tet positive by the exact test; the mesh conforming and closed.
  Index not_positive = 0;
  for (const auto& c : after.cells)
    not_positive += CGAL::orientation(cg(after.points[c[0]]), cg(after.points[c[1]]),
                                      cg(after.points[c[2]]), cg(after.points[c[3]])) != CGAL::POSITIVE;
  EXPECT_EQ(not_positive, 0);
  const ValidityReport v = check_validity(to_poly_mesh(after));
  EXPECT_TRUE(v.valid()) << (v.problems.empty() ? "" : v.problems.front());
  expect_input_covered(surfaces, after);

  // The same bytes with two threads.
  const FrontResult again = mesh_with_threads(surfaces, options, 2);
  EXPECT_EQ(again.mesh.cells, after.cells);
  EXPECT_EQ(again.mesh.points, after.points);
  EXPECT_EQ(again.mesh.cell_region, after.cell_region);
  EXPECT_EQ(again.mesh.boundary_faces, after.boundary_faces);
  return r;
}

std::vector<ProjectionSurface> sphere() {
  const std::string file = VOLMESH_CGAL_DATA "/meshes/sphere.off";
  return surfaces_of({LabelledSurface{read_surface(file), 0, file}});
}

// The paper's example, two regions with the inner cube's triangles between them.
TEST(TetFrontImprove, CubeInclusion) {
  const FrontResult r =
      expect_improved(surfaces_of(builtin_surfaces("cube-inclusion")), {.size = 2.0}, 28.0, 150.0);
  EXPECT_EQ(std::set<Index>(r.mesh.cell_region.begin(), r.mesh.cell_region.end()).size(), 2u);
}

TEST(TetFrontImprove, Sphere) { expect_improved(sphere(), {.size = 0.1}, 28.0, 150.0); }

// A front stopped early leaves most of the ball to the fallback's tets, on the surface points.
TEST(TetFrontImprove, FallbackCavity) {
  expect_improved(sphere(), {.size = 0.2, .stop_after = 30}, 28.0, 150.0);
}

// Most of the ball left to the fallback at a finer size: its cavity mesh and the cones around
// it have short edges, which contractions remove.
TEST(TetFrontImprove, FallbackShortEdges) {
  const FrontResult r = expect_improved(sphere(), {.size = 0.15, .stop_after = 100}, 28.0, 150.0);
  EXPECT_GT(r.stats.improve.operations.contractions, 0);
}

}  // namespace
}  // namespace volmesh::tet
