// tet-front's graded sizes: the size field is the capped, rate-limited envelope of the boundary
// points' sizes (checked against its definition point by point), the auxiliary cells follow it
// (far fewer points than a grid at the smallest size), and a size far above the boundary's
// triangles gives a valid mesh of a bounded number of tets, the same for one and two threads;
// --interior-size lowers the count, and absurd interior sizes are refused.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "aux_grid.hpp"
#include "split_checks.hpp"
#include "front_surfaces.hpp"
#include "size_field.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

const std::string kCactus = VOLMESH_CGAL_DATA "/meshes/cactus.off";
// cactus.off's mean edge is 0.046: ten times it.
constexpr double kTenTimesCactusEdge = 0.46;

std::vector<ProjectionSurface> cactus() {
  return test::surfaces_of({LabelledSurface{read_surface(kCactus), 0, kCactus}});
}

std::pair<Vec3, Vec3> box_of(const TriSurface& s) {
  Vec3 lo = s.points.front(), hi = lo;
  for (const Vec3& p : s.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

// The field's definition, by brute force: each point's mean incident edge (the size where it
// fits), then the capped envelope.
double envelope(const TriSurface& s, double size, double cap, const Vec3& x) {
  std::vector<double> sum(s.points.size(), 0.0);
  std::vector<int> count(s.points.size(), 0);
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) {
      const double l = (s.points[t[k]] - s.points[t[(k + 1) % 3]]).norm();
      sum[t[k]] += l;
      sum[t[(k + 1) % 3]] += l;
      ++count[t[k]];
      ++count[t[(k + 1) % 3]];
    }
  double h = cap;
  for (std::size_t p = 0; p < s.points.size(); ++p) {
    const double mean = sum[p] / count[p];
    const double e = mean * front::kFitRatio >= size ? size : mean;
    h = std::min(h, e + front::kGradingRate * (x - s.points[p]).norm());
  }
  return h;
}

// Points on a lattice over the box, a little beyond it.
std::vector<Vec3> lattice(const Vec3& lo, const Vec3& hi, int n) {
  std::vector<Vec3> out;
  const Vec3 margin = 0.1 * (hi - lo);
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        out.push_back(lo - margin + (hi - lo + 2.0 * margin).cwiseProduct(Vec3(i, j, k) / n));
  return out;
}

TEST(SizeField, IsTheCappedEnvelopeOfTheBoundarySizes) {
  const TriSurface s = read_surface(kCactus);
  const auto [lo, hi] = box_of(s);
  constexpr int kSteps = 12;
  for (const auto& [size, interior] : {std::pair{0.2, 0.0}, std::pair{0.05, 0.3}}) {
    const front::SizeField field(s.points, s.triangles, size, interior);
    const double cap = std::max(size, interior);
    EXPECT_EQ(field.cap(), cap);
    EXPECT_EQ(field.rate(), front::kGradingRate);
    const std::vector<Vec3> xs = lattice(lo, hi, kSteps);
    for (const Vec3& x : xs) {
      const double h = field.at(x);
      EXPECT_NEAR(h, envelope(s, size, cap, x), 1e-14) << x.transpose();
      EXPECT_GE(h, field.min());
      EXPECT_LE(h, cap);
    }
    // The gradient bound, between lattice neighbours and at the boundary points.
    for (std::size_t a = 1; a < xs.size(); ++a)
      EXPECT_LE(std::abs(field.at(xs[a]) - field.at(xs[a - 1])),
                front::kGradingRate * (xs[a] - xs[a - 1]).norm() * (1.0 + 1e-12));
    for (const Vec3& p : s.points) EXPECT_LE(field.at(p), size);
  }
}

// A boundary whose points fit the size (mean edge at least size / 1.5) gives the uniform size.
TEST(SizeField, IsUniformWhereTheBoundaryFitsTheSize) {
  const TriSurface s = read_surface(kCactus);
  const front::SizeField field(s.points, s.triangles, 0.02, 0.0);
  EXPECT_TRUE(field.uniform());
  EXPECT_EQ(field.rate(), 0.0);
  EXPECT_EQ(field.at(s.points.front()), 0.02);
  EXPECT_EQ(field.min(), 0.02);
}

// The auxiliary cells follow the field: each leaf's side within twice the least size below it,
// and far fewer points than a grid at the field's smallest size where the boundary is fine in
// places only (elephant: a fiftieth, its edges down to a quarter of their mean); cactus, thin
// everywhere, stays near the boundary's size throughout.
TEST(AuxCells, FollowTheLocalSize) {
  const std::string elephant = VOLMESH_CGAL_DATA "/meshes/elephant.off";
  for (const auto& [file, size, fewer] :
       {std::tuple{kCactus, kTenTimesCactusEdge, 0.5}, std::tuple{elephant, 0.2, 50.0}}) {
    const TriSurface s = read_surface(file);
    const auto [lo, hi] = box_of(s);
    const front::SizeField field(s.points, s.triangles, size, 0.0);
    const front::AuxCells cells =
        front::make_aux_cells(lo, hi, field, kDefaultAuxRatio, front::kMaxAuxPoints);
    EXPECT_GT(cells.finest, 0) << file;
    for (const front::AuxLeaf& leaf : cells.leaves) {
      const double side = cells.side(leaf.level);
      const Vec3 corner = cells.leaf_lo(leaf);
      const double least = field.min_in_box(corner, corner + Vec3::Constant(side));
      EXPECT_LE(side, 2.0 * least * (1.0 + 1e-12)) << file;
      if (leaf.level > 0) EXPECT_GT(4.0 * side, least) << file;  // its parent was too coarse
    }
    EXPECT_EQ(front::aux_cell_points(cells),
              front::aux_points_needed(lo, hi, field, kDefaultAuxRatio));
    EXPECT_LT(front::aux_cell_points(cells),
              front::aux_grid_points(lo, hi, field.min() / kDefaultAuxRatio) / fewer)
        << file;
  }
}

// A grid of one step (for a uniform size) is reached point by point: alive exactly strictly
// inside the cube [0.25, 0.75]^3, and as many alive as it counts.
TEST(AuxCells, AUniformGridIsIndexedByItsPoints) {
  const TriSurface cube = read_surface(VOLMESH_TEST_DATA "/domains/inner_cube.off");
  const front::AuxGrid g = front::make_aux_grid(cube.points, cube.triangles, 0.03);
  ASSERT_GT(g.n[0], 0);
  long long alive = 0, wrong = 0;
  for (long long k = 0; k < g.n[2]; ++k)
    for (long long j = 0; j < g.n[1]; ++j)
      for (long long i = 0; i < g.n[0]; ++i) {
        const Vec3 p = g.point(i, j, k);
        const bool inside = (p.array() > 0.25).all() && (p.array() < 0.75).all();
        const bool live = g.alive(g.at(i, j, k));
        alive += live;
        wrong += live != inside;
      }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(alive, g.live);
  EXPECT_GT(alive, 0);
}

FrontResult mesh_with_threads(const std::vector<ProjectionSurface>& surfaces,
                              const FrontOptions& options, int threads) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return tetrahedralize_by_front(surfaces, options);
}

