#pragma once
// The front's input from labelled surfaces, as the tet meshers' input check gives it.
#include <utility>
#include <vector>

#include "volmesh/domain/surface.hpp"
#include "volmesh/tet/projection.hpp"

namespace volmesh::tet::test {

inline std::vector<ProjectionSurface> surfaces_of(std::vector<LabelledSurface> list) {
  const SurfaceDomain domain(std::move(list));
  std::vector<ProjectionSurface> out;
  for (Index s = 0; s < static_cast<Index>(domain.labels().size()); ++s)
    out.push_back({domain.surface(s), domain.labels()[s], domain.depths()[s] == 0});
  return out;
}

}  // namespace volmesh::tet::test
