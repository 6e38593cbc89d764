#include "volmesh/fem/quadrature.hpp"

#include <stdexcept>
#include <string>

namespace volmesh::fem {
namespace {

constexpr TetQuadraturePoint tet_point(double a, double b, double c, double d, double w) {
  return {{a, b, c, d}, w};
}

constexpr std::array<TetQuadraturePoint, 1> kTet1{tet_point(0.25, 0.25, 0.25, 0.25, 1.0)};

constexpr double kTet2a = 0.5854101966249685, kTet2b = 0.1381966011250105;
constexpr std::array<TetQuadraturePoint, 4> kTet2{tet_point(kTet2a, kTet2b, kTet2b, kTet2b, 0.25),
                                                  tet_point(kTet2b, kTet2a, kTet2b, kTet2b, 0.25),
                                                  tet_point(kTet2b, kTet2b, kTet2a, kTet2b, 0.25),
                                                  tet_point(kTet2b, kTet2b, kTet2b, kTet2a, 0.25)};

// Walkington, "Quadrature on simplices of arbitrary dimension" (2000), the 14-point
// degree-5 rule; weights normalised to sum 1.
constexpr double kTet5a = 0.31088591926330060980, kTet5A = 1.0 - 3.0 * kTet5a;
constexpr double kTet5b = 0.092735250310891226402, kTet5B = 1.0 - 3.0 * kTet5b;
constexpr double kTet5c = 0.045503704125649649492, kTet5C = 0.5 - kTet5c;
constexpr double kTet5wa = 6.0 * 0.018781320953002641800;
constexpr double kTet5wb = 6.0 * 0.012248840519393658257;
constexpr double kTet5wc = 6.0 * 0.0070910034628469110730;
constexpr std::array<TetQuadraturePoint, 14> kTet5{
    tet_point(kTet5A, kTet5a, kTet5a, kTet5a, kTet5wa),
    tet_point(kTet5a, kTet5A, kTet5a, kTet5a, kTet5wa),
    tet_point(kTet5a, kTet5a, kTet5A, kTet5a, kTet5wa),
    tet_point(kTet5a, kTet5a, kTet5a, kTet5A, kTet5wa),
    tet_point(kTet5B, kTet5b, kTet5b, kTet5b, kTet5wb),
    tet_point(kTet5b, kTet5B, kTet5b, kTet5b, kTet5wb),
    tet_point(kTet5b, kTet5b, kTet5B, kTet5b, kTet5wb),
    tet_point(kTet5b, kTet5b, kTet5b, kTet5B, kTet5wb),
    tet_point(kTet5C, kTet5C, kTet5c, kTet5c, kTet5wc),
    tet_point(kTet5C, kTet5c, kTet5C, kTet5c, kTet5wc),
    tet_point(kTet5C, kTet5c, kTet5c, kTet5C, kTet5wc),
    tet_point(kTet5c, kTet5C, kTet5C, kTet5c, kTet5wc),
    tet_point(kTet5c, kTet5C, kTet5c, kTet5C, kTet5wc),
    tet_point(kTet5c, kTet5c, kTet5C, kTet5C, kTet5wc)};

constexpr TriangleQuadraturePoint tri_point(double a, double b, double c, double w) {
  return {{a, b, c}, w};
}

constexpr std::array<TriangleQuadraturePoint, 1> kTri1{tri_point(1.0 / 3, 1.0 / 3, 1.0 / 3, 1.0)};
constexpr std::array<TriangleQuadraturePoint, 3> kTri2{
    tri_point(2.0 / 3, 1.0 / 6, 1.0 / 6, 1.0 / 3), tri_point(1.0 / 6, 2.0 / 3, 1.0 / 6, 1.0 / 3),
    tri_point(1.0 / 6, 1.0 / 6, 2.0 / 3, 1.0 / 3)};

// Dunavant, "High degree efficient symmetrical Gaussian quadrature rules for the triangle"
// (1985), the 7-point degree-5 rule.
constexpr double kTri5a = 0.470142064105115, kTri5A = 1.0 - 2.0 * kTri5a;
constexpr double kTri5b = 0.101286507323456, kTri5B = 1.0 - 2.0 * kTri5b;
constexpr double kTri5wa = 0.132394152788506, kTri5wb = 0.125939180544827;
constexpr std::array<TriangleQuadraturePoint, 7> kTri5{
    tri_point(1.0 / 3, 1.0 / 3, 1.0 / 3, 0.225), tri_point(kTri5A, kTri5a, kTri5a, kTri5wa),
    tri_point(kTri5a, kTri5A, kTri5a, kTri5wa),  tri_point(kTri5a, kTri5a, kTri5A, kTri5wa),
    tri_point(kTri5B, kTri5b, kTri5b, kTri5wb),  tri_point(kTri5b, kTri5B, kTri5b, kTri5wb),
    tri_point(kTri5b, kTri5b, kTri5B, kTri5wb)};

constexpr std::array<GaussPoint, 1> kGauss1{{{0.0, 2.0}}};
constexpr double kGauss2x = 0.57735026918962576451;  // 1/√3
constexpr std::array<GaussPoint, 2> kGauss2{{{-kGauss2x, 1.0}, {kGauss2x, 1.0}}};
constexpr double kGauss3x = 0.77459666924148337704;  // √(3/5)
constexpr std::array<GaussPoint, 3> kGauss3{
    {{-kGauss3x, 5.0 / 9.0}, {0.0, 8.0 / 9.0}, {kGauss3x, 5.0 / 9.0}}};
constexpr double kGauss4x0 = 0.33998104358485626480, kGauss4x1 = 0.86113631159405257522;
constexpr double kGauss4w0 = 0.65214515486254614263, kGauss4w1 = 0.34785484513745385737;
constexpr std::array<GaussPoint, 4> kGauss4{{{-kGauss4x1, kGauss4w1},
                                             {-kGauss4x0, kGauss4w0},
                                             {kGauss4x0, kGauss4w0},
                                             {kGauss4x1, kGauss4w1}}};

}  // namespace

std::span<const TetQuadraturePoint> tet_rule(int degree) {
  if (degree <= 1) return kTet1;
  if (degree == 2) return kTet2;
  if (degree <= 5) return kTet5;
  throw std::invalid_argument("tet_rule: no stored rule of degree " + std::to_string(degree));
}

std::span<const TriangleQuadraturePoint> triangle_rule(int degree) {
  if (degree <= 1) return kTri1;
  if (degree == 2) return kTri2;
  if (degree <= 5) return kTri5;
  throw std::invalid_argument("triangle_rule: no stored rule of degree " + std::to_string(degree));
}

std::span<const GaussPoint> gauss_legendre(int n) {
  switch (n) {
    case 1:
      return kGauss1;
    case 2:
      return kGauss2;
    case 3:
      return kGauss3;
    case 4:
      return kGauss4;
    default:
      throw std::invalid_argument("gauss_legendre: no stored rule with " + std::to_string(n) +
                                  " points");
  }
}

}  // namespace volmesh::fem
