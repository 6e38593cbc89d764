#include "node_crossings.hpp"

namespace volmesh {

Vec3 field_gradient(const VoxelGrid& field, const std::array<Index, 3>& sample) {
  Vec3 gradient;
  for (int a = 0; a < 3; ++a) {
    std::array<Index, 3> below = sample, above = sample;
    if (below[a] > 0) --below[a];
    if (above[a] + 1 < field.dims[a]) ++above[a];
    const double df = double{field.at(above[0], above[1], above[2])} -
                      double{field.at(below[0], below[1], below[2])};
    gradient[a] = df / (field.spacing[a] * static_cast<double>(above[a] - below[a]));
  }
  return gradient;
}

std::vector<EdgeCrossing> node_crossings(const VoxelGrid& field, const std::array<Index, 3>& lo,
                                         Index size) {
  std::vector<EdgeCrossing> crossings;
  for (Index k = lo[2]; k <= lo[2] + size; ++k)
    for (Index j = lo[1]; j <= lo[1] + size; ++j)
      for (Index i = lo[0]; i <= lo[0] + size; ++i) {
        const std::array<Index, 3> from{i, j, k};
        for (int a = 0; a < 3; ++a) {
          std::array<Index, 3> to = from;
          if (++to[a] > lo[a] + size) continue;
          const double f0 = field.at(i, j, k), f1 = field.at(to[0], to[1], to[2]);
          if ((f0 >= 0.0) == (f1 >= 0.0)) continue;
          // The signs differ, so f0 != f1 and t is in [0, 1] (0 or 1 at an end where F = 0).
          const double t = f0 / (f0 - f1);
          const Vec3 point =
              (1.0 - t) * field.point(i, j, k) + t * field.point(to[0], to[1], to[2]);
          const Vec3 gradient =
              (1.0 - t) * field_gradient(field, from) + t * field_gradient(field, to);
          const double norm = gradient.norm();
          crossings.push_back({point, norm > 0.0 ? Vec3(gradient / norm) : Vec3::Zero()});
        }
      }
  return crossings;
}

}  // namespace volmesh
