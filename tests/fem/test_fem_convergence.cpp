// Convergence on the unit cube with smooth, shifted manufactured solutions: the least-squares
// slope of log(error) against log(h) over the levels is the expected order ± 0.25 — Poisson
// P1 2/1 (L2/H1), P2 3/2, Q1 2/1, the polyhedral space 2/1 on octree meshes with hanging
// faces and on warped cut cells; elasticity P1, Q1 and polyhedral 2/1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "fem_test_meshes.hpp"
#include "volmesh/fem/fem.hpp"

namespace volmesh::fem {
namespace {

// s(x) = Π_k sin(a_k x_k + c_k) with its gradient and Hessian, written out by hand.
struct SineProduct {
  Vec3 a, c;
  double value(const Vec3& x) const {
    return std::sin(a[0] * x[0] + c[0]) * std::sin(a[1] * x[1] + c[1]) *
           std::sin(a[2] * x[2] + c[2]);
  }
  Vec3 gradient(const Vec3& x) const {
    Vec3 s, d;
    for (int k = 0; k < 3; ++k) {
      s[k] = std::sin(a[k] * x[k] + c[k]);
      d[k] = a[k] * std::cos(a[k] * x[k] + c[k]);
    }
    return {d[0] * s[1] * s[2], s[0] * d[1] * s[2], s[0] * s[1] * d[2]};
  }
  Eigen::Matrix3d hessian(const Vec3& x) const {
    Vec3 s, d;
    for (int k = 0; k < 3; ++k) {
      s[k] = std::sin(a[k] * x[k] + c[k]);
      d[k] = a[k] * std::cos(a[k] * x[k] + c[k]);
    }
    Eigen::Matrix3d h;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double product = 1.0;
        for (int k = 0; k < 3; ++k)
          product *= (k == i && k == j) ? -a[k] * a[k] * s[k] : (k == i || k == j) ? d[k] : s[k];
        h(i, j) = product;
      }
    return h;
  }
};

// u = sin(x+0.3)·sin(2y+0.1)·sin(3z+0.7): −Δu = 14u. Dirichlet on the cube's sides but xmax,
// which carries the flux ∂u/∂x.
PoissonProblem sine_poisson() {
  const SineProduct s{Vec3(1, 2, 3), Vec3(0.3, 0.1, 0.7)};
  PoissonProblem p;
  p.conductivity[1] = 1.0;
  p.source = [s](const Vec3& x) { return 14.0 * s.value(x); };
  p.exact = [s](const Vec3& x) { return s.value(x); };
  p.exact_gradient = [s](const Vec3& x) { return s.gradient(x); };
  for (const char* tag : {"xmin", "ymin", "ymax", "zmin", "zmax"})
    p.boundary[tag] = {ScalarBoundaryCondition::Kind::dirichlet, p.exact};
  p.boundary["xmax"] = {ScalarBoundaryCondition::Kind::neumann,
                        [s](const Vec3& x) { return s.gradient(x).x(); }};
  return p;
}

// u_i = Π_k sin(a_ik x_k + c_ik), E = 1, ν = 0.3: b = −μ Δu − (λ+μ) ∇(∇·u); traction σn on
// xmax, displacement elsewhere.
ElasticityProblem sine_elasticity() {
  const std::array<SineProduct, 3> u{SineProduct{Vec3(1, 2, 1.5), Vec3(0.3, 0.1, 0.7)},
                                     SineProduct{Vec3(2, 1, 1), Vec3(0.5, 0.2, 0.1)},
                                     SineProduct{Vec3(1.5, 1, 2), Vec3(0.1, 0.6, 0.4)}};
  const IsotropicMaterial material{1.0, 0.3};
  const LameParameters lame = lame_parameters(material);
  ElasticityProblem p;
  p.material[1] = material;
  p.exact = [u](const Vec3& x) { return Vec3(u[0].value(x), u[1].value(x), u[2].value(x)); };
  p.exact_gradient = [u](const Vec3& x) {
    Eigen::Matrix3d g;
    for (int i = 0; i < 3; ++i) g.row(i) = u[i].gradient(x).transpose();
    return g;
  };
  p.body_force = [u, lame](const Vec3& x) {
    Vec3 b;
    std::array<Eigen::Matrix3d, 3> h;
    for (int i = 0; i < 3; ++i) h[i] = u[i].hessian(x);
    for (int j = 0; j < 3; ++j) {
      double grad_div = 0.0;
      for (int i = 0; i < 3; ++i) grad_div += h[i](i, j);
      b[j] = -lame.mu * h[j].trace() - (lame.lambda + lame.mu) * grad_div;
    }
    return b;
  };
  for (const char* tag : {"xmin", "ymin", "ymax", "zmin", "zmax"})
    p.boundary[tag] = {VectorBoundaryCondition::Kind::displacement, p.exact};
  const auto gradient = p.exact_gradient;
  p.boundary["xmax"] = {VectorBoundaryCondition::Kind::traction, [gradient, lame](const Vec3& x) {
                          return Vec3(isotropic_stress(gradient(x), lame) * Vec3(1, 0, 0));
                        }};
  return p;
}

// Least-squares slope of log(error) against log(h).
double slope(const std::vector<double>& h, const std::vector<double>& error) {
  const std::size_t n = h.size();
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += std::log(h[i]) / n;
    my += std::log(error[i]) / n;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (std::log(h[i]) - mx) * (std::log(error[i]) - my);
    sxx += (std::log(h[i]) - mx) * (std::log(h[i]) - mx);
  }
  return sxy / sxx;
}

