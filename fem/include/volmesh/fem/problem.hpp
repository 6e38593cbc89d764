#pragma once
// What a solver is asked (docs/methods.md, "Problems"): coefficients per region, data per
// boundary tag, and, when known, the exact solution the errors are measured against. Boundary
// data are evaluated on the TRUE boundary: a mesh boundary point is first mapped by
// to_true_boundary (a staircase face lies O(h) away from the surface it stands for; evaluating
// there would hide the geometric error the studies measure).
#include <functional>
#include <map>
#include <string>

#include <Eigen/Core>

#include "volmesh/core/types.hpp"

namespace volmesh::fem {

// Thread safety: the solvers evaluate sources, body forces and exact solutions from several
// threads at once (the cell loops run in parallel on TBB), so every function given here must
// be safe to call concurrently. The named problems are pure functions of the point; user
// expressions (expression.hpp) are, because each thread evaluates its own muparser parser (a
// mu::Parser is not: it writes its variables and stack on every Eval).
using ScalarFunction = std::function<double(const Vec3&)>;
using VectorFunction = std::function<Vec3(const Vec3&)>;
using TensorFunction = std::function<Eigen::Matrix3d(const Vec3&)>;
using PointMap = std::function<Vec3(const Vec3&)>;

struct ScalarBoundaryCondition {
  enum class Kind { dirichlet, neumann };
  Kind kind = Kind::dirichlet;
  // u on a Dirichlet tag; the outward flux k ∂u/∂n on a Neumann tag. Evaluated at the
  // mesh point mapped onto the true boundary.
  ScalarFunction value;
};

// −∇·(k∇u) = f, k constant per region.
struct PoissonProblem {
  std::map<Index, double> conductivity;  // every region of the mesh needs an entry
  ScalarFunction source;                 // f; zero when empty
  std::map<std::string, ScalarBoundaryCondition> boundary;  // every boundary tag needs one
  PointMap to_true_boundary;       // identity when empty
  ScalarFunction exact;            // optional: errors are reported when given
  VectorFunction exact_gradient;   // optional: the H1 seminorm error needs it
};

struct IsotropicMaterial {
  double young = 1.0;    // E
  double poisson = 0.3;  // ν, in (-1, 1/2)
};

struct VectorBoundaryCondition {
  enum class Kind { displacement, traction };
  Kind kind = Kind::displacement;
  VectorFunction value;  // u on a displacement tag, σ·n on a traction tag
};

// −∇·σ(u) = b, σ = λ tr(ε) I + 2μ ε, material constant per region.
struct ElasticityProblem {
  std::map<Index, IsotropicMaterial> material;  // every region of the mesh needs an entry
  VectorFunction body_force;                    // b; zero when empty
  std::map<std::string, VectorBoundaryCondition> boundary;  // every boundary tag needs one
  PointMap to_true_boundary;  // identity when empty
  VectorFunction exact;          // optional
  TensorFunction exact_gradient; // optional: ∇u, row i = ∇u_i
};

}  // namespace volmesh::fem
