#pragma once
// Local refinement of a hex mesh by Schneiders' 3-refinement templates on marked nodes (the
// paper's "27-cell" templates): a hex with all eight corners marked splits into 27, and the hexes
// around it take transition templates that conform with both sides.
//
// A hex's template depends only on which of its corners are marked. The four supported cases,
// with every edge, quad and hex subdivided on a 3 x 3 x 3 lattice of its parameter cube:
//   none   : the hex is kept;
//   node   : one corner: the small cube at it and three hexes joining its inner faces to the far
//            faces (4 hexes);
//   edge   : the two corners of one edge: three small cubes along it, three above and three
//            beside them, and two slabs to the far faces (11 hexes);
//   face   : the four corners of one face: a 3 x 3 layer on it, a second 3 x 3 layer lifted
//            toward the far face (inner nodes at half height), and four hexes closing it (22);
//   full   : all eight corners: 27 hexes.
// Every other pattern is reduced to these by marking more nodes (the closure): marks that lie in
// one face become that whole face, marks that do not become the whole hex (two corners on a face
// diagonal -> the face; on a body diagonal, three or four not in one face, or five or more -> all
// eight). Marks only grow, so repeating this over all hexes reaches a fixed point.
//
// Conformity: an edge with both ends marked is split into three, with one marked end it gets one
// node at a third of its length from that end, else none. A quad is subdivided by its own four
// marks alone, so the two hexes on it agree:
//   0 marked          : kept;
//   1 corner          : 3 quads (the small quad at the corner and two joining it to the far edges);
//   2 on one edge     : 7 quads (three small ones along the edge, three above them with the inner
//                       two nodes at two thirds of the height, one closing quad to the far edge);
//   4                 : 9 quads.
// After the closure no quad has two diagonal or three marked corners, since no template has one.
//
// New nodes are placed by trilinear interpolation of the parent hex at their lattice point, so a
// box's refinement preserves its volume exactly and a new node on a shared quad or edge is the same
// point from either side; it is created once, keyed by the parent corners it interpolates and their
// weights. Each new hex keeps its parent's region and is positively oriented in VTK order when the
// parent is. Boundary quads are replaced by their subdivision, each keeping its parent's tag.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh {

enum class RefineCase : std::uint8_t { none, node, edge, face, full };
inline constexpr int kRefineCases = 5;

struct RefineStats {
  Index hexes_before = 0, hexes_after = 0;
  Index nodes_before = 0, nodes_after = 0;
  Index marked_given = 0;          // marked nodes as given
  Index marked_after_closure = 0;  // after the closure
  Index closure_passes = 0;        // sweeps over the hexes until no mark was added
  // Parent hexes by the template they took, indexed by RefineCase.
  std::array<Index, kRefineCases> hexes_by_case{};
};

// One char per node, non-zero = marked. The closure of the marks over the mesh's hexes (see
// above); returns the number of passes it took.
Index close_refinement_marks(const HexMesh& mesh, std::vector<char>& marked_nodes);

// The template case of a hex whose corner marks are `mask` (bit c = VTK corner c), once closed.
RefineCase refine_case(unsigned mask);

// Refines `mesh` in place after closing the marks. Throws InputError when marked_nodes does not
// have one entry per node. With no node marked the mesh is left as it is.
RefineStats refine_hexes(HexMesh& mesh, std::vector<char> marked_nodes);

// Marks: every node of the `layers` layers of hexes nearest the boundary (layer 1: the hexes with
// a node on a boundary quad; layer k + 1: those sharing a node with layer k), so that those hexes
// split into 27. 0 layers marks nothing.
std::vector<char> mark_boundary_layers(const HexMesh& mesh, int layers);

// Marks the nodes inside `box` (closed).
std::vector<char> mark_box(const HexMesh& mesh, const Eigen::AlignedBox3d& box);

}  // namespace volmesh