// The least-squares orders, and the errors per level for the failure messages.
struct Orders {
  double l2, h1;
  std::string levels;
};

template <class Solve>
Orders measure(const std::vector<Index>& levels, const std::function<PolyMesh(Index)>& mesh_of,
               const std::function<double(Index)>& h_of, Solve solve) {
  std::vector<double> h, l2, h1;
  std::string table;
  for (Index n : levels) {
    const auto errors = solve(mesh_of(n));
    h.push_back(h_of(n));
    l2.push_back(errors.l2);
    h1.push_back(errors.h1);
    char line[96];
    std::snprintf(line, sizeof line, "\n  n %d: h %.4f  L2 %.3e  H1 %.3e", n, h.back(), errors.l2, errors.h1);
    table += line;
  }
  return {slope(h, l2), slope(h, h1), table};
}

// The expected orders within ±0.25 (the least-squares slope over four levels).
void expect_orders(const Orders& o, double l2, double h1) {
  EXPECT_NEAR(o.l2, l2, 0.25) << "L2 order" << o.levels;
  EXPECT_NEAR(o.h1, h1, 0.25) << "H1 order" << o.levels;
}

ErrorNorms poisson_errors(const PolyMesh& mesh, Space space) {
  return *solve_poisson(mesh, sine_poisson(), space).errors;
}
ErrorNorms elasticity_errors(const PolyMesh& mesh, Space space) {
  return *solve_elasticity(mesh, sine_elasticity(), space).errors;
}

const auto inverse = [](Index n) { return 1.0 / n; };
// The checkerboard's finest cells have edge 1/(2n).
const auto half_inverse = [](Index n) { return 0.5 / n; };

TEST(Convergence, PoissonP1) {
  const Orders o = measure({4, 6, 9, 12}, test::kuhn_cube, inverse,
                           [](const PolyMesh& m) { return poisson_errors(m, Space::p1); });
  expect_orders(o, 2.0, 1.0);
}

TEST(Convergence, PoissonP2) {
  const Orders o = measure({2, 3, 4, 6}, test::kuhn_cube, inverse,
                           [](const PolyMesh& m) { return poisson_errors(m, Space::p2); });
  expect_orders(o, 3.0, 2.0);
}

TEST(Convergence, PoissonQ1) {
  const Orders o = measure({4, 6, 9, 12}, test::hex_cube, inverse,
                           [](const PolyMesh& m) { return poisson_errors(m, Space::q1); });
  expect_orders(o, 2.0, 1.0);
}

TEST(Convergence, PoissonPolyhedralOnOctreeCellsWithHangingFaces) {
  const Orders o = measure({2, 3, 4, 6}, test::octree_checkerboard, half_inverse,
                           [](const PolyMesh& m) { return poisson_errors(m, Space::polyhedral); });
  expect_orders(o, 2.0, 1.0);
}

// Cubes cut by a plane into two regions (same conductivity), then warped: polygonal faces
// that are not planar, and cut pieces down to 1% of h thick (the plane passes that close to
// grid vertices at these levels).
PolyMesh warped_cut_cells(Index n) {
  PolyMesh mesh = test::plane_cut_grid(n, Vec3(1.0, 0.6, 0.35), 0.93);
  test::warp(mesh, 0.03);
  return mesh;
}

TEST(Convergence, PoissonPolyhedralOnWarpedCutCells) {
  const Orders o = measure({3, 6, 9, 12}, warped_cut_cells, inverse, [](const PolyMesh& m) {
    PoissonProblem p = sine_poisson();
    p.conductivity[2] = 1.0;
    return *solve_poisson(m, p, Space::polyhedral).errors;
  });
  expect_orders(o, 2.0, 1.0);
}

TEST(Convergence, ElasticityP1) {
  const Orders o = measure({3, 5, 8, 10}, test::kuhn_cube, inverse,
                           [](const PolyMesh& m) { return elasticity_errors(m, Space::p1); });
  expect_orders(o, 2.0, 1.0);
}

TEST(Convergence, ElasticityQ1) {
  const Orders o = measure({3, 5, 8, 10}, test::hex_cube, inverse,
                           [](const PolyMesh& m) { return elasticity_errors(m, Space::q1); });
  expect_orders(o, 2.0, 1.0);
}

TEST(Convergence, ElasticityPolyhedralOnOctreeCellsWithHangingFaces) {
  const Orders o =
      measure({2, 3, 4, 5}, test::octree_checkerboard, half_inverse,
              [](const PolyMesh& m) { return elasticity_errors(m, Space::polyhedral); });
  expect_orders(o, 2.0, 1.0);
}

}  // namespace
}  // namespace volmesh::fem
