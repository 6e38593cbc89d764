#pragma once
// A uniform grid of cells about h wide over the front's faces, so that each test looks at the
// faces near a tet only. A face is listed in every cell its box overlaps; removed faces are
// dropped from the cells a query visits.
#include <array>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

struct FaceGrid {
  Vec3 origin = Vec3::Zero();
  double cell = 1.0;
  std::array<long long, 3> n{1, 1, 1};
  std::vector<std::vector<Index>> faces;  // by cell
  std::vector<unsigned> stamp;            // by face: the query that last returned it
  unsigned query = 0;
};

FaceGrid make_face_grid(const Vec3& lo, const Vec3& hi, double cell);

void insert_face(FaceGrid& grid, Index face, const Vec3& lo, const Vec3& hi);

// The live faces (live[f] != 0) listed in the cells overlapping [lo, hi], each once, in no
// particular order, into `out` (cleared first).
void faces_near(FaceGrid& grid, const Vec3& lo, const Vec3& hi, const std::vector<char>& live,
                std::vector<Index>& out);

inline std::vector<Index> faces_near(FaceGrid& grid, const Vec3& lo, const Vec3& hi,
                                     const std::vector<char>& live) {
  std::vector<Index> out;
  faces_near(grid, lo, hi, live, out);
  return out;
}

}  // namespace volmesh::tet::front
