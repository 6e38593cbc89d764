#pragma once
// --threads T: at most T threads for TBB while the returned limit lives (none for T <= 0).
#include <oneapi/tbb/global_control.h>

#include <memory>

namespace volmesh::cli {

inline std::unique_ptr<tbb::global_control> limit_threads(int threads) {
  if (threads <= 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                               static_cast<std::size_t>(threads));
}

}  // namespace volmesh::cli
