// checkMesh's verdict on the faces a triangulation gives a cell's pieces, from the pieces'
// centres (face_metrics.hpp): what the choice among the candidates and the repairs minimise.
#include <algorithm>

#include "cell_split_state.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/quality/face_metrics.hpp"

namespace volmesh::cutcell {
namespace {

// A triangle this flat (area / longest side squared) is as bad as an inverted one: its
// corners lie in a line up to rounding, it has no normal to orient it (`volmesh check`
// rejects it at 1e-12).
constexpr double kFlatTriangle = 1e-9;

}  // namespace

double badness(const SplitState& s, std::span<const int> face, const Vec3& owner, const Vec3& neighbour,
               bool outside) {
  FaceGeometry g;
  if (face.size() == 3) {
    const Vec3 &a = s.position[face[0]], &b = s.position[face[1]], &c = s.position[face[2]];
    g.centre = (a + b + c) / 3.0;
    g.area_vector = 0.5 * (b - a).cross(c - a);
    if (flatness(s.position, face, g.area_vector.norm()) <= kFlatTriangle) return kInvertedFace;
  } else {
    g = polygon_geometry(s.position, std::vector<Index>(face.begin(), face.end()));
  }
  // Every inverted face counts alike here (the merging grades them by how far behind a
  // centre they lie): to the choice among candidates, one inverted face is as bad as another.
  return std::min(kInvertedFace,
                  checkmesh_badness(g, s.position, face, owner, outside ? nullptr : &neighbour, s.options.limits));
}

double worst_badness(const SplitState& s, const LoopTriangles& triangles) {
  const std::vector<Vec3> centre = piece_centres(s, triangles);
  double worst = 0.0;
  for (std::size_t l = 0; l < s.loops.size(); ++l) {
    const auto [lower, higher] = s.loop_pieces(s.loops[l]);
    for (const Triangle& t : triangles[l])
      worst = std::max(worst, badness(s, t, centre[higher], centre[lower], s.out.pieces[lower].region == 0));
  }
  return worst;
}

}  // namespace volmesh::cutcell
