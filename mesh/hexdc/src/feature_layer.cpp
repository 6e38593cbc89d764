// The second pillowing of the patches between chains (feature_layer.hpp).
#include <algorithm>
#include <map>
#include <set>

#include "quad_faces.hpp"
#include "volmesh/hexdc/feature_layer.hpp"

namespace volmesh {
namespace {

using hexdc_detail::hex_face_key;
using hexdc_detail::QuadKey;
using hexdc_detail::sorted_key;

// A copied node moves this far from its place toward the mean centre of its shrink-set hexes:
// the new hexes take about that share of the old ones' thickness.
constexpr double kShrink = 0.5;

using Edge = std::pair<Index, Index>;
Edge edge_key(Index a, Index b) { return {std::min(a, b), std::max(a, b)}; }

// Per boundary quad, its patch: quads joined across edges not on a chain, numbered in order of
// their first quad.
std::vector<Index> patches(const HexMesh& mesh, const std::set<Edge>& chain_edges) {
  std::map<Edge, std::vector<Index>> sides;
  for (std::size_t q = 0; q < mesh.boundary_faces.size(); ++q)
    for (std::size_t c = 0; c < 4; ++c)
      sides[edge_key(mesh.boundary_faces[q][c], mesh.boundary_faces[q][(c + 1) % 4])].push_back(
          static_cast<Index>(q));
  std::vector<Index> patch(mesh.boundary_faces.size(), -1);
  Index next = 0;
  for (std::size_t seed = 0; seed < patch.size(); ++seed) {
    if (patch[seed] >= 0) continue;
    std::vector<Index> stack{static_cast<Index>(seed)};
    patch[seed] = next;
    while (!stack.empty()) {
      const auto q = static_cast<std::size_t>(stack.back());
      stack.pop_back();
      for (std::size_t c = 0; c < 4; ++c) {
        const Edge e = edge_key(mesh.boundary_faces[q][c], mesh.boundary_faces[q][(c + 1) % 4]);
        if (chain_edges.count(e) > 0) continue;
        for (const Index r : sides[e])
          if (patch[static_cast<std::size_t>(r)] < 0) {
            patch[static_cast<std::size_t>(r)] = next;
            stack.push_back(r);
          }
      }
    }
    ++next;
  }
  return patch;
}

struct Face {
  Index hex;
  std::array<Index, 4> nodes;  // outward from the set
};

// Where the copies go, in the layer's hexes (pillow.hpp: the inner quad as corners 0-3, the
// boundary quad above as 4-7): kShrink of the way toward the mean centre of the node's quads in
// the set, its boundary quads for a surface node (along the surface, into the patch), its hexes
// for an inner one.
void place_copies(HexMesh& mesh, const std::vector<Index>& set, const std::map<Index, Index>& copy) {
  std::map<Index, std::pair<Vec3, int>> centres;
  const auto add = [&](Index v, const Vec3& centre) {
    auto& [sum, n] = centres.try_emplace(v, Vec3::Zero(), 0).first->second;
    sum += centre;
    ++n;
  };
  for (const Index h : set) {
    const auto& cell = mesh.cells[static_cast<std::size_t>(h)];
    Vec3 top = Vec3::Zero(), bottom = Vec3::Zero();
    for (std::size_t c = 0; c < 4; ++c) {
      bottom += mesh.points[static_cast<std::size_t>(cell[c])] / 4.0;
      top += mesh.points[static_cast<std::size_t>(cell[c + 4])] / 4.0;
    }
    for (std::size_t c = 0; c < 4; ++c) {
      if (copy.count(cell[c + 4]) > 0) add(cell[c + 4], top);
      if (copy.count(cell[c]) > 0) add(cell[c], 0.5 * (top + bottom));
    }
  }
  for (const auto& [v, c] : copy) {
    const Vec3& p = mesh.points[static_cast<std::size_t>(v)];
    const auto& [sum, n] = centres.at(v);
    mesh.points[static_cast<std::size_t>(c)] = p + kShrink * (sum / n - p);
  }
}

// Pillows the shrink set `set` (hexes, each owning the boundary quads `quads`): every face of
// the set that is neither inside it nor on the boundary gets a new hex between it and a copy of
// it, which the set's hexes take. The new hexes' faces on no other hex join the boundary with
// tag `tag`. Returns the hexes added.
Index pillow_set(HexMesh& mesh, const std::vector<Index>& set, const std::vector<Index>& quads,
                 Index tag) {
  const bool tagged = mesh.boundary_tag.size() == mesh.boundary_faces.size() && !mesh.boundary_tag.empty();
  std::map<QuadKey, int> count;
  for (const Index h : set)
    for (const auto& face : kHexFaces) ++count[hex_face_key(mesh, h, face)];
  std::set<QuadKey> outside;
  for (const Index q : quads) outside.insert(sorted_key(mesh.boundary_faces[static_cast<std::size_t>(q)]));
  std::vector<Face> faces;
  std::map<Index, Index> copy;
  for (const Index h : set)
    for (const auto& face : kHexFaces) {
      const QuadKey key = hex_face_key(mesh, h, face);
      if (count[key] != 1 || outside.count(key) > 0) continue;
      const auto& cell = mesh.cells[static_cast<std::size_t>(h)];
      faces.push_back({h, {cell[face[0]], cell[face[1]], cell[face[2]], cell[face[3]]}});
      for (const Index v : faces.back().nodes)
        if (copy.emplace(v, mesh.num_points()).second) mesh.points.push_back(mesh.points[static_cast<std::size_t>(v)]);
    }
  place_copies(mesh, set, copy);
  const auto renumber = [&](Index& v) {
    const auto it = copy.find(v);
    if (it != copy.end()) v = it->second;
  };
  for (const Index h : set)
    for (Index& v : mesh.cells[static_cast<std::size_t>(h)]) renumber(v);
  for (const Index q : quads)
    for (Index& v : mesh.boundary_faces[static_cast<std::size_t>(q)]) renumber(v);
  const Index first_new = mesh.num_cells();
  for (const Face& f : faces) {
    std::array<Index, 8> hex{};
    for (std::size_t c = 0; c < 4; ++c) {
      hex[c] = copy.at(f.nodes[c]);
      hex[c + 4] = f.nodes[c];
    }
    mesh.cells.push_back(hex);
    mesh.cell_region.push_back(mesh.cell_region[static_cast<std::size_t>(f.hex)]);
  }
  // The new hexes' faces on no other hex: the strips' quads on the boundary.
  std::map<QuadKey, int> all;
  for (Index h = 0; h < mesh.num_cells(); ++h)
    for (const auto& face : kHexFaces) ++all[hex_face_key(mesh, h, face)];
  for (Index h = first_new; h < mesh.num_cells(); ++h)
    for (const auto& face : kHexFaces) {
      if (all[hex_face_key(mesh, h, face)] != 1) continue;
      const auto& cell = mesh.cells[static_cast<std::size_t>(h)];
      mesh.boundary_faces.push_back({cell[face[0]], cell[face[1]], cell[face[2]], cell[face[3]]});
      if (tagged) mesh.boundary_tag.push_back(tag);
    }
  return mesh.num_cells() - first_new;
}

}  // namespace

void pillow_patches(HexMesh& mesh, FeatureLayer& layer) {
  std::set<Edge> chain_edges;
  for (const FeatureChain& chain : layer.chains)
    for (std::size_t i = 1; i < chain.nodes.size(); ++i)
      chain_edges.insert(edge_key(chain.nodes[i - 1], chain.nodes[i]));
  if (chain_edges.empty()) return;
  const std::vector<Index> patch = patches(mesh, chain_edges);
  // Patches bordering another across a chain.
  std::map<Edge, std::vector<Index>> sides;
  for (std::size_t q = 0; q < mesh.boundary_faces.size(); ++q)
    for (std::size_t c = 0; c < 4; ++c) {
      const Edge e = edge_key(mesh.boundary_faces[q][c], mesh.boundary_faces[q][(c + 1) % 4]);
      if (chain_edges.count(e) > 0) sides[e].push_back(patch[q]);
    }
  std::set<Index> bordering;
  for (const auto& [e, p] : sides)
    if (p.size() == 2 && p[0] != p[1]) bordering.insert(p.begin(), p.end());
  const std::vector<Index> owner = hexdc_detail::quad_owners(mesh);
  const std::size_t given_quads = patch.size();
  for (const Index p : bordering) {
    std::vector<Index> set, quads;
    for (std::size_t q = 0; q < given_quads; ++q)
      if (patch[q] == p && owner[q] >= 0) {
        set.push_back(owner[q]);
        quads.push_back(static_cast<Index>(q));
      }
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
    const Index tag = mesh.boundary_tag.empty() ? 0 : mesh.boundary_tag[static_cast<std::size_t>(quads.front())];
    layer.strip_hexes += pillow_set(mesh, set, quads, tag);
    ++layer.patches_pillowed;
  }
}

}  // namespace volmesh
