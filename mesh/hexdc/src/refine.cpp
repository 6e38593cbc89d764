// Assembly of the refined mesh (refine.hpp): each hex replaced by its template, new nodes shared
// through a key on the parent corners they interpolate, boundary quads rebuilt from the new hexes'
// faces that lie on a parent's boundary quad.
#include <algorithm>
#include <map>
#include <utility>

#include "refine_templates.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/hexdc/refine.hpp"

namespace volmesh {

namespace {

using hexdc_detail::kLatticeSteps;
using hexdc_detail::LatticePoint;
using hexdc_detail::TemplateHex;

// A node by the parent corners it interpolates and their integer trilinear weights (summing to
// kLatticeSteps^3), sorted by corner id: the same key from every hex sharing the quad or edge.
using NodeKey = std::vector<std::pair<Index, int>>;
using QuadKey = std::array<Index, 4>;

QuadKey sorted_quad(QuadKey q) {
  std::sort(q.begin(), q.end());
  return q;
}

class Assembler {
 public:
  explicit Assembler(const HexMesh& mesh) : mesh_(mesh), points_(mesh.points) {
    for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
      boundary_tag_.emplace(sorted_quad(mesh.boundary_faces[f]), mesh.boundary_tag[f]);
  }

  void add_template(Index parent, const std::vector<TemplateHex>& hexes) {
    const auto& cell = mesh_.cells[static_cast<std::size_t>(parent)];
    for (const TemplateHex& hex : hexes) {
      std::array<Index, 8> corners;
      for (std::size_t c = 0; c < 8; ++c) corners[c] = node_at(cell, hex[c]);
      cells_.push_back(corners);
      regions_.push_back(mesh_.cell_region[static_cast<std::size_t>(parent)]);
      add_boundary_quads(cell, hex, corners);
    }
  }

  void finish(HexMesh& out) {
    out.points = std::move(points_);
    out.cells = std::move(cells_);
    out.cell_region = std::move(regions_);
    out.boundary_faces = std::move(faces_);
    out.boundary_tag = std::move(tags_);
  }

 private:
  Index node_at(const std::array<Index, 8>& cell, const LatticePoint& q) {
    for (int c = 0; c < 8; ++c)
      if (hexdc_detail::corner_point(c) == q) return cell[static_cast<std::size_t>(c)];
    NodeKey key;
    for (int c = 0; c < 8; ++c) {
      const LatticePoint corner = hexdc_detail::corner_point(c);
      int weight = 1;
      for (std::size_t i = 0; i < 3; ++i) weight *= corner[i] != 0 ? q[i] : kLatticeSteps - q[i];
      if (weight != 0) key.emplace_back(cell[static_cast<std::size_t>(c)], weight);
    }
    std::sort(key.begin(), key.end());
    const auto [it, inserted] = nodes_.try_emplace(key, static_cast<Index>(points_.size()));
    if (inserted) {
      constexpr double kWeightSum = kLatticeSteps * kLatticeSteps * kLatticeSteps;
      Vec3 p = Vec3::Zero();
      for (const auto& [id, weight] : key)
        p += (static_cast<double>(weight) / kWeightSum) * mesh_.points[static_cast<std::size_t>(id)];
      points_.push_back(p);
    }
    return it->second;
  }

  // The new hex's faces lying on a face of the parent that is a boundary quad, with its tag.
  void add_boundary_quads(const std::array<Index, 8>& parent, const TemplateHex& hex,
                          const std::array<Index, 8>& corners) {
    for (const auto& face : kHexFaces) {
      for (std::size_t axis = 0; axis < 3; ++axis) {
        const int side = hex[static_cast<std::size_t>(face[0])][axis];
        if (side != 0 && side != kLatticeSteps) continue;
        const bool flat = std::all_of(face.begin(), face.end(), [&](int c) {
          return hex[static_cast<std::size_t>(c)][axis] == side;
        });
        if (!flat) continue;
        QuadKey parent_face;
        std::size_t n = 0;
        for (int c = 0; c < 8; ++c)
          if (hexdc_detail::corner_point(c)[axis] == side) parent_face[n++] = parent[static_cast<std::size_t>(c)];
        const auto tag = boundary_tag_.find(sorted_quad(parent_face));
        if (tag == boundary_tag_.end()) continue;
        faces_.push_back({corners[static_cast<std::size_t>(face[0])], corners[static_cast<std::size_t>(face[1])],
                          corners[static_cast<std::size_t>(face[2])], corners[static_cast<std::size_t>(face[3])]});
        tags_.push_back(tag->second);
      }
    }
  }

  const HexMesh& mesh_;
  std::map<QuadKey, Index> boundary_tag_;
  std::map<NodeKey, Index> nodes_;
  std::vector<Vec3> points_;
  std::vector<std::array<Index, 8>> cells_;
  std::vector<Index> regions_;
  std::vector<std::array<Index, 4>> faces_;
  std::vector<Index> tags_;
};

Index count_marked(const std::vector<char>& marked) {
  return static_cast<Index>(std::count_if(marked.begin(), marked.end(), [](char m) { return m != 0; }));
}

}  // namespace

RefineStats refine_hexes(HexMesh& mesh, std::vector<char> marked_nodes) {
  if (marked_nodes.size() != mesh.points.size())
    throw InputError("refine: " + std::to_string(marked_nodes.size()) + " node marks for " +
                     std::to_string(mesh.points.size()) + " nodes");
  RefineStats stats;
  stats.hexes_before = stats.hexes_after = mesh.num_cells();
  stats.nodes_before = stats.nodes_after = mesh.num_points();
  stats.marked_given = count_marked(marked_nodes);
  if (stats.marked_given == 0) {
    stats.hexes_by_case[static_cast<std::size_t>(RefineCase::none)] = mesh.num_cells();
    return stats;
  }
  stats.closure_passes = close_refinement_marks(mesh, marked_nodes);
  stats.marked_after_closure = count_marked(marked_nodes);

  Assembler assembler(mesh);
  for (Index h = 0; h < mesh.num_cells(); ++h) {
    const unsigned mask = hexdc_detail::corner_mask(mesh.cells[static_cast<std::size_t>(h)], marked_nodes);
    ++stats.hexes_by_case[static_cast<std::size_t>(refine_case(mask))];
    assembler.add_template(h, hexdc_detail::template_hexes(mask));
  }
  assembler.finish(mesh);
  stats.hexes_after = mesh.num_cells();
  stats.nodes_after = mesh.num_points();
  return stats;
}

}  // namespace volmesh
