#pragma once
// Scalar fields given as text on the command line (`--exact "sin(x)*exp(y*z)"`), parsed by
// muparser: variables x, y, z; constants pi (= _pi) and _e to full double precision;
// muparser's functions (sin, cos, tan, asin, acos, atan, sinh, cosh, tanh, asinh, acosh,
// atanh, exp, ln, log, log2, log10, sqrt, abs, sign, rint, min, max, sum, avg), operators
// + - * / ^, comparisons and `c ? a : b`.
#include <string>

#include "volmesh/fem/problem.hpp"

namespace volmesh::fem {

// The field as a function of the point. Throws InputError naming the option `what` (e.g.
// "--exact") with muparser's message, which gives the position of the offending token, for an
// empty text, a syntax error, or an unknown variable or function.
// The returned function may be called from several threads at once (the solvers assemble in
// parallel): a muparser Parser is not safe for concurrent evaluation, so each thread evaluates
// its own parser, made on its first call.
ScalarFunction parse_expression(const std::string& text, const std::string& what);

}  // namespace volmesh::fem
