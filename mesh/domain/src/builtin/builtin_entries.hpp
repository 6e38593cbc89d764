#pragma once
// One entry per built-in domain; each family of built-ins (analytic solids, layers) provides
// a list, and builtin_registry.cpp joins them.
#include <map>
#include <memory>
#include <vector>

#include "volmesh/domain/domain.hpp"

namespace volmesh {

struct BuiltinDomain {
  const char* name;
  std::unique_ptr<Domain> (*make)();
  std::map<Index, double> (*region_volumes)();  // exact, or empty
};

std::vector<BuiltinDomain> analytic_builtin_domains();
std::vector<BuiltinDomain> layered_builtin_domains();

}  // namespace volmesh
