// Isoparametric P2 on the unit ball. The meshes: Kuhn-split grids of [-1, 1]³ mapped radially
// onto the ball (x → x‖x‖∞/‖x‖₂), so that every boundary vertex lies on the unit sphere. With
// the sine problem's data on the true sphere, straight P2 is limited by the polyhedral
// boundary (L2 ≈ h²); with the boundary edge nodes on the sphere it converges at h³ in L2 and
// h² in H1, Dirichlet or Neumann. The curved map's volume tends to 4π/3 at h⁴.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fe_space.hpp"
#include "fem_test_meshes.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/fem/fem.hpp"
#include "volmesh/fem/problems.hpp"

namespace volmesh::fem {
namespace {

const std::vector<Index> kCells{4, 6, 8, 12};  // grid cells per axis

PolyMesh ball_mesh(Index n) {
  PolyMesh mesh = to_poly_mesh(kuhn_tet_mesh(Vec3(-1, -1, -1), Vec3(1, 1, 1), {n, n, n}));
  for (Vec3& p : mesh.points)
    if (p.norm() > 0.0) p *= p.lpNorm<Eigen::Infinity>() / p.norm();
  return mesh;
}

// Least-squares slope of log(error) against log(h), h = 1/n.
double slope(const std::vector<double>& errors) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(errors.size());
  for (std::size_t i = 0; i < errors.size(); ++i) {
    const double x = -std::log(static_cast<double>(kCells[i])), y = std::log(errors[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

struct Rates {
  double l2, h1;
};

// The slopes of the P2 errors over kCells for the problem make(mesh) gives, the meshes'
// boundary tags first set by retag(mesh) when given.
template <class Make>
Rates p2_rates(const Make& make, void (*retag)(PolyMesh&) = nullptr) {
  std::vector<double> l2, h1;
  for (Index n : kCells) {
    PolyMesh mesh = ball_mesh(n);
    if (retag) retag(mesh);
    const ScalarSolution s = solve_poisson(mesh, make(mesh), Space::p2);
    l2.push_back(s.errors->l2);
    h1.push_back(s.errors->h1);
  }
  return {slope(l2), slope(h1)};
}

class IsoparametricBall : public ::testing::Test {
 protected:
  std::unique_ptr<Domain> ball = make_builtin_domain("ball");
};

TEST_F(IsoparametricBall, CurvedBoundaryGivesThirdOrder) {
  const Rates curved =
      p2_rates([&](const PolyMesh& mesh) { return make_poisson_problem("sine", *ball, mesh.tag_names); });
  EXPECT_GE(curved.l2, 2.7);
  EXPECT_GE(curved.h1, 1.8);

  // The same data on the true sphere, the edge nodes left at the chords' midpoints (the
  // space sees no boundary map, the Dirichlet data maps the nodes itself): the data are
  // O(h²) off at the edge nodes, exact at the vertices, an error oscillating along the
  // boundary that reaches O(h) deep: L2 ≈ h^2.5.
  const Rates straight = p2_rates([&](const PolyMesh& mesh) {
    PoissonProblem p = make_poisson_problem("sine", *ball, mesh.tag_names);
    const ScalarFunction u = p.exact;
    p.boundary.begin()->second.value = [u](const Vec3& x) { return u(x.normalized()); };
    p.to_true_boundary = nullptr;
    return p;
  });
  EXPECT_NEAR(straight.l2, 2.5, 0.2);
  EXPECT_GT(curved.l2, straight.l2 + 0.3);
}

// Tags the boundary faces above z = 0 "top" (the flux of u given there), the others "bottom".
void split_top_bottom(PolyMesh& mesh) {
  mesh.tag_names = {"bottom", "top"};
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f)) continue;
    double z = 0.0;
    for (Index v : mesh.face(f)) z += mesh.points[v].z();
    mesh.face_tag[f] = z > 0.0 ? 1 : 0;
  }
}

TEST_F(IsoparametricBall, NeumannDataOnCurvedFaces) {
  const Rates curved = p2_rates(
      [&](const PolyMesh& mesh) { return make_poisson_problem("sine-neumann", *ball, mesh.tag_names); },
      split_top_bottom);
  EXPECT_GE(curved.l2, 2.7);
  EXPECT_GE(curved.h1, 1.8);
}

double curved_volume(const PolyMesh& mesh, const PointMap& to_true_boundary) {
  const auto space = detail::make_space(mesh, Space::p2, to_true_boundary);
  detail::CellPoints q;
  double volume = 0.0;
  for (Index c = 0; c < space->num_cells(); ++c) {
    space->cell_points(c, detail::Rule::accurate, q);
    for (double w : q.weight) volume += w;
  }
  return volume;
}

TEST_F(IsoparametricBall, VolumeTendsToTheBallsAtFourthOrder) {
  const double exact = 4.0 * std::numbers::pi / 3.0;
  const PointMap radial = true_boundary_map(*ball);
  std::vector<double> curved, straight;
  for (Index n : kCells) {
    const PolyMesh mesh = ball_mesh(n);
    curved.push_back(std::abs(curved_volume(mesh, radial) - exact));
    straight.push_back(std::abs(curved_volume(mesh, nullptr) - exact));
  }
  EXPECT_GE(slope(curved), 3.7);
  EXPECT_NEAR(slope(straight), 2.0, 0.2);
}

TEST(IsoparametricP2, FlatSidesStayAffine) {
  // On the unit cube every boundary edge's midpoint is its own closest boundary point: the
  // map changes nothing, to the last bit.
  PolyMesh mesh = test::kuhn_cube(3);
  test::tag_cube_sides(mesh);
  const std::unique_ptr<Domain> box = make_builtin_domain("box");
  PoissonProblem p = make_poisson_problem("sine", *box, mesh.tag_names);
  const ScalarSolution mapped = solve_poisson(mesh, p, Space::p2);
  p.to_true_boundary = nullptr;
  const ScalarSolution plain = solve_poisson(mesh, p, Space::p2);
  EXPECT_EQ(mapped.errors->l2, plain.errors->l2);
  EXPECT_EQ(mapped.cell_values, plain.cell_values);
}

TEST(IsoparametricP2, RejectsAFoldingMap) {
  // A flat tet: its base on z = 0 with the corners on the unit circle, its apex 0.01 above.
  // The boundary map pushes the base's edge nodes onto the sphere through the corners
  // centred 5 below, 0.07 up past the apex: the map folds.
  TetMesh tet;
  for (int k = 0; k < 3; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / 3.0;
    tet.points.push_back(Vec3(std::cos(angle), std::sin(angle), 0.0));
  }
  tet.points.push_back(Vec3(0, 0, 0.01));
  tet.cells.push_back({0, 1, 2, 3});
  tet.cell_region.push_back(1);
  const PolyMesh mesh = to_poly_mesh(tet);
  const Vec3 centre(0, 0, -5);
  const double radius = (tet.points[0] - centre).norm();
  const PointMap onto_sphere = [&](const Vec3& x) {
    return Vec3(centre + radius * (x - centre).normalized());
  };
  try {
    detail::make_space(mesh, Space::p2, onto_sphere);
    ADD_FAILURE() << "a folding map was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell 0: the curved P2 tetrahedron"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace volmesh::fem
