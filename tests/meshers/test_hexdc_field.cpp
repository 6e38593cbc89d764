// hexdc's field for a surface domain: the exact signed distance of its one outermost
// surface, positive inside, as `volmesh sdf` computes it.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "../support/surfaces.hpp"
#include "hexdc_field.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh {
namespace {

constexpr int kLevel = 3;
constexpr int kDepth = 4;  // 17 samples per axis

std::vector<std::array<Index, 3>> some_samples(Index dim) {
  const Index mid = dim / 2, last = dim - 1;
  return {{0, 0, 0}, {mid, mid, mid}, {1, mid, 3}, {last, 2, mid}, {mid - 1, mid + 2, 1}};
}

TEST(MeshersHexdcField, SurfaceDomainSamplesTheExactSignedDistance) {
  const TriSurface sphere = test::icosphere(2);
  const SurfaceDomain domain({LabelledSurface{sphere}});
  const VoxelGrid field = meshers::hexdc_field(domain, kDepth, meshers::hexdc_margin(kLevel),
                                               meshers::outer_surface_distance(domain).get());
  const SignedDistance exact(sphere, "sphere");
  const Index dim = field.dims[0];
  for (const auto& [i, j, k] : some_samples(dim)) {
    const Vec3 p = field.point(i, j, k);
    const float f = field.values[field.index(i, j, k)];
    EXPECT_EQ(f, static_cast<float>(exact(p))) << i << " " << j << " " << k;
    EXPECT_EQ(f > 0.0f, domain.region(p) != 0) << i << " " << j << " " << k;
  }
  const Index mid = dim / 2;
  EXPECT_GT(field.values[field.index(mid, mid, mid)], 0.0f);  // the centre, inside
  EXPECT_LT(field.values[field.index(0, 0, 0)], 0.0f);
}

// A nested surface is an interface, not a boundary: the field is the outer surface's alone.
TEST(MeshersHexdcField, NestedSurfacesTakeTheOutermostOnesDistance) {
  TriSurface inner = test::unit_cube();
  for (Vec3& p : inner.points) p = 0.25 * p + Vec3::Constant(0.375);
  TriSurface outer = test::unit_cube();
  const SurfaceDomain domain({LabelledSurface{inner}, LabelledSurface{outer}});
  EXPECT_EQ(domain.surface(1).num_triangles(), outer.num_triangles());
  const VoxelGrid field = meshers::hexdc_field(domain, kDepth, meshers::hexdc_margin(kLevel),
                                               meshers::outer_surface_distance(domain).get());
  const SignedDistance exact(outer, "outer");
  for (const auto& [i, j, k] : some_samples(field.dims[0])) {
    const Vec3 p = field.point(i, j, k);
    EXPECT_EQ(field.values[field.index(i, j, k)], static_cast<float>(exact(p)));
  }
}

}  // namespace
}  // namespace volmesh
