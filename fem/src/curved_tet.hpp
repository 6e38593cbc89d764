#pragma once
// The quadratic geometry maps of isoparametric P2: a tetrahedron whose edge nodes may sit off
// the straight midpoints (10 nodes: corners, then edges in lagrange.hpp's order), and its
// triangle faces (6 nodes: corners, then the edges of the loop). x(λ) = Σ N_k(λ) X_k with the
// P2 shape functions N_k; with X_k at the straight midpoints the map is the affine one.
#include <array>
#include <span>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/fem/problem.hpp"

namespace volmesh::fem::detail {

// At barycentric point l of the tet with geometry nodes `nodes`: its position, the P2 shape
// values and their physical gradients (through the inverse Jacobian). Returns the volume
// element det(∂x/∂(λ1, λ2, λ3)) / 6 — the tet's volume where the map is affine — by which a
// rule's weight (summing to 1) is multiplied. Where it is not positive the gradients are
// meaningless.
double curved_tet_point(const std::array<Vec3, 10>& nodes, const std::array<double, 4>& l,
                        Vec3& x, std::span<double, 10> value, std::span<Vec3, 10> gradient);

// At barycentric point l of the triangle with geometry nodes `nodes`: its position; returns
// the area element |∂x/∂λ1 × ∂x/∂λ2| / 2 — the triangle's area where the map is affine.
double curved_triangle_point(const std::array<Vec3, 6>& nodes, const std::array<double, 3>& l,
                             Vec3& x);

// The edge nodes on the true boundary: for each edge of a boundary face (mesh.is_boundary),
// given by its mesh points in `edges` (sorted, as core's edge list), whose two ends lie on the
// true boundary, its midpoint mapped by to_true_boundary. Entry e of the result is that point,
// or the straight midpoint where the edge is not such an edge or the map leaves the midpoint
// where it is (a flat side); moved[e] says which. Ends count as on the true boundary within
// kOnBoundary of the edge's length: a mesher that puts boundary vertices on the surface puts
// them there to rounding, and an edge whose ends are off it (a staircase) is no chord of it.
inline constexpr double kOnBoundary = 1e-6;
std::vector<Vec3> boundary_edge_nodes(const PolyMesh& mesh,
                                      std::span<const std::array<Index, 2>> edges,
                                      const PointMap& to_true_boundary, std::vector<char>& moved);

}  // namespace volmesh::fem::detail
