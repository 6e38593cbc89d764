#include "voxel_dda.hpp"

namespace volmesh::voxel {

std::optional<Clip> clip_segment(const Vec3& lo, const Vec3& hi, const Vec3& a, const Vec3& d) {
  if (!a.allFinite() || !d.allFinite()) return std::nullopt;
  Clip clip;
  for (int m = 0; m < 3; ++m) {
    if (d[m] == 0.0) {
      if (a[m] < lo[m] || a[m] > hi[m]) return std::nullopt;
      continue;
    }
    double enter = (lo[m] - a[m]) / d[m], leave = (hi[m] - a[m]) / d[m];
    if (enter > leave) std::swap(enter, leave);
    if (enter > clip.t0) clip.t0 = enter, clip.axis0 = m;
    if (leave < clip.t1) clip.t1 = leave, clip.axis1 = m;
  }
  if (clip.t0 > clip.t1) return std::nullopt;
  return clip;
}

}  // namespace volmesh::voxel
