#pragma once
// Wall time of a stage, for the `*_seconds` figures of the --json summaries.
#include <chrono>

namespace volmesh {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace volmesh
