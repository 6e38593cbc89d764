#include "volmesh/hexdc/pillow.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "hex_mesh_geometry.hpp"
#include "quad_faces.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh {
namespace {

using namespace hexdc_detail;

Index multi_boundary_hexes(const HexMesh& mesh) {
  std::vector<int> faces(mesh.cells.size(), 0);
  for (const Index h : quad_owners(mesh))
    if (h >= 0) ++faces[static_cast<std::size_t>(h)];
  return static_cast<Index>(
      std::count_if(faces.begin(), faces.end(), [](int n) { return n >= 2; }));
}

struct Quality {
  Index invalid = 0;
  double min_scaled_jacobian = std::numeric_limits<double>::infinity();
};

Quality quality(const HexMesh& mesh) {
  Quality q;
  for (Index h = 0; h < mesh.num_cells(); ++h) {
    const HexGrade grade = hex_grade(hex_corners(mesh, h));
    q.min_scaled_jacobian = std::min(q.min_scaled_jacobian, grade.scaled_jacobian);
    q.invalid += grade.corner_tets_positive ? 0 : 1;
  }
  return q;
}

// The boundary nodes, each with the unit inward direction and the offset of its inner copy.
struct Copies {
  std::vector<Index> boundary_nodes;  // the outer nodes, in index order
  std::vector<Vec3> direction;        // per boundary node
  std::vector<double> offset;         // per boundary node
};

Copies plan_copies(const HexMesh& mesh, const PillowOptions& options, double cos_feature) {
  const std::size_t n = mesh.points.size();
  std::vector<std::vector<Index>> quads(n);
  for (std::size_t q = 0; q < mesh.boundary_faces.size(); ++q)
    for (const Index v : mesh.boundary_faces[q])
      quads[static_cast<std::size_t>(v)].push_back(static_cast<Index>(q));
  std::vector<double> shortest(n, std::numeric_limits<double>::infinity());
  for (const auto& cell : mesh.cells)
    for (const auto& [a, b] : kHexEdges) {
      const auto u = static_cast<std::size_t>(cell[a]), w = static_cast<std::size_t>(cell[b]);
      const double length = (mesh.points[u] - mesh.points[w]).norm();
      shortest[u] = std::min(shortest[u], length);
      shortest[w] = std::min(shortest[w], length);
    }
  Copies copies;
  for (std::size_t v = 0; v < n; ++v) {
    if (quads[v].empty()) continue;
    Vec3 outward = node_normal(mesh, quads[v]);
    if (on_feature(mesh, quads[v], cos_feature)) {
      Vec3 sum = Vec3::Zero();
      for (const Index q : quads[v]) sum += quad_vector_area(mesh, q).normalized();
      outward = sum.normalized();
    }
    copies.boundary_nodes.push_back(static_cast<Index>(v));
    copies.direction.push_back(-outward);
    copies.offset.push_back(options.offset_fraction * shortest[v]);
  }
  return copies;
}

// Failing hexes among `hexes`.
Index failing(const HexMesh& mesh, const std::vector<Index>& hexes) {
  return static_cast<Index>(std::count_if(hexes.begin(), hexes.end(), [&](Index h) {
    return !hex_corner_tets_positive(hex_corners(mesh, h));
  }));
}

void place_copy(HexMesh& mesh, const Copies& copies, Index first_copy, std::size_t i) {
  mesh.points[static_cast<std::size_t>(first_copy) + i] =
      mesh.points[static_cast<std::size_t>(copies.boundary_nodes[i])] +
      copies.offset[i] * copies.direction[i];
}

// Halves the offset of each inner copy in a failing hex when that lowers the failures among its
// hexes, up to options.halvings rounds. A halving that does not help is undone: a thinner pillow
// hex on a curved quad fails sooner, so shrinking is no cure in general. Returns, per copy, whether
// it was shrunk.
std::vector<bool> shrink_failing_copies(HexMesh& mesh, Copies& copies, Index first_copy,
                                        const PillowOptions& options) {
  std::vector<std::vector<Index>> hexes(copies.boundary_nodes.size());
  for (Index h = 0; h < mesh.num_cells(); ++h)
    for (const Index v : mesh.cells[static_cast<std::size_t>(h)])
      if (v >= first_copy) hexes[static_cast<std::size_t>(v - first_copy)].push_back(h);
  std::vector<bool> shrunk(copies.boundary_nodes.size(), false);
  for (int k = 0; k < options.halvings; ++k) {
    bool any = false;
    for (std::size_t i = 0; i < hexes.size(); ++i) {
      const Index was = failing(mesh, hexes[i]);
      if (was == 0) continue;
      copies.offset[i] *= 0.5;
      place_copy(mesh, copies, first_copy, i);
      if (failing(mesh, hexes[i]) < was) {
        shrunk[i] = any = true;
        continue;
      }
      copies.offset[i] *= 2.0;
      place_copy(mesh, copies, first_copy, i);
    }
    if (!any) break;
  }
  return shrunk;
}

}  // namespace

