// The staircase mesher: valid polyhedral meshes, first-order volumes, determinism, errors.
#include <gtest/gtest.h>

#include <oneapi/tbb/global_control.h>

#include <cmath>
#include <map>
#include <numbers>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/domain/analytic.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/octree/staircase.hpp"

namespace volmesh {
namespace {

PolyMesh staircase(const Domain& domain, int level, StaircaseStats* stats = nullptr) {
  StaircaseOptions options;
  options.octree.level = level;
  return staircase_mesh(domain, options, stats);
}

void expect_valid(const PolyMesh& mesh) {
  const ValidityReport r = check_validity(mesh);
  EXPECT_TRUE(r.valid()) << (r.problems.empty() ? std::string() : r.problems.front());
  EXPECT_EQ(r.unused_points, 0);
}

double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += std::log(x[i]) / x.size();
    my += std::log(y[i]) / x.size();
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

// Area of the faces separating region r from anything else (another region or outside).
std::map<Index, double> region_boundary_area(const PolyMesh& mesh) {
  std::map<Index, double> area;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Index a = mesh.cell_region[mesh.owner[f]];
    const Index b = mesh.is_boundary(f) ? 0 : mesh.cell_region[mesh.neighbour[f]];
    if (a == b) continue;
    Vec3 n = Vec3::Zero();
    const auto loop = mesh.face(f);
    for (std::size_t k = 0; k < loop.size(); ++k)
      n += mesh.points[loop[k]].cross(mesh.points[loop[(k + 1) % loop.size()]]);
    area[a] += 0.5 * n.norm();
    if (b != 0) area[b] += 0.5 * n.norm();
  }
  return area;
}

// Centre classification moves the boundary by at most half a cell diagonal, so the volume
// error is first order, but its signs cancel irregularly from level to level (a lattice
// point count); the boundary's distance to the sphere shows the first order cleanly.
TEST(Staircase, BallIsValidAndConvergesAtFirstOrder) {
  const auto ball = make_builtin_domain("ball");
  const double exact = 4.0 * std::numbers::pi / 3.0;
  std::vector<double> h, distance;
  for (int level = 3; level <= 6; ++level) {
    StaircaseStats stats;
    const PolyMesh mesh = staircase(*ball, level, &stats);
    const ValidityReport validity = check_validity(mesh);
    EXPECT_TRUE(validity.valid()) << validity.problems.front();
    EXPECT_EQ(validity.unused_points, 0);
    EXPECT_EQ(stats.cells, mesh.num_cells());
    EXPECT_EQ(stats.level, level);
    h.push_back(std::ldexp(2.2, -level));  // root: the bounding box's side * 1.1
    const double volume = validity.total_volume;
    EXPECT_LT(std::abs(volume - exact), 0.5 * std::sqrt(3.0) * h.back() * 4.0 * std::numbers::pi);
    double worst = 0.0;
    for (Index f = 0; f < mesh.num_faces(); ++f)
      if (mesh.is_boundary(f))
        for (const Index v : mesh.face(f))
          worst = std::max(worst, std::abs(mesh.points[v].norm() - 1.0));
    EXPECT_LE(worst, std::sqrt(3.0) * h.back());
    distance.push_back(worst);
    if (level == 6) {
      EXPECT_NEAR(volume, exact, 1e-3 * exact);
    }
  }
  const double rate = slope(h, distance);
  EXPECT_GT(rate, 0.6);
  EXPECT_LT(rate, 1.4);
}

TEST(Staircase, PrimitivesHaveEveryRegionWithFirstOrderVolumes) {
  const auto domain = make_builtin_domain("primitives");
  const std::map<Index, double> exact = builtin_region_volumes("primitives");
  const PolyMesh mesh = staircase(*domain, 5);
  const ValidityReport r = check_validity(mesh);
  ASSERT_TRUE(r.valid()) << r.problems.front();
  ASSERT_EQ(r.region_volume.size(), 7u);
  const auto area = region_boundary_area(mesh);
  const double h = std::ldexp(2.8 * 1.1, -5);
  for (const auto& [region, volume] : exact)
    EXPECT_LT(std::abs(r.region_volume.at(region) - volume), 0.5 * h * area.at(region)) << region;
  // Interfaces between regions stay internal faces.
  Index interface_faces = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (!mesh.is_boundary(f) &&
        mesh.cell_region[mesh.owner[f]] != mesh.cell_region[mesh.neighbour[f]])
      ++interface_faces;
  EXPECT_GT(interface_faces, 100);
}

TEST(Staircase, BigCellNextToFourSmallOnesHasFourFacesThereAndCloses) {
  Octree tree(Vec3::Zero(), 1.0);
  tree.split(std::vector<Index>{0});
  tree.split(std::vector<Index>{0});  // the octant at the origin
  const AnalyticDomain all({box(Vec3::Constant(-1.0), Vec3::Constant(2.0))}, {0, 1});
  const PolyMesh mesh = staircase_cells(tree, all);
  ASSERT_EQ(mesh.num_cells(), 15);
  expect_valid(mesh);
  EXPECT_NEAR(check_validity(mesh).total_volume, 1.0, 1e-12);
  // The octant at x in [1/2, 1], y, z in [0, 1/2] is cell 8 of 15 in Morton order
  // (after the eight small ones). Its -x side has four faces.
  const Index big = 8;
  int on_minus_x = 0, total = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.owner[f] != big && mesh.neighbour[f] != big) continue;
    ++total;
    bool all_at_half = true;
    for (const Index v : mesh.face(f)) all_at_half = all_at_half && mesh.points[v].x() == 0.5;
    on_minus_x += all_at_half;
  }
  EXPECT_EQ(on_minus_x, 4);
  // Its four other faces along the small block's edges list the hanging mid-edge vertex.
  EXPECT_EQ(total, 4 + 5);
  Index five = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if ((mesh.owner[f] == big || mesh.neighbour[f] == big) && mesh.face(f).size() == 5) ++five;
  EXPECT_EQ(five, 4);
}

