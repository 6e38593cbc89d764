#include <algorithm>

#include "volmesh/core/geometry.hpp"
#include "volmesh/fem/polyhedral.hpp"

namespace volmesh::fem {
std::optional<VirtualElement> virtual_element(const PolyMesh& mesh, const FaceSplits& splits,
                                              std::span<const Index> faces, Index c,
                                              std::span<const Index> vertices) {
  const std::size_t n = vertices.size();
  if (n < 4) return std::nullopt;
  for (Index f : faces)
    if (splits.folded[f]) return std::nullopt;
  VirtualElement e;
  e.vertex_average = Vec3::Zero();
  for (Index v : vertices) e.vertex_average += mesh.points[v] / static_cast<double>(n);
  e.gradient.assign(n, Vec3::Zero());
  const auto local = [&](Index point) {
    return std::lower_bound(vertices.begin(), vertices.end(), point) - vertices.begin();
  };
  // Signed cones on the face triangles from the vertex average: their volumes add up to the
  // cell's wherever the apex lies; ∫ φ_i n over a triangle is its area vector times the mean
  // of φ_i at its corners (a face node carries 1/size of each of its face's vertices).
  Vec3 moment = Vec3::Zero();
  double longest = 0.0;
  for_each_sub_tetrahedron(mesh, splits, faces, c, e.vertex_average, [&](const SubTetrahedron& t) {
    const double v = tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
    e.volume += v;
    moment += v * (t.corners[0] + t.corners[1] + t.corners[2] + t.corners[3]) / 4.0;
    for (int i = 1; i < 4; ++i) longest = std::max(longest, (t.corners[i] - t.corners[0]).norm());
    const Vec3 third = (t.corners[2] - t.corners[1]).cross(t.corners[3] - t.corners[1]) / 6.0;
    const auto loop = mesh.face(t.face);
    e.gradient[local(loop[t.p])] += third;
    e.gradient[local(loop[t.q])] += third;
    if (t.fanned)
      for (Index v : loop) e.gradient[local(v)] += third / static_cast<double>(loop.size());
    else
      e.gradient[local(loop[t.r])] += third;
  });
  // A cell thinner than this of its size is as degenerate as a flat sub-tetrahedron (the
  // same threshold as the star centre's, geometry/cell_tessellation.cpp).
  constexpr double kDegenerateShape = 1e-12;
  if (!(e.volume > kDegenerateShape * longest * longest * longest)) return std::nullopt;
  e.centroid = moment / e.volume;
  for (Vec3& g : e.gradient) g /= e.volume;
  return e;
}

}  // namespace volmesh::fem
