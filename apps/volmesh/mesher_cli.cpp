#include "mesher_cli.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>

#include "volmesh/core/errors.hpp"

namespace volmesh::cli {

namespace {

using meshers::OptionSpec;

// An option with the methods that take it.
struct SharedOption {
  OptionSpec spec;
  std::vector<std::string> methods;
};

std::vector<SharedOption> declared_options(bool octree) {
  std::vector<SharedOption> all;
  for (const meshers::MesherInfo& m : meshers::meshers()) {
    std::vector<OptionSpec> specs = m.options;
    if (octree && m.octree)
      specs.insert(specs.begin(), meshers::octree_options().begin(),
                   meshers::octree_options().end());
    for (OptionSpec& s : specs) {
      const auto same = std::find_if(all.begin(), all.end(),
                                     [&](const SharedOption& o) { return o.spec.name == s.name; });
      if (same != all.end())
        same->methods.push_back(m.name);
      else
        all.push_back({std::move(s), {m.name}});
    }
  }
  return all;
}

void add_option(CLI::App& app, const SharedOption& o, meshers::MethodOptions& given) {
  std::string help;
  for (const std::string& m : o.methods) help += (help.empty() ? "" : ", ") + m;
  help += ": " + o.spec.help;
  const std::string flag = "--" + o.spec.name, name = o.spec.name;
  switch (o.spec.type) {
    case OptionSpec::Type::flag:
      app.add_flag_function(
          flag, [&given, name](std::int64_t) { given[name] = true; }, help);
      break;
    case OptionSpec::Type::integer:
      app.add_option_function<std::int64_t>(
             flag, [&given, name](const std::int64_t& v) { given[name] = v; }, help)
          ->check(CLI::Range(static_cast<std::int64_t>(o.spec.min),
                             static_cast<std::int64_t>(o.spec.max)));
      break;
    case OptionSpec::Type::real:
      app.add_option_function<double>(
             flag, [&given, name](const double& v) { given[name] = v; }, help)
          ->check(CLI::Range(o.spec.min, o.spec.max));
      break;
    case OptionSpec::Type::choice:
      app.add_option_function<std::string>(
             flag, [&given, name](const std::string& v) { given[name] = v; }, help)
          ->check(CLI::IsMember(o.spec.choices));
      break;
    case OptionSpec::Type::text:
      app.add_option_function<std::string>(
          flag, [&given, name](const std::string& v) { given[name] = v; }, help);
      break;
  }
}

}  // namespace

std::vector<std::string> mesher_names() {
  std::vector<std::string> names;
  for (const meshers::MesherInfo& m : meshers::meshers()) names.push_back(m.name);
  return names;
}

std::string default_domains() {
  std::vector<std::pair<std::string, std::string>> by_domain;  // domain, its methods
  for (const meshers::MesherInfo& m : meshers::meshers()) {
    const auto same = std::find_if(by_domain.begin(), by_domain.end(),
                                   [&](const auto& d) { return d.first == m.default_domain; });
    if (same == by_domain.end())
      by_domain.emplace_back(m.default_domain, m.name);
    else
      same->second += ", " + m.name;
  }
  std::string text;
  for (const auto& [domain, methods] : by_domain)
    text += (text.empty() ? "" : "; ") + domain + " for " + methods;
  return text;
}

std::string meshers_help() {
  std::size_t width = 0;
  for (const meshers::MesherInfo& m : meshers::meshers()) width = std::max(width, m.name.size());
  std::string text = "Methods:\n";
  for (const meshers::MesherInfo& m : meshers::meshers())
    text += "  " + m.name + std::string(width + 2 - m.name.size(), ' ') + m.description + "\n";
  return text;
}

void add_mesher_options(CLI::App& app, meshers::MethodOptions& given, bool octree) {
  for (const SharedOption& o : declared_options(octree)) add_option(app, o, given);
}

bool options_apply(const std::string& command, const meshers::MesherInfo& info,
                   const meshers::MethodOptions& given) {
  try {
    meshers::check_options(info, given);
    return true;
  } catch (const InputError& e) {
    std::cerr << "volmesh " << command << ": " << e.what() << "\n";
    return false;
  }
}

}  // namespace volmesh::cli