TEST(Staircase, SameMeshForOneAndTwoThreads) {
  const auto domain = make_builtin_domain("primitives");
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return staircase(*domain, 4);
  };
  const PolyMesh one = run(1), two = run(2);
  EXPECT_EQ(one.points, two.points);
  EXPECT_EQ(one.face_offsets, two.face_offsets);
  EXPECT_EQ(one.face_vertices, two.face_vertices);
  EXPECT_EQ(one.owner, two.owner);
  EXPECT_EQ(one.neighbour, two.neighbour);
  EXPECT_EQ(one.face_tag, two.face_tag);
  EXPECT_EQ(one.cell_region, two.cell_region);
  EXPECT_EQ(one.tag_names, two.tag_names);
}

TEST(Staircase, BoundaryFacesAreTaggedByBoundaryName) {
  const auto domain = make_builtin_domain("thick-sphere");
  const PolyMesh mesh = staircase(*domain, 4);
  expect_valid(mesh);
  std::vector<std::string> names = mesh.tag_names;
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"inner", "outer"}));
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_boundary(f)) {
      Vec3 c = Vec3::Zero();
      for (const Index v : mesh.face(f)) c += mesh.points[v];
      c /= static_cast<double>(mesh.face(f).size());
      EXPECT_EQ(mesh.tag_names[mesh.face_tag[f]], c.norm() < 0.75 ? "inner" : "outer");
    }
}

TEST(Staircase, DomainThinnerThanACellIsAnInputError) {
  const AnalyticDomain plate({box(Vec3(0.0, 0.0, 0.0), Vec3(1.0, 1.0, 0.01))}, {0, 1});
  StaircaseOptions options;
  options.octree.level = 2;
  try {
    staircase_mesh(plate, options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("thinner than one cell"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volmesh
