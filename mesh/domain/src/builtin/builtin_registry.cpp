// Look-up of built-in domains by name.
#include <algorithm>
#include <cstring>

#include "builtin_entries.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh {
namespace {

const std::vector<BuiltinDomain>& registry() {
  static const std::vector<BuiltinDomain> all = [] {
    std::vector<BuiltinDomain> list = analytic_builtin_domains();
    for (BuiltinDomain& d : layered_builtin_domains()) list.push_back(d);
    std::sort(list.begin(), list.end(), [](const BuiltinDomain& a, const BuiltinDomain& b) {
      return std::strcmp(a.name, b.name) < 0;
    });
    return list;
  }();
  return all;
}

const BuiltinDomain& find(const std::string& name) {
  for (const BuiltinDomain& d : registry())
    if (name == d.name) return d;
  std::string valid;
  for (const std::string& n : builtin_domain_names()) valid += (valid.empty() ? "" : ", ") + n;
  throw InputError("builtin:" + name + ": unknown built-in domain (valid: " + valid + ")");
}

}  // namespace

std::vector<std::string> builtin_domain_names() {
  std::vector<std::string> names;
  for (const BuiltinDomain& d : registry()) names.emplace_back(d.name);
  return names;
}

std::unique_ptr<Domain> make_builtin_domain(const std::string& name) { return find(name).make(); }

std::map<Index, double> builtin_region_volumes(const std::string& name) {
  return find(name).region_volumes();
}

}  // namespace volmesh
