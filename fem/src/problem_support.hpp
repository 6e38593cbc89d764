#pragma once
// Pieces shared by the named and the user problems.
#include <map>
#include <string>
#include <vector>

#include "volmesh/domain/domain.hpp"
#include "volmesh/fem/problem.hpp"

namespace volmesh::fem {

// The same boundary condition on every tag.
std::map<std::string, ScalarBoundaryCondition> on_every_tag(const std::vector<std::string>& tags,
                                                            const ScalarBoundaryCondition& bc);

// k on every region of the domain.
std::map<Index, double> same_conductivity(const Domain& domain, double k);

// Outward flux k ∇u·n at the true boundary point q (n: the domain's normal there).
ScalarFunction boundary_flux(const Domain& domain, double k, VectorFunction gradient);

}  // namespace volmesh::fem
