#pragma once
// Whether a mesh read back holds cells of one shape only, as its writer meant them.
#include <gtest/gtest.h>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/topology.hpp"

namespace volmesh::test {

inline void expect_every_cell(const PolyMesh& mesh, CellShape shape) {
  const CellFaces cell_faces = build_cell_faces(mesh);
  for (Index c = 0; c < mesh.num_cells(); ++c)
    ASSERT_EQ(classify_cell(mesh, cell_faces, c).shape, shape) << c;
}

}  // namespace volmesh::test
