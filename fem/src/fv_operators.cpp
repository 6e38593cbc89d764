// The finite-volume operators: two-point matrix, right-hand sides, gradients, corrections.
#include <tbb/parallel_for.h>

#include <algorithm>

#include "fv_system.hpp"

namespace volmesh::fem {

Eigen::SparseMatrix<double> fv_matrix(const PolyMesh& mesh, const FvSystem& s) {
  const Index nc = mesh.num_cells();
  std::vector<double> diagonal(nc, 0.0);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(nc) + mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const double a = s.coefficient[f];
    const Index p = mesh.owner[f];
    if (s.kind[f] == FvFace::neumann) continue;
    diagonal[p] += a;
    if (mesh.is_boundary(f)) continue;
    const Index q = mesh.neighbour[f];
    diagonal[q] += a;
    entries.emplace_back(std::max(p, q), std::min(p, q), -a);
  }
  for (Index c = 0; c < nc; ++c) entries.emplace_back(c, c, diagonal[c]);
  Eigen::SparseMatrix<double> a(nc, nc);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

Eigen::VectorXd fv_base_rhs(const PolyMesh& mesh, const FvSystem& s,
                            const PoissonProblem& problem) {
  Eigen::VectorXd b(mesh.num_cells());
  tbb::parallel_for(Index{0}, mesh.num_cells(), [&](Index c) {
    const CellGeometry& cell = s.geometry.cells[c];
    double sum = problem.source ? problem.source(cell.centre) * cell.volume : 0.0;
    for (Index f : s.cell_faces.of(c)) {
      if (s.kind[f] == FvFace::dirichlet)
        sum += s.coefficient[f] * s.boundary_value[f];
      else if (s.kind[f] == FvFace::neumann)
        sum += s.geometry.faces[f].area_vector.norm() * s.boundary_value[f];
    }
    b[c] = sum;
  });
  return b;
}

std::vector<Vec3> fv_gradients(const PolyMesh& mesh, const FvSystem& s,
                               const Eigen::VectorXd& u, bool boundary_data) {
  std::vector<Vec3> g(mesh.num_cells());
  tbb::parallel_for(Index{0}, mesh.num_cells(), [&](Index c) {
    const auto cf = s.cell_faces.of(c);
    const std::size_t first = static_cast<std::size_t>(s.cell_faces.offsets[c]);
    Vec3 sum = boundary_data ? s.gradient_constant[c] : Vec3::Zero();
    for (std::size_t j = 0; j < cf.size(); ++j) {
      const Index f = cf[j];
      double value;
      switch (s.kind[f]) {
        case FvFace::internal:
        case FvFace::interface:
          value = u[mesh.owner[f] == c ? mesh.neighbour[f] : mesh.owner[f]];
          break;
        case FvFace::dirichlet:
          value = boundary_data ? s.boundary_value[f] : 0.0;
          break;
        default:
          continue;
      }
      sum += s.lsq[first + j] * (value - u[c]);
    }
    g[c] = sum;
  });
  return g;
}

Eigen::VectorXd fv_correction(const PolyMesh& mesh, const FvSystem& s,
                              const std::vector<Vec3>& g) {
  Eigen::VectorXd r(mesh.num_cells());
  tbb::parallel_for(Index{0}, mesh.num_cells(), [&](Index c) {
    double sum = 0.0;
    for (Index f : s.cell_faces.of(c)) {
      if (s.kind[f] == FvFace::neumann) continue;
      const Index p = mesh.owner[f];
      const Vec3 face_gradient =
          mesh.is_boundary(f)
              ? g[p]
              : Vec3(s.owner_weight[f] * g[p] + (1.0 - s.owner_weight[f]) * g[mesh.neighbour[f]]);
      const double flux = s.coefficient[f] * s.correction[f].dot(face_gradient);
      sum += p == c ? flux : -flux;
    }
    r[c] = sum;
  });
  return r;
}

}  // namespace volmesh::fem
