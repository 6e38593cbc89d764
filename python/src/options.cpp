#include "options.hpp"

#include <algorithm>

namespace volmesh::python {

namespace {

// The type `name` is declared with: by `info`, else by any method (the registry then says
// which methods take it); none when no method declares it.
std::optional<meshers::OptionSpec::Type> declared_type(const meshers::MesherInfo& info,
                                                       const std::string& name) {
  std::vector<meshers::MesherInfo> order{info};
  order.insert(order.end(), meshers::meshers().begin(), meshers::meshers().end());
  for (const meshers::MesherInfo& m : order)
    for (const meshers::OptionSpec& s : meshers::options_of(m))
      if (s.name == name) return s.type;
  return std::nullopt;
}

}  // namespace

meshers::MethodOptions method_options(const meshers::MesherInfo& info, const py::kwargs& given) {
  meshers::MethodOptions options;
  for (const auto& [key, value] : given) {
    std::string name = key.cast<std::string>();
    std::replace(name.begin(), name.end(), '_', '-');
    const auto type = declared_type(info, name);
    meshers::OptionValue v;
    if (py::isinstance<py::bool_>(value)) {
      if (!value.cast<bool>() && type == meshers::OptionSpec::Type::flag) continue;  // not given
      v = value.cast<bool>();
    } else if (py::isinstance<py::int_>(value)) {
      if (type == meshers::OptionSpec::Type::real)
        v = value.cast<double>();
      else
        v = value.cast<std::int64_t>();
    } else if (py::isinstance<py::float_>(value)) {
      v = value.cast<double>();
    } else {
      v = py::str(value).cast<std::string>();
    }
    options[name] = std::move(v);
  }
  meshers::check_options(info, options);
  return options;
}

}  // namespace volmesh::python
