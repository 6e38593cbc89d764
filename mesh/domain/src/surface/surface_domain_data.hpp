#pragma once
// What a SurfaceDomain holds, shared by its queries (surface_domain.cpp) and its crossings
// (surface_crossings.cpp).
#include <vector>

#include "surface_closest.hpp"
#include "surface_exact.hpp"
#include "surface_geometry.hpp"

namespace volmesh::surface {

struct DomainData {
  explicit DomainData(SurfaceGeometry g)
      : geometry(std::move(g)), exact(geometry), closest(geometry) {}

  // The label of the innermost surface containing the point (the deepest, then the
  // highest label), 0 if none.
  Index region(const std::vector<Containment>& c) const {
    Index best = kNoIndex;
    for (Index s = 0; s < geometry.num_surfaces(); ++s)
      if (c[s].inside() && (best == kNoIndex || depth[s] > depth[best] ||
                            (depth[s] == depth[best] && label[s] > label[best])))
        best = s;
    return best == kNoIndex ? 0 : label[best];
  }

  SurfaceGeometry geometry;
  ExactTree exact;
  ClosestTree closest;
  std::vector<Index> label, depth;  // per surface
  std::vector<Index> regions;       // sorted, unique
  Box3 bounds;
};

}  // namespace volmesh::surface
