#include "volmesh/fem/expression.hpp"

#include <muParser.h>
#include <tbb/enumerable_thread_specific.h>

#include <memory>
#include <numbers>

#include "volmesh/core/errors.hpp"

namespace volmesh::fem {
namespace {

// muparser binds variables by address: a parser and its variables live and move together.
struct BoundParser {
  double x = 0.0, y = 0.0, z = 0.0;
  mu::Parser parser;

  explicit BoundParser(const std::string& text) {
    parser.DefineVar("x", &x);
    parser.DefineVar("y", &y);
    parser.DefineVar("z", &z);
    // muparser 2.3.3's own _pi and _e carry 13 digits only.
    parser.DefineConst("pi", std::numbers::pi);
    parser.DefineConst("_pi", std::numbers::pi);
    parser.DefineConst("_e", std::numbers::e);
    parser.SetExpr(text);
    parser.Eval();  // muparser parses on the first evaluation: report errors now
  }
  double operator()(const Vec3& p) {
    x = p.x();
    y = p.y();
    z = p.z();
    return parser.Eval();
  }
};

struct SharedExpression {
  std::string text;
  tbb::enumerable_thread_specific<std::unique_ptr<BoundParser>> per_thread;

  double operator()(const Vec3& p) {
    std::unique_ptr<BoundParser>& mine = per_thread.local();
    if (!mine) mine = std::make_unique<BoundParser>(text);
    return (*mine)(p);
  }
};

}  // namespace

ScalarFunction parse_expression(const std::string& text, const std::string& what) {
  if (text.find_first_not_of(" \t") == std::string::npos)
    throw InputError(what + ": empty expression");
  try {
    BoundParser check(text);
  } catch (const mu::Parser::exception_type& e) {
    std::string message = e.GetMsg();
    if (!message.empty() && message.back() == '.') message.pop_back();
    // Some messages ("Missing parenthesis") leave the position out; it counts from 0.
    if (message.find("position") == std::string::npos && e.GetPos() >= 0)
      message += " at position " + std::to_string(e.GetPos());
    throw InputError(what + ": \"" + text + "\": " + message);
  }
  auto shared = std::make_shared<SharedExpression>();
  shared->text = text;
  return [shared](const Vec3& p) { return (*shared)(p); };
}

}  // namespace volmesh::fem
