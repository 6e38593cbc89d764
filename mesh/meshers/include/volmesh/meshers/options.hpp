#pragma once
// The options a mesher takes besides its resolution: declared by the mesher (name, help,
// type, range or choices), given by the caller as values by name, and checked against the
// declarations before the mesher runs. An option not given leaves the method's own default.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace volmesh::meshers {

struct OptionSpec {
  // The value each type takes (OptionValue): flag bool, integer std::int64_t, real double,
  // choice and text std::string. A text's form (a list of numbers, say) is the method's to check.
  enum class Type { flag, integer, real, choice, text };
  std::string name;  // as on the command line, without the dashes: "feature-angle"
  std::string help;  // one line for --help, saying the default where there is one
  Type type = Type::flag;
  double min = 0.0, max = 0.0;       // integer, real: the closed range of the values
  std::vector<std::string> choices = {};  // choice: the values allowed
};

using OptionValue = std::variant<bool, std::int64_t, double, std::string>;
// The options given, by name.
using MethodOptions = std::map<std::string, OptionValue, std::less<>>;

// Throws InputError when `value` is not of the spec's type, or out of its range or choices
// ("--feature-angle 95: out of range [1, 90]").
void check_option(const OptionSpec& spec, const OptionValue& value);

// The value given for `name`, if any (of the type its spec declares).
template <class T>
std::optional<T> given(const MethodOptions& options, std::string_view name) {
  const auto it = options.find(name);
  if (it == options.end()) return std::nullopt;
  return std::get<T>(it->second);
}

// "--name" for a flag, "--name value" otherwise, as a command line says it.
std::string option_text(std::string_view name, const OptionValue& value);

}  // namespace volmesh::meshers
