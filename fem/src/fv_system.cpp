// Setting up the finite-volume discretisation: data checks, face coefficients and the
// least-squares gradient operator.
#include <Eigen/QR>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "fv_system.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh::fem {
namespace {

// OpenFOAM's guard: a cell centre (nearly) in the plane of its face still sees the face at
// 0.05 of its distance.
constexpr double kMinNormalFraction = 0.05;
// Correction vectors this small relative to the centre distance are rounding: the face is
// orthogonal.
constexpr double kOrthogonal = 1e-12;

double normal_distance(const Vec3& n, const Vec3& v) {
  return std::max(n.dot(v), kMinNormalFraction * v.norm());
}

// The correction vector t = normal_part − d, zero when it is rounding.
Vec3 correction_vector(const Vec3& normal_part, const Vec3& d) {
  const Vec3 t = normal_part - d;
  return t.norm() <= kOrthogonal * d.norm() ? Vec3::Zero() : t;
}

std::vector<double> cell_conductivity(const PolyMesh& mesh, const PoissonProblem& problem) {
  std::vector<double> k(mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Index region = mesh.cell_region[c];
    const auto it = problem.conductivity.find(region);
    if (it == problem.conductivity.end())
      throw InputError("region " + std::to_string(region) + " (cell " + std::to_string(c) +
                       "): no conductivity k given");
    if (!(it->second > 0.0) || !std::isfinite(it->second))
      throw InputError("region " + std::to_string(region) +
                       ": conductivity must be positive and finite, got " +
                       std::to_string(it->second));
    k[c] = it->second;
  }
  return k;
}

// The condition of each boundary face's tag.
std::vector<const ScalarBoundaryCondition*> face_conditions(const PolyMesh& mesh,
                                                            const PoissonProblem& problem) {
  std::vector<const ScalarBoundaryCondition*> by_tag(mesh.tag_names.size(), nullptr);
  std::vector<const ScalarBoundaryCondition*> by_face(mesh.num_faces(), nullptr);
  bool any_dirichlet = false;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f)) continue;
    const Index tag = mesh.face_tag[f];
    if (tag < 0 || tag >= static_cast<Index>(by_tag.size()))
      throw InputError("boundary face " + std::to_string(f) + ": tag " + std::to_string(tag) +
                       " has no name");
    if (!by_tag[tag]) {
      const std::string& name = mesh.tag_names[tag];
      const auto it = problem.boundary.find(name);
      if (it == problem.boundary.end() || !it->second.value)
        throw InputError("boundary tag " + name + ": no boundary condition given");
      by_tag[tag] = &it->second;
    }
    by_face[f] = by_tag[tag];
    any_dirichlet |= by_tag[tag]->kind == ScalarBoundaryCondition::Kind::dirichlet;
  }
  if (!any_dirichlet)
    throw InputError("no boundary face has a Dirichlet condition: u is defined only up to a "
                     "constant");
  return by_face;
}

}  // namespace

