#pragma once
// The quality improvement pass on a finished mesh (front.hpp, ImproveStats): flips, collapses
// of short interior edges and smoothing of the interior nodes, each change made only where it raises the minimum quality
// of the tets it touches, repeated until a pass changes nothing.
#include <array>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet::front {

// Points below fixed_nodes (the input surfaces' points) and the corners of `kept` never move;
// every triangle of `kept` (the input surfaces' triangles or their pieces, outer and interface)
// stays a face of the mesh. Collapsed nodes are dropped from m.points (the others keep their
// order, so the surfaces' points stay first). The mesh's boundary faces are untouched; its tets keep their
// regions. Serial, so the result is the same for any thread count.
ImproveStats improve_mesh(TetMesh& m, Index fixed_nodes,
                          const std::vector<std::array<Index, 3>>& kept);

}  // namespace volmesh::tet::front