// At ten times the boundary's mean edge the front grades from the boundary's size: a valid mesh
// (every tet positive by the exact test, conforming, its volume, the input triangles kept) of at
// most ten tets per input triangle, the same bytes for one and two threads.
TEST(TetFrontGrading, SizeFarAboveTheBoundaryGivesAValidMesh) {
  const auto surfaces = cactus();
  const FrontOptions options{.size = kTenTimesCactusEdge};
  const FrontResult r = mesh_with_threads(surfaces, options, 1);
  test::expect_valid_with_splits(surfaces[0].surface, r);
  Index not_positive = 0;
  const auto cg = [&](Index v) {
    const Vec3& p = r.mesh.points[v];
    return K::Point_3(p.x(), p.y(), p.z());
  };
  for (const auto& c : r.mesh.cells)
    not_positive += CGAL::orientation(cg(c[0]), cg(c[1]), cg(c[2]), cg(c[3])) != CGAL::POSITIVE;
  EXPECT_EQ(not_positive, 0);
  EXPECT_LE(r.mesh.num_cells(), 10 * surfaces[0].surface.num_triangles());
  EXPECT_EQ(r.stats.size_max, kTenTimesCactusEdge);
  EXPECT_LT(r.stats.size_min, kTenTimesCactusEdge / 10.0);
  EXPECT_EQ(r.stats.grading_rate, front::kGradingRate);

  const FrontResult again = mesh_with_threads(surfaces, options, 2);
  EXPECT_EQ(again.mesh.cells, r.mesh.cells);
  EXPECT_EQ(again.mesh.points, r.mesh.points);
  EXPECT_EQ(again.mesh.boundary_faces, r.mesh.boundary_faces);
}

// Growing the size inward past --size makes fewer tets, the mesh valid either way.
TEST(TetFrontGrading, InteriorSizeMakesFewerTets) {
  const auto surfaces = cactus();
  constexpr double kSize = 0.05, kInterior = 0.2;
  const FrontResult fine = tetrahedralize_by_front(surfaces, {.size = kSize, .improve = false});
  const FrontResult graded = tetrahedralize_by_front(
      surfaces, {.size = kSize, .improve = false, .interior_size = kInterior});
  test::expect_valid_with_splits(surfaces[0].surface, fine);
  test::expect_valid_with_splits(surfaces[0].surface, graded);
  EXPECT_EQ(graded.stats.size_max, kInterior);
  EXPECT_LT(graded.mesh.num_cells(), fine.mesh.num_cells());
}

TEST(TetFrontGrading, AbsurdInteriorSizesAreRefused) {
  const auto surfaces = cactus();
  const auto [lo, hi] = box_of(surfaces[0].surface);
  const double inf = std::numeric_limits<double>::infinity();
  // 0 is FrontOptions' "none", but no interior size --interior-size can give.
  EXPECT_THROW(require_front_interior_size("cactus.off", 0.0, 0.05, lo, hi), InputError);
  for (const double bad : {-1.0, inf, std::numeric_limits<double>::quiet_NaN(), 0.01, 1e3}) {
    EXPECT_THROW(require_front_interior_size("cactus.off", bad, 0.05, lo, hi), InputError) << bad;
    EXPECT_THROW(tetrahedralize_by_front(surfaces, {.size = 0.05, .interior_size = bad}),
                 InputError)
        << bad;
  }
  try {
    require_front_interior_size("cactus.off", 0.01, 0.05, lo, hi);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "tet-front: cactus.off: --interior-size 0.01 is smaller than --size 0.05");
  }
}

}  // namespace
}  // namespace volmesh::tet
