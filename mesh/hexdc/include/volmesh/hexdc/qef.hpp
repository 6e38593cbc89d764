#pragma once
// The vertex of a boundary octree node in dual contouring: the minimiser of the quadratic
// error function E(x) = Σ (nᵢ · (x − pᵢ))² over the crossings (pᵢ, nᵢ) of the isosurface with
// the node's edges.
//
// With A the matrix of the normals (row i = nᵢᵀ) and b the vector of nᵢ · pᵢ, E is minimal
// where A x = b in the least-squares sense. When the normals do not span three directions
// (a flat piece of surface, or an edge instead of a corner) the minimisers form a plane or a
// line, and the paper regularises E toward the mass point m of the crossings. This solves the
// truncated-SVD form instead, about the mass point:
//   x = m + A⁺ (b − A m),
// with A⁺ the pseudo-inverse of A in which singular values below kQefSingularCutoff times
// the largest are dropped. Along the kept directions x minimises E; along the dropped ones it
// stays at m, so x is the minimiser nearest the mass point, as the paper's extra row intends,
// without biasing the well-determined directions.
#include <Eigen/Geometry>
#include <span>

#include "volmesh/core/types.hpp"

namespace volmesh {

// Singular values of A below this fraction of the largest are treated as zero: 0.1 as in
// Ju et al.'s and Lindstrom's dual contouring. For two unit normals at an angle θ the ratio
// of the singular values is tan(θ/2), so surfaces bending by less than about 11° count as
// flat: their planes would otherwise meet far away, and the vertex would follow round-off.
inline constexpr double kQefSingularCutoff = 0.1;

// A crossing of the isosurface with an edge of the node: the point and the unit normal there.
struct EdgeCrossing {
  Vec3 point;
  Vec3 normal;
};

struct QefVertex {
  Vec3 point;
  int rank = 0;  // singular values kept, 0..3 (0 only when every normal is zero)
  // The minimiser left the node's box and the mass point was returned instead.
  bool fell_back = false;
};

// Box tolerance, relative to the node's diagonal, under which a minimiser on the box's
// surface still counts as inside (round-off of a corner lying exactly on a face).
inline constexpr double kQefBoxTolerance = 1e-9;

// The QEF vertex of a node. If the minimiser lies outside `node` (beyond kQefBoxTolerance)
// the mass point is returned: it lies inside the node whenever the crossings lie on its
// edges, and it stays near the surface, whereas clamping would move the vertex to the box's
// surface, possibly far from the isosurface and onto a vertex of the neighbouring node,
// folding the hexes between them.
// Throws std::invalid_argument when `crossings` is empty.
QefVertex solve_qef(std::span<const EdgeCrossing> crossings, const Eigen::AlignedBox3d& node);

}  // namespace volmesh
