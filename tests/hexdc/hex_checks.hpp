#pragma once
// Per-hex access and measures shared by the hexdc tests of meshes after contouring.
#include <array>
#include <cmath>

#include <Eigen/Dense>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh::test_hexdc {

inline std::array<Vec3, 8> corners_of(const HexMesh& mesh, std::size_t h) {
  std::array<Vec3, 8> corners;
  for (std::size_t c = 0; c < 8; ++c) corners[c] = mesh.points[mesh.cells[h][c]];
  return corners;
}

// The trilinear hex's volume: det J integrated by 2x2x2 Gauss points, exact since det J has degree
// at most 2 in each reference coordinate. Neighbours share their bilinear faces, so the sum over a
// conforming mesh is the volume its boundary quads enclose.
inline double hex_volume(const std::array<Vec3, 8>& x) {
  constexpr std::array<std::array<int, 3>, 8> kRef{
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  const double g = 0.5 / std::sqrt(3.0);
  double volume = 0.0;
  for (const auto& gp : kRef) {
    const Vec3 xi(0.5 + (gp[0] != 0 ? g : -g), 0.5 + (gp[1] != 0 ? g : -g),
                  0.5 + (gp[2] != 0 ? g : -g));
    Eigen::Matrix3d jac = Eigen::Matrix3d::Zero();
    for (std::size_t c = 0; c < 8; ++c) {
      Vec3 w, dw;
      for (int a = 0; a < 3; ++a) {
        w[a] = kRef[c][a] != 0 ? xi[a] : 1.0 - xi[a];
        dw[a] = kRef[c][a] != 0 ? 1.0 : -1.0;
      }
      jac.col(0) += x[c] * dw[0] * w[1] * w[2];
      jac.col(1) += x[c] * w[0] * dw[1] * w[2];
      jac.col(2) += x[c] * w[0] * w[1] * dw[2];
    }
    volume += jac.determinant() / 8.0;
  }
  return volume;
}

inline double mesh_volume(const HexMesh& mesh) {
  double sum = 0.0;
  for (std::size_t h = 0; h < mesh.cells.size(); ++h) sum += hex_volume(corners_of(mesh, h));
  return sum;
}

// Hexes failing the ten corner tets.
inline Index invalid_hexes(const HexMesh& mesh) {
  Index n = 0;
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    n += hex_corner_tets_positive(corners_of(mesh, h)) ? 0 : 1;
  return n;
}

}  // namespace volmesh::test_hexdc
