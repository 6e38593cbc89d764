#include "volmesh/meshers/options.hpp"

#include <algorithm>
#include <sstream>

#include "volmesh/core/errors.hpp"

namespace volmesh::meshers {

namespace {

// The variant index each type's values have in OptionValue.
std::size_t value_index(OptionSpec::Type type) {
  switch (type) {
    case OptionSpec::Type::flag:
      return 0;
    case OptionSpec::Type::integer:
      return 1;
    case OptionSpec::Type::real:
      return 2;
    case OptionSpec::Type::choice:
    case OptionSpec::Type::text:
      return 3;
  }
  return std::variant_npos;
}

const char* type_name(OptionSpec::Type type) {
  switch (type) {
    case OptionSpec::Type::flag:
      return "a flag";
    case OptionSpec::Type::integer:
      return "an integer";
    case OptionSpec::Type::real:
      return "a number";
    case OptionSpec::Type::choice:
      return "one of its choices";
    case OptionSpec::Type::text:
      return "a text";
  }
  return "";
}

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::string option_text(std::string_view name, const OptionValue& value) {
  std::string text = "--" + std::string(name);
  if (const auto* s = std::get_if<std::string>(&value)) return text + " " + *s;
  if (const auto* i = std::get_if<std::int64_t>(&value)) return text + " " + std::to_string(*i);
  if (const auto* d = std::get_if<double>(&value)) return text + " " + number_text(*d);
  return text;
}

void check_option(const OptionSpec& spec, const OptionValue& value) {
  if (value.index() != value_index(spec.type))
    throw InputError("--" + spec.name + " takes " + type_name(spec.type));
  const std::string given = option_text(spec.name, value);
  if (spec.type == OptionSpec::Type::choice) {
    const std::string& v = std::get<std::string>(value);
    if (std::find(spec.choices.begin(), spec.choices.end(), v) == spec.choices.end()) {
      std::string known;
      for (const std::string& c : spec.choices) known += (known.empty() ? "" : ", ") + c;
      throw InputError(given + ": not one of " + known);
    }
  }
  if (spec.type == OptionSpec::Type::integer || spec.type == OptionSpec::Type::real) {
    const double v = spec.type == OptionSpec::Type::integer
                         ? static_cast<double>(std::get<std::int64_t>(value))
                         : std::get<double>(value);
    if (!(v >= spec.min && v <= spec.max))
      throw InputError(given + ": out of range [" + number_text(spec.min) + ", " +
                       number_text(spec.max) + "]");
  }
}

}  // namespace volmesh::meshers
