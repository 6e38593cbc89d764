#pragma once
// The one order in which the projection mesher's callers try directions when a projection's
// exact mesh does not round to doubles (rounding.hpp refuses it): tet-projection when it
// chooses the axis itself, and tet-front's fallback on every stalled cavity.
#include <vector>

#include "volmesh/tet/projection.hpp"

namespace volmesh::tet {

// `first` along its axis, then `first` tilted once (kTiltEighths[0]), then the other axes
// untilted in the order z, x, y, then `first`'s other tilts: every axis untilted and `first`'s
// kTilts tilts. Rounding fails mostly where a symmetric model's points and edges meet in
// projection along every axis, which a tilt breaks and another axis often does not.
std::vector<ProjectionOptions> projection_directions(Axis first);

}  // namespace volmesh::tet
