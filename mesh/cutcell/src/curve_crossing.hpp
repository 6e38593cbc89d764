#pragma once
// Where two interfaces cross inside a face (an X-junction: two surfaces crossing, four
// regions around), from the two points where each crosses the face's sides and its normals
// there. The least-squares intersection of the four tangent lines extrapolates the far
// tangent of a curved one across the face (off by d^2 / 2r at distance d); each curve is
// taken instead as the parabola over its chord whose end slopes match the normals' tangents
// on average: O(h^3) off a smooth curve, exact on a straight one.
#include <array>
#include <optional>

#include "volmesh/core/types.hpp"

namespace volmesh::cutcell {

// A curve in a plane through two points, with unit normals pointing to the same side.
struct CurveEnds {
  std::array<Vec3, 2> point;
  std::array<Vec3, 2> normal;
};

// The crossing of the two curves in the plane of unit normal `plane_normal`; nullopt when a
// curve leaves its chord too steeply for a parabola over it, or they do not cross between
// their ends.
std::optional<Vec3> crossing_of_curves(const CurveEnds& a, const CurveEnds& b, const Vec3& plane_normal);

}  // namespace volmesh::cutcell
