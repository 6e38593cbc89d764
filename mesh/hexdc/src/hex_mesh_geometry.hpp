#pragma once
// Geometry of a HexMesh's hexes and boundary quads shared by smoothing, untangling, pillowing
// and projection.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh::hexdc_detail {

// The feature angle every stage takes (smoothing, pillowing, projection, untangling): throws
// InputError "STAGE: feature angle must lie in [0, 180] degrees" outside that range, else
// returns its cosine, which the feature test compares against.
inline double feature_cosine(const char* stage, double degrees) {
  if (!(degrees >= 0.0 && degrees <= 180.0))
    throw InputError(std::string(stage) + ": feature angle must lie in [0, 180] degrees");
  return std::cos(degrees * std::numbers::pi / 180.0);
}

inline std::array<Vec3, 8> hex_corners(const HexMesh& mesh, Index h) {
  std::array<Vec3, 8> corners;
  const auto& cell = mesh.cells[static_cast<std::size_t>(h)];
  for (std::size_t c = 0; c < 8; ++c) corners[c] = mesh.points[static_cast<std::size_t>(cell[c])];
  return corners;
}

// Per hex of the mesh as it is now: a quality measure and whether it passes the ten corner tets.
struct HexState {
  std::vector<double> quality;
  std::vector<bool> valid;
};

// The state of every hex, its quality by `measure` (a function of the 8 corners).
template <class Measure>
HexState hex_state(const HexMesh& mesh, Measure measure) {
  HexState state;
  state.quality.reserve(mesh.cells.size());
  state.valid.reserve(mesh.cells.size());
  for (Index h = 0; h < mesh.num_cells(); ++h) {
    const auto corners = hex_corners(mesh, h);
    state.quality.push_back(measure(corners));
    state.valid.push_back(hex_corner_tets_positive(corners));
  }
  return state;
}

// Moves node v to `target` when every hex of `hexes` (v's) passing the ten corner tets still
// does and the least scaled Jacobian over them stays at or above min(what it was, `floor`),
// updating `state` (whose quality is the scaled Jacobian); otherwise restores the node. The hex
// `hexes[first]` is judged first and, on a rejection, `first` becomes the hex that failed: the
// hex that failed a step usually fails its half too, so a rejection costs one grade, not all.
// `trial` holds the grades of the hexes judged so far.
inline bool guarded_move(HexMesh& mesh, const std::vector<Index>& hexes, std::size_t v,
                         const Vec3& target, double floor, HexState& state, std::size_t& first,
                         std::vector<HexGrade>& trial) {
  double least_before = std::numeric_limits<double>::infinity();
  for (const Index h : hexes)
    least_before = std::min(least_before, state.quality[static_cast<std::size_t>(h)]);
  const double least_allowed = std::min(least_before, floor);
  const Vec3 old_point = mesh.points[v];
  mesh.points[v] = target;
  trial.resize(hexes.size());
  if (first >= hexes.size()) first = 0;
  for (std::size_t k = 0; k < hexes.size(); ++k) {
    const std::size_t i = k == 0 ? first : (k <= first ? k - 1 : k);
    const auto h = static_cast<std::size_t>(hexes[i]);
    trial[i] = hex_grade(hex_corners(mesh, static_cast<Index>(h)));
    if (trial[i].scaled_jacobian < least_allowed ||
        (state.valid[h] && !trial[i].corner_tets_positive)) {
      mesh.points[v] = old_point;
      first = i;
      return false;
    }
  }
  for (std::size_t i = 0; i < hexes.size(); ++i) {
    const auto h = static_cast<std::size_t>(hexes[i]);
    state.quality[h] = trial[i].scaled_jacobian;
    state.valid[h] = trial[i].corner_tets_positive;
  }
  return true;
}

// Marks every node sharing a hex or a boundary quad with node v: the nodes whose moves are
// judged on a hex or a quad that a move of v changes.
inline void mark_around(const HexMesh& mesh, const std::vector<Index>& hexes,
                        const std::vector<Index>& quads, std::vector<char>& marked) {
  for (const Index h : hexes)
    for (const Index u : mesh.cells[static_cast<std::size_t>(h)])
      marked[static_cast<std::size_t>(u)] = 1;
  for (const Index q : quads)
    for (const Index u : mesh.boundary_faces[static_cast<std::size_t>(q)])
      marked[static_cast<std::size_t>(u)] = 1;
}

inline double least_quality(const HexState& state) {
  return *std::min_element(state.quality.begin(), state.quality.end());
}

inline Index invalid_count(const HexState& state) {
  return static_cast<Index>(std::count(state.valid.begin(), state.valid.end(), false));
}

// Per node, the hexes having it as a corner, in hex order.
inline std::vector<std::vector<Index>> hexes_of_nodes(const HexMesh& mesh) {
  std::vector<std::vector<Index>> hexes(mesh.points.size());
  for (Index h = 0; h < mesh.num_cells(); ++h)
    for (const Index v : mesh.cells[static_cast<std::size_t>(h)]) {
      auto& list = hexes[static_cast<std::size_t>(v)];
      if (list.empty() || list.back() != h) list.push_back(h);
    }
  return hexes;
}

// Per node, the boundary quads having it as a corner, in quad order (empty off the boundary).
inline std::vector<std::vector<Index>> boundary_quads_of_nodes(const HexMesh& mesh) {
  std::vector<std::vector<Index>> quads(mesh.points.size());
  for (std::size_t q = 0; q < mesh.boundary_faces.size(); ++q)
    for (const Index v : mesh.boundary_faces[q])
      quads[static_cast<std::size_t>(v)].push_back(static_cast<Index>(q));
  return quads;
}

// Half the cross product of the diagonals: the quad's normal times its area, exact for a planar
// quad, so that quads in an axis plane give an exactly axial normal.
inline Vec3 quad_vector_area(const HexMesh& mesh, Index q) {
  const auto& quad = mesh.boundary_faces[static_cast<std::size_t>(q)];
  const auto p = [&](std::size_t c) { return mesh.points[static_cast<std::size_t>(quad[c])]; };
  return 0.5 * (p(2) - p(0)).cross(p(3) - p(1));
}

// The unit sum of the vector areas of `quads`; zero when the areas cancel.
inline Vec3 node_normal(const HexMesh& mesh, const std::vector<Index>& quads) {
  Vec3 sum = Vec3::Zero();
  for (const Index q : quads) sum += quad_vector_area(mesh, q);
  return sum.normalized();
}

// A boundary node on a crease or corner: a quad's normal leaves the mean normal by more than the
// feature angle (or the quads have no mean normal).
inline bool on_feature(const HexMesh& mesh, const std::vector<Index>& quads, double cos_feature) {
  const Vec3 normal = node_normal(mesh, quads);
  if (normal.isZero()) return true;
  return std::any_of(quads.begin(), quads.end(), [&](Index q) {
    return quad_vector_area(mesh, q).normalized().dot(normal) < cos_feature;
  });
}

}  // namespace volmesh::hexdc_detail
