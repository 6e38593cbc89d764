#include "volmesh/core/progress.hpp"

namespace volmesh {

Progress part_of(const Progress& progress, double begin, double end, const std::string& prefix) {
  if (!progress) return {};
  return [progress, begin, end, prefix](const std::string& stage, double fraction) {
    progress(prefix + stage, begin + fraction * (end - begin));
  };
}

}  // namespace volmesh
