#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "volmesh/meshers/octree_request.hpp"
#include "registration.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/octree/octree.hpp"

namespace volmesh::meshers {

namespace {

// Filled before main by the methods' Registrations, sorted by name.
std::vector<MesherInfo>& table() {
  static std::vector<MesherInfo> entries;
  return entries;
}

// "the cutcell method", "the cutcell and staircase methods".
std::string methods_phrase(const std::vector<std::string>& names) {
  std::string text = "the ";
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return text + (names.size() == 1 ? " method" : " methods");
}

// Throws InputError unless the request gives the method's resolution and no other.
void require_resolution(const MesherInfo& info, const MeshRequest& request) {
  const bool level = request.level.has_value(), size = request.size.has_value();
  if (info.resolution == Resolution::surface) {
    if (level || size)
      throw InputError(info.name + " meshes the domain's triangulated surfaces as they are: no " +
                       (level ? "--level" : "--size"));
    return;
  }
  const bool by_level = info.resolution == Resolution::level;
  const bool wanted = by_level ? level : size;
  const bool other = by_level ? size : level;
  if (!wanted || other)
    throw InputError(info.name + " meshes by " + (by_level ? "--level" : "--size") +
                     (other ? (by_level ? ", not --size" : ", not --level") : ": none given"));
}

}  // namespace

Registration::Registration(MesherInfo info) {
  std::vector<MesherInfo>& entries = table();
  const auto at =
      std::lower_bound(entries.begin(), entries.end(), info.name,
                       [](const MesherInfo& e, const std::string& n) { return e.name < n; });
  if ((at != entries.end() && at->name == info.name) || !info.run) {
    std::fprintf(stderr, "volmesh: mesher %s registered twice or without a function\n",
                 info.name.c_str());
    std::abort();
  }
  entries.insert(at, std::move(info));
}

const std::vector<OptionSpec>& octree_options() {
  static const std::vector<OptionSpec> specs{
      {.name = "base-level",
       .help = "uniform depth everywhere before refining toward the interfaces (default " +
               std::to_string(OctreeOptions{}.base_level) + ")",
       .type = OptionSpec::Type::integer,
       .min = 0,
       .max = kOctreeMaxLevel},
      {.name = "cells-between-levels",
       .help = "cells of each level across before the next coarser one begins (snappyHexMesh's "
               "nCellsBetweenLevels; default " +
               std::to_string(OctreeOptions{}.cells_between_levels) + ": 2:1 balance only)",
       .type = OptionSpec::Type::integer,
       .min = 1,
       .max = 64},
  };
  return specs;
}

std::vector<OptionSpec> options_of(const MesherInfo& info) {
  std::vector<OptionSpec> all;
  if (info.octree) all = octree_options();
  all.insert(all.end(), info.options.begin(), info.options.end());
  return all;
}

const std::vector<MesherInfo>& meshers() { return table(); }

std::string mesher_names() {
  std::string names;
  for (const MesherInfo& m : meshers()) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

const MesherInfo& find_mesher(std::string_view name) {
  for (const MesherInfo& m : meshers())
    if (m.name == name) return m;
  throw InputError("unknown method " + std::string(name) + " (known: " + mesher_names() + ")");
}

void check_options(const MesherInfo& info, const MethodOptions& options) {
  const std::vector<OptionSpec> taken = options_of(info);
  for (const auto& [name, value] : options) {
    const auto spec = std::find_if(taken.begin(), taken.end(),
                                   [&](const OptionSpec& s) { return s.name == name; });
    if (spec != taken.end()) {
      check_option(*spec, value);
      continue;
    }
    std::vector<std::string> takers;
    for (const MesherInfo& m : meshers())
      for (const OptionSpec& s : options_of(m))
        if (s.name == name) takers.push_back(m.name);
    throw InputError("--" + name +
                     (takers.empty() ? std::string(": no method takes it")
                                     : " applies to " + methods_phrase(takers) + " only"));
  }
}

MeshResult mesh(const MesherInfo& info, const Domain& domain, const MeshRequest& given) {
  MeshRequest request = given;
  if (info.resolution == Resolution::size && request.uniform && request.level && !request.size) {
    OctreeOptions at;
    at.level = *request.level;
    request.size = octree_cell_size(domain, at);
    request.level.reset();
  }
  check_options(info, request.options);
  require_resolution(info, request);
  if (request.uniform && request.options.contains("base-level"))
    throw InputError("--base-level: a uniform mesh has its level everywhere");
  MeshResult result = info.run(domain, request);
  result.summary["cells"] = result.mesh.num_cells();
  result.summary["faces"] = result.mesh.num_faces();
  result.summary["vertices"] = result.mesh.num_points();
  return result;
}

}  // namespace volmesh::meshers
