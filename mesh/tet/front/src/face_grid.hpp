#pragma once
// The front's faces listed by the leaves of the auxiliary cells (aux_cells.hpp), each about
// one local size wide, so that each test looks at the faces near a tet only, at any grading.
// A face is listed in every leaf its box meets; removed faces are dropped from the leaves a
// query visits.
#include <vector>

#include "aux_cells.hpp"
#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

struct FaceGrid {
  const AuxCells* cells = nullptr;
  std::vector<std::vector<Index>> faces;  // by leaf
  std::vector<unsigned> stamp;            // by face: the query that last returned it
  unsigned query = 0;
};

FaceGrid make_face_grid(const AuxCells& cells);

void insert_face(FaceGrid& grid, Index face, const Vec3& lo, const Vec3& hi);

// The live faces (live[f] != 0) listed in the leaves meeting [lo, hi], each once, in a fixed
// order, into `out` (cleared first).
void faces_near(FaceGrid& grid, const Vec3& lo, const Vec3& hi, const std::vector<char>& live,
                std::vector<Index>& out);

}  // namespace volmesh::tet::front
