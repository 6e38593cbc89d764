// Q1 on a mesh of hexahedra: the trilinear map of the reference cube, 2×2×2 Gauss points for
// the matrices and loads, 3×3×3 for errors; bilinear faces with 3×3 points.
#include <Eigen/LU>
#include <sstream>

#include "fe_space.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/lagrange.hpp"
#include "volmesh/fem/quadrature.hpp"

namespace volmesh::fem::detail {
namespace {

// Jacobian determinant relative to the product of its column lengths (Verdict's scaled
// Jacobian) at or below which a hex counts as degenerate.
constexpr double kDegenerateShape = 1e-12;

class Q1Space final : public FeSpace {
 public:
  explicit Q1Space(const PolyMesh& mesh) : mesh_(mesh) {
    corners_ = element_corners(mesh, CellShape::Hexahedron, Space::q1);
    check_jacobians();
    std::vector<char> used(mesh.num_points(), 0);
    for (const auto& h : corners_)
      for (Index v : h) used[v] = 1;
    number_used_points(mesh, used, *this);
    cell_node_offsets.resize(corners_.size() + 1);
    cell_node_list.resize(corners_.size() * 8);
    for (std::size_t c = 0; c < corners_.size(); ++c) {
      cell_node_offsets[c + 1] = static_cast<Index>((c + 1) * 8);
      for (int a = 0; a < 8; ++a) cell_node_list[c * 8 + a] = point_node[corners_[c][a]];
    }
  }

  void cell_points(Index c, Rule rule, CellPoints& out) const override {
    out.clear();
    static constexpr std::array<int, 8> kLocal{0, 1, 2, 3, 4, 5, 6, 7};
    out.begin_group(kLocal);
    const auto rule1d = gauss_legendre(rule == Rule::accurate ? 3 : 2);
    std::array<double, 8> n;
    std::array<Vec3, 8> dn;
    for (const auto& qz : rule1d)
      for (const auto& qy : rule1d)
        for (const auto& qx : rule1d) {
          const Vec3 xi(qx.x, qy.x, qz.x);
          q1_hex_values(xi, n);
          q1_hex_reference_gradients(xi, dn);
          Vec3 at = Vec3::Zero();
          const Eigen::Matrix3d j = jacobian(c, dn);
          for (int a = 0; a < 8; ++a) at += n[a] * mesh_.points[corners_[c][a]];
          const Eigen::Matrix3d inverse_transpose = j.inverse().transpose();
          const int i = out.add_point(j.determinant() * qx.weight * qy.weight * qz.weight, at);
          auto v = out.values(i);
          auto g = out.gradients(i);
          for (int a = 0; a < 8; ++a) {
            v[a] = n[a];
            g[a] = inverse_transpose * dn[a];
          }
        }
  }

  void face_nodes(Index f, std::vector<Index>& out) const override {
    out.clear();
    for (Index v : mesh_.face(f)) out.push_back(point_node[v]);
  }

  void face_points(Index f, FacePoints& out) const override {
    out.clear();
    face_nodes(f, out.nodes);
    const auto loop = mesh_.face(f);
    std::array<double, 4> n;
    std::array<Eigen::Vector2d, 4> dn;
    for (const auto& qy : gauss_legendre(3))
      for (const auto& qx : gauss_legendre(3)) {
        q1_quad_values(qx.x, qy.x, n);
        q1_quad_reference_gradients(qx.x, qy.x, dn);
        Vec3 at = Vec3::Zero(), t1 = Vec3::Zero(), t2 = Vec3::Zero();
        for (int a = 0; a < 4; ++a) {
          const Vec3& p = mesh_.points[loop[a]];
          at += n[a] * p;
          t1 += dn[a][0] * p;
          t2 += dn[a][1] * p;
        }
        double* values = out.add_point(t1.cross(t2).norm() * qx.weight * qy.weight, at);
        std::copy(n.begin(), n.end(), values);
      }
  }

 private:
  // J(i, j) = ∂x_i/∂ξ_j.
  Eigen::Matrix3d jacobian(Index c, const std::array<Vec3, 8>& dn) const {
    Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 8; ++a) j += mesh_.points[corners_[c][a]] * dn[a].transpose();
    return j;
  }

  // The worst scaled Jacobian over the corners and the centre, and where it occurs (8: centre).
  std::pair<double, int> worst_jacobian(Index c) const {
    std::pair<double, int> worst{1.0, -1};
    std::array<Vec3, 8> dn;
    for (int k = 0; k <= 8; ++k) {
      const Vec3 xi =
          k < 8 ? Vec3(kHexCorners[k][0], kHexCorners[k][1], kHexCorners[k][2]) : Vec3::Zero();
      q1_hex_reference_gradients(xi, dn);
      const Eigen::Matrix3d j = jacobian(c, dn);
      const double scale = j.col(0).norm() * j.col(1).norm() * j.col(2).norm();
      const double scaled = scale > 0.0 ? j.determinant() / scale : 0.0;
      if (worst.second < 0 || scaled < worst.first) worst = {scaled, k};
    }
    return worst;
  }

  void check_jacobians() const {
    const Index bad = first_cell_where(static_cast<Index>(corners_.size()), [&](Index c) {
      return !(worst_jacobian(c).first > kDegenerateShape);
    });
    if (bad == kNoIndex) return;
    const auto [scaled, at] = worst_jacobian(bad);
    std::ostringstream message;
    message << "mesh: cell " << bad << ": " << (scaled < 0.0 ? "inverted" : "degenerate")
            << " hexahedron (scaled Jacobian " << scaled << " at "
            << (at < 8 ? "corner " + std::to_string(at) : std::string("the centre")) << ")";
    throw InputError(message.str());
  }

  const PolyMesh& mesh_;
  std::vector<std::array<Index, 8>> corners_;
};

}  // namespace

std::unique_ptr<FeSpace> make_q1_space(const PolyMesh& mesh) {
  return std::make_unique<Q1Space>(mesh);
}

}  // namespace volmesh::fem::detail
