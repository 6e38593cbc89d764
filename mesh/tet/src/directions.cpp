#include "volmesh/tet/directions.hpp"

namespace volmesh::tet {

std::vector<ProjectionOptions> projection_directions(Axis first) {
  std::vector<ProjectionOptions> directions{{.auto_axis = false, .axis = first},
                                            {.auto_axis = false, .axis = first, .tilt = 1}};
  for (const Axis a : {Axis::z, Axis::x, Axis::y})
    if (a != first) directions.push_back({.auto_axis = false, .axis = a});
  for (int tilt = 2; tilt <= kTilts; ++tilt)
    directions.push_back({.auto_axis = false, .axis = first, .tilt = tilt});
  return directions;
}

}  // namespace volmesh::tet
