#pragma once
// Orientation-preserving canonical forms of cells and faces for the VTU and MSH writers, so
// that their output depends on the cells alone and not on how the PolyMesh happens to store
// its faces: writing a mesh read back from our own file gives the same bytes again.
#include <array>
#include <span>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// The smallest (lexicographically) of the 12 even permutations of a VTK-ordered tet.
std::array<Index, 4> canonical_tet(const std::array<Index, 8>& corners);
// The smallest of the 24 rotations of a VTK-ordered hex.
std::array<Index, 8> canonical_hex(const std::array<Index, 8>& corners);

// Rotates a face loop to start at its smallest vertex (keeps the orientation).
void rotate_to_smallest(std::span<Index> loop);

// Outward loops of cell c, each rotated to its smallest vertex, sorted.
std::vector<std::vector<Index>> canonical_faces(const PolyMesh& mesh, std::span<const Index> faces,
                                                Index c);

}  // namespace volmesh
