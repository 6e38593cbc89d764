#pragma once
// What Poisson and elasticity share around the assembly: coefficients per region, conditions
// per boundary tag, Dirichlet nodes, boundary loads, error norms.
#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "fe_space.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/parallel.hpp"
#include "volmesh/fem/problem.hpp"
#include "volmesh/fem/solution.hpp"

namespace volmesh::fem::detail {

// Each cell's entry of `by_region`; throws InputError "no <what> for region R".
template <class T>
std::vector<T> per_cell(const PolyMesh& mesh, const std::map<Index, T>& by_region,
                        const std::string& what) {
  std::vector<T> out;
  out.reserve(mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto it = by_region.find(mesh.cell_region[c]);
    if (it == by_region.end())
      throw InputError("no " + what + " for region " + std::to_string(mesh.cell_region[c]));
    out.push_back(it->second);
  }
  return out;
}

// The tags of the faces between the pieces of a mesh ("procBoundary<r>to<q>").
inline constexpr std::string_view kPieceBoundaryPrefix = "procBoundary";

// The condition of every boundary tag (nullptr for a tag no boundary face uses, and for the
// faces between pieces); throws InputError naming the first used tag without one.
template <class Condition>
std::vector<const Condition*> conditions_per_tag(const PolyMesh& mesh,
                                                 const std::map<std::string, Condition>& by_name) {
  std::vector<const Condition*> out(mesh.tag_names.size(), nullptr);
  std::vector<char> used(mesh.tag_names.size(), 0);
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_boundary(f)) {
      const Index tag = mesh.face_tag[f];
      if (tag < 0 || tag >= static_cast<Index>(mesh.tag_names.size()))
        throw InputError("mesh: boundary face " + std::to_string(f) + " has no valid tag");
      used[tag] = 1;
    }
  for (std::size_t t = 0; t < used.size(); ++t) {
    // Faces between the pieces of a mesh held in pieces lie inside the domain.
    if (!used[t] || mesh.tag_names[t].starts_with(kPieceBoundaryPrefix)) continue;
    const auto it = by_name.find(mesh.tag_names[t]);
    if (it == by_name.end())
      throw InputError("no boundary condition for boundary tag '" + mesh.tag_names[t] + "'");
    out[t] = &it->second;
  }
  return out;
}

inline Vec3 on_true_boundary(const PointMap& map, const Vec3& x) { return map ? map(x) : x; }

// For each node, the lowest marked tag among the boundary faces carrying it; kNoIndex for a
// node on no marked face.
std::vector<Index> lowest_marked_tag(const PolyMesh& mesh, const FeSpace& space,
                                     const std::vector<char>& marked);

// The boundary data at a point of the true boundary: `components` values into `out`.
using BoundaryData = std::function<void(Index tag, const Vec3& at, double* out)>;

// rhs += ∫ g·N over the boundary faces with a marked tag, g taken at the quadrature points
// mapped by to_true_boundary. Faces in order: deterministic.
void add_boundary_load(const PolyMesh& mesh, const FeSpace& space, int components,
                       const std::vector<char>& marked, const PointMap& to_true_boundary,
                       const BoundaryData& data, Eigen::VectorXd& rhs);

// The norms from per-cell integrals of the squared errors (fields l2 and h1 of each cell's
// result), summed in cell order (and over the ranks when each holds a piece of the mesh), and
// the nodal maximum.
template <class CellResult>
ErrorNorms error_norms(const std::vector<CellResult>& cells, bool with_gradient, double linf,
                       bool over_ranks = false) {
  double sums[2] = {0.0, 0.0};  // l2², h1²
  for (const CellResult& r : cells) {
    sums[0] += r.l2;
    sums[1] += r.h1;
  }
  if (over_ranks) sum_over_ranks(sums, 2);
  const double l2 = sums[0], h1 = sums[1];
  ErrorNorms e;
  e.l2 = std::sqrt(l2);
  if (with_gradient) e.h1 = std::sqrt(h1);
  e.linf = linf;
  return e;
}

}  // namespace volmesh::fem::detail
