// Look-up of built-in domains by name: a fixed name, or a family's stem and parameters.
#include <algorithm>

#include "builtin_entries.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh {
namespace {

struct Registry {
  std::vector<BuiltinDomain> domains;
  std::vector<BuiltinFamily> families;
};

const Registry& registry() {
  static const Registry all = [] {
    Registry r;
    for (auto list : {analytic_builtin_domains(), layered_builtin_domains(),
                      polyhedral_builtin_domains()})
      for (BuiltinDomain& d : list) r.domains.push_back(std::move(d));
    r.families = polyhedral_builtin_families();
    return r;
  }();
  return all;
}

// The family's name up to and with its first ':' ("twisted-prism:").
std::string stem(const BuiltinFamily& f) { return f.pattern.substr(0, f.pattern.find(':') + 1); }

BuiltinDomain find(const std::string& name) {
  for (const BuiltinDomain& d : registry().domains)
    if (name == d.name) return d;
  for (const BuiltinFamily& f : registry().families)
    if (name.starts_with(stem(f))) return f.instance(name);
  std::string valid;
  for (const std::string& n : builtin_domain_names()) valid += (valid.empty() ? "" : ", ") + n;
  throw InputError("builtin:" + name + ": unknown built-in domain (valid: " + valid + ")");
}

}  // namespace

std::vector<std::string> builtin_domain_names() {
  std::vector<std::string> names;
  for (const BuiltinDomain& d : registry().domains) names.push_back(d.name);
  for (const BuiltinFamily& f : registry().families) names.push_back(f.pattern);
  std::sort(names.begin(), names.end());
  return names;
}

std::unique_ptr<Domain> make_builtin_domain(const std::string& name) { return find(name).make(); }

std::map<Index, double> builtin_region_volumes(const std::string& name) {
  return find(name).region_volumes();
}

std::vector<LabelledSurface> builtin_surfaces(const std::string& name) {
  const BuiltinDomain d = find(name);
  return d.surfaces ? d.surfaces() : std::vector<LabelledSurface>{};
}

}  // namespace volmesh