FvSystem build_fv_system(const PolyMesh& mesh, const PoissonProblem& problem, bool corrected) {
  FvSystem s;
  s.k = cell_conductivity(mesh, problem);
  const std::vector<const ScalarBoundaryCondition*> conditions = face_conditions(mesh, problem);
  s.cell_faces = build_cell_faces(mesh);
  s.geometry = mesh_geometry(mesh, s.cell_faces);
  const auto& faces = s.geometry.faces;
  const auto& cells = s.geometry.cells;
  const PointMap identity = [](const Vec3& p) { return p; };
  const PointMap& to_true = problem.to_true_boundary ? problem.to_true_boundary : identity;

  const Index nf = mesh.num_faces();
  s.kind.resize(nf);
  s.coefficient.assign(nf, 0.0);
  s.correction.assign(nf, Vec3::Zero());
  s.owner_weight.assign(nf, 1.0);
  s.boundary_value.assign(nf, 0.0);
  std::vector<double> interface_share(nf, 1.0);  // owner's share in the interface value
  tbb::parallel_for(Index{0}, nf, [&](Index f) {
    const double area = faces[f].area_vector.norm();
    const Index p = mesh.owner[f];
    const Vec3 xp = cells[p].centre, xf = faces[f].centre;
    if (mesh.is_boundary(f)) {
      const ScalarBoundaryCondition& bc = *conditions[f];
      s.kind[f] = bc.kind == ScalarBoundaryCondition::Kind::dirichlet ? FvFace::dirichlet
                                                                      : FvFace::neumann;
      s.boundary_value[f] = bc.value(to_true(xf));
      if (area == 0.0) return;
      const Vec3 n = faces[f].area_vector / area;
      const double d = normal_distance(n, xf - xp);
      s.coefficient[f] = s.k[p] * area / d;
      if (corrected) s.correction[f] = correction_vector(d * n, xf - xp);
      return;
    }
    const Index q = mesh.neighbour[f];
    const Vec3 xq = cells[q].centre;
    s.kind[f] = s.k[p] == s.k[q] ? FvFace::internal : FvFace::interface;
    if (area == 0.0) return;
    const Vec3 n = faces[f].area_vector / area;
    const double dp = normal_distance(n, xf - xp), dq = normal_distance(n, xq - xf);
    s.coefficient[f] = area / (dp / s.k[p] + dq / s.k[q]);
    s.owner_weight[f] = dq / (dp + dq);
    interface_share[f] = (s.k[p] / dp) / (s.k[p] / dp + s.k[q] / dq);
    if (corrected) s.correction[f] = correction_vector((dp + dq) * n, xq - xp);
  });
  s.non_orthogonal = std::any_of(s.correction.begin(), s.correction.end(),
                                 [](const Vec3& t) { return !t.isZero(0.0); });

  // Least squares over the faces of each cell: rows δ_j·∇u = Δ_j with weights 1/|δ_j|².
  s.lsq.assign(s.cell_faces.faces.size(), Vec3::Zero());
  s.gradient_constant.assign(mesh.num_cells(), Vec3::Zero());
  tbb::parallel_for(Index{0}, mesh.num_cells(), [&](Index c) {
    const auto cf = s.cell_faces.of(c);
    const std::size_t first = static_cast<std::size_t>(s.cell_faces.offsets[c]);
    const Vec3 xc = cells[c].centre;
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
    Vec3 neumann_rhs = Vec3::Zero();
    std::vector<double> factor(cf.size(), 1.0);  // Δ_j = factor_j · (value_j − u_c)
    for (std::size_t j = 0; j < cf.size(); ++j) {
      const Index f = cf[j];
      const double area = faces[f].area_vector.norm();
      const bool own = mesh.owner[f] == c;
      const Vec3 xf = faces[f].centre;
      Vec3 delta = xf - xc;
      switch (s.kind[f]) {
        case FvFace::internal:
          delta = cells[own ? mesh.neighbour[f] : mesh.owner[f]].centre - xc;
          break;
        case FvFace::interface:
          factor[j] = own ? 1.0 - interface_share[f] : interface_share[f];
          break;
        case FvFace::dirichlet:
          break;
        case FvFace::neumann:
          factor[j] = 0.0;
          if (area > 0.0) {
            const Vec3 n = faces[f].area_vector / area;
            const double d = normal_distance(n, delta);
            delta = d * n;
            // A ghost point at distance d along n where u exceeds u_c by d·g/k.
            neumann_rhs += delta / delta.squaredNorm() * (d * s.boundary_value[f] / s.k[c]);
          }
          break;
      }
      if (area == 0.0 || delta.squaredNorm() == 0.0) {
        factor[j] = 0.0;
        continue;
      }
      const Vec3 weighted = delta / delta.squaredNorm();
      normal_matrix += weighted * delta.transpose();
      s.lsq[first + j] = weighted;
    }
    const Eigen::Matrix3d inverse =
        normal_matrix.completeOrthogonalDecomposition().pseudoInverse();
    for (std::size_t j = 0; j < cf.size(); ++j)
      s.lsq[first + j] = factor[j] * (inverse * s.lsq[first + j]);
    s.gradient_constant[c] = inverse * neumann_rhs;
  });
  return s;
}

}  // namespace volmesh::fem
