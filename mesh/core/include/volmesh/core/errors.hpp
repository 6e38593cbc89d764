#pragma once
// Error types that the command line maps to exit codes (docs/architecture.md).
#include <stdexcept>
#include <string>

namespace volmesh {

// Bad input data or a failed operation: exit code 1. The message is one line that names the
// file (or object), the entity and what is wrong, e.g.
//   "bunny.stl: triangle 17: vertex index 90 out of range (82 vertices)".
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace volmesh