PillowStats pillow_boundary(HexMesh& mesh, const PillowOptions& options, FeatureLayer* layer) {
  if (!(options.offset_fraction > 0.0 && options.offset_fraction < 1.0))
    throw InputError("pillow_boundary: the offset fraction must lie in (0, 1)");
  if (options.halvings < 0) throw InputError("pillow_boundary: halvings must not be negative");
  const double cos_feature = feature_cosine("pillow_boundary", options.feature_angle_deg);
  PillowStats stats;
  if (mesh.cells.empty()) return stats;
  FeatureLayer features;
  if (options.features != nullptr) features = chain_features(mesh, *options.features);
  const Quality before = quality(mesh);
  stats.invalid_hexes_before = before.invalid;
  stats.min_scaled_jacobian_before = before.min_scaled_jacobian;
  stats.multi_boundary_hexes_before = multi_boundary_hexes(mesh);

  Copies copies = plan_copies(mesh, options, cos_feature);
  const std::vector<Index> owner = quad_owners(mesh);
  const Index first_copy = mesh.num_points();
  std::vector<Index> inner(mesh.points.size(), -1);
  mesh.points.resize(mesh.points.size() + copies.boundary_nodes.size());
  for (std::size_t i = 0; i < copies.boundary_nodes.size(); ++i) {
    inner[static_cast<std::size_t>(copies.boundary_nodes[i])] = first_copy + static_cast<Index>(i);
    place_copy(mesh, copies, first_copy, i);
  }
  for (auto& cell : mesh.cells)
    for (Index& v : cell)
      if (inner[static_cast<std::size_t>(v)] >= 0) v = inner[static_cast<std::size_t>(v)];
  for (std::size_t q = 0; q < mesh.boundary_faces.size(); ++q) {
    const auto& quad = mesh.boundary_faces[q];
    std::array<Index, 8> hex{};
    for (std::size_t c = 0; c < 4; ++c) {
      hex[c] = inner[static_cast<std::size_t>(quad[c])];
      hex[c + 4] = quad[c];
    }
    mesh.cells.push_back(hex);
    mesh.cell_region.push_back(owner[q] >= 0 ? mesh.cell_region[static_cast<std::size_t>(owner[q])]
                                             : 1);
  }
  stats.boundary_nodes = static_cast<Index>(copies.boundary_nodes.size());
  stats.pillow_hexes = static_cast<Index>(mesh.boundary_faces.size());

  const std::vector<bool> shrunk = shrink_failing_copies(mesh, copies, first_copy, options);
  if (options.features != nullptr && options.follow_features) pillow_patches(mesh, features);
  if (layer != nullptr) *layer = std::move(features);
  const Quality after = quality(mesh);
  stats.shrunk_copies = static_cast<Index>(std::count(shrunk.begin(), shrunk.end(), true));
  stats.invalid_hexes_after = after.invalid;
  stats.min_scaled_jacobian_after = after.min_scaled_jacobian;
  stats.multi_boundary_hexes_after = multi_boundary_hexes(mesh);
  return stats;
}

}  // namespace volmesh
