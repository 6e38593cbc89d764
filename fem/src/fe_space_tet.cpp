// P1 and P2 on a mesh of tetrahedra. P2 numbers the vertex nodes first, then one node per
// mesh edge (core's sorted edge list) at its midpoint.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fe_space.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/topology.hpp"
#include "volmesh/fem/lagrange.hpp"
#include "volmesh/fem/quadrature.hpp"

namespace volmesh::fem::detail {
namespace {

// Volume relative to the cube of the longest edge below which a tet counts as degenerate
// (a regular tet has 0.118): where the computed volume is within rounding of zero, so its
// element matrices would be noise. Thinner valid tets are solved on: the projection mesher's
// are exact-positive and can be very flat.
constexpr double kDegenerateShape = 8.0 * std::numeric_limits<double>::epsilon();

class TetSpace final : public FeSpace {
 public:
  TetSpace(const PolyMesh& mesh, bool quadratic) : mesh_(mesh), quadratic_(quadratic) {
    const Space space = quadratic ? Space::p2 : Space::p1;
    const auto corners8 = element_corners(mesh, CellShape::Tetrahedron, space);
    corners_.resize(corners8.size());
    for (std::size_t c = 0; c < corners8.size(); ++c)
      std::copy_n(corners8[c].begin(), 4, corners_[c].begin());
    check_volumes();

    std::vector<char> used(mesh.num_points(), 0);
    for (const auto& t : corners_)
      for (Index v : t) used[v] = 1;
    number_used_points(mesh, used, *this);
    vertex_nodes_ = num_nodes();
    if (quadratic_) {
      edges_ = build_edges(mesh).edges;
      if (static_cast<std::int64_t>(vertex_nodes_) + static_cast<std::int64_t>(edges_.size()) >
          kMaxIndex)
        throw InputError("mesh: too many P2 nodes for 32-bit indices");
      for (const auto& e : edges_)
        node_point.push_back(0.5 * (mesh.points[e[0]] + mesh.points[e[1]]));
    }

    const int per_cell = quadratic_ ? 10 : 4;
    cell_node_offsets.resize(corners_.size() + 1);
    cell_node_list.resize(corners_.size() * per_cell);
    for (std::size_t c = 0; c < corners_.size(); ++c) {
      cell_node_offsets[c + 1] = static_cast<Index>((c + 1) * per_cell);
      Index* nodes = cell_node_list.data() + c * per_cell;
      const auto& t = corners_[c];
      for (int i = 0; i < 4; ++i) nodes[i] = point_node[t[i]];
      if (quadratic_)
        for (int e = 0; e < 6; ++e)
          nodes[4 + e] = edge_node(t[kTetEdges[e][0]], t[kTetEdges[e][1]]);
    }
  }

  void cell_points(Index c, Rule rule, CellPoints& out) const override {
    out.clear();
    const auto& t = corners_[c];
    const std::array<Vec3, 4> p{mesh_.points[t[0]], mesh_.points[t[1]], mesh_.points[t[2]],
                                mesh_.points[t[3]]};
    const TetAffine a = tet_affine(p[0], p[1], p[2], p[3]);
    static constexpr std::array<int, 10> kLocal{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    out.begin_group(std::span(kLocal).first(quadratic_ ? 10 : 4));
    for (const auto& q : tet_rule(degree(rule))) {
      const auto& l = q.barycentric;
      const int i =
          out.add_point(a.volume * q.weight, l[0] * p[0] + l[1] * p[1] + l[2] * p[2] + l[3] * p[3]);
      if (quadratic_) {
        p2_tet_values(l, out.values(i).first<10>());
        p2_tet_gradients(l, a.gradient, out.gradients(i).first<10>());
      } else {
        auto v = out.values(i);
        auto g = out.gradients(i);
        for (int k = 0; k < 4; ++k) {
          v[k] = l[k];
          g[k] = a.gradient[k];
        }
      }
    }
  }

  void face_nodes(Index f, std::vector<Index>& out) const override {
    const auto loop = mesh_.face(f);
    out.clear();
    for (Index v : loop) out.push_back(point_node[v]);
    if (quadratic_)
      for (const auto& e : kTriangleEdges) out.push_back(edge_node(loop[e[0]], loop[e[1]]));
  }

  void face_points(Index f, FacePoints& out) const override {
    out.clear();
    face_nodes(f, out.nodes);
    const auto loop = mesh_.face(f);
    const Vec3 &a = mesh_.points[loop[0]], &b = mesh_.points[loop[1]], &c = mesh_.points[loop[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (const auto& q : triangle_rule(5)) {
      const auto& l = q.barycentric;
      double* n = out.add_point(area * q.weight, l[0] * a + l[1] * b + l[2] * c);
      if (quadratic_)
        p2_triangle_values(l, std::span<double, 6>(n, 6));
      else
        std::copy(l.begin(), l.end(), n);
    }
  }

 private:
  int degree(Rule rule) const {
    switch (rule) {
      case Rule::stiffness:
        return quadratic_ ? 2 : 1;
      case Rule::load:
        return quadratic_ ? 5 : 2;
      case Rule::accurate:
        return 5;
    }
    return 5;
  }

  Index edge_node(Index a, Index b) const {
    const std::array<Index, 2> key{std::min(a, b), std::max(a, b)};
    return vertex_nodes_ +
           static_cast<Index>(std::lower_bound(edges_.begin(), edges_.end(), key) - edges_.begin());
  }

  double shape_measure(Index c) const {
    const auto& t = corners_[c];
    const std::array<Vec3, 4> p{mesh_.points[t[0]], mesh_.points[t[1]], mesh_.points[t[2]],
                                mesh_.points[t[3]]};
    double longest = 0.0;
    for (const auto& e : kTetEdges) longest = std::max(longest, (p[e[0]] - p[e[1]]).norm());
    const double volume = tet_affine(p[0], p[1], p[2], p[3]).volume;
    return longest > 0.0 ? volume / (longest * longest * longest) : 0.0;
  }

  void check_volumes() const {
    const Index bad = first_cell_where(static_cast<Index>(corners_.size()), [&](Index c) {
      return !(shape_measure(c) > kDegenerateShape);
    });
    if (bad == kNoIndex) return;
    const auto& t = corners_[bad];
    const double volume =
        tet_affine(mesh_.points[t[0]], mesh_.points[t[1]], mesh_.points[t[2]], mesh_.points[t[3]])
            .volume;
    std::ostringstream message;
    message << "mesh: cell " << bad << ": " << (volume < 0.0 ? "inverted" : "degenerate")
            << " tetrahedron (volume " << volume << ")";
    throw InputError(message.str());
  }

  const PolyMesh& mesh_;
  bool quadratic_;
  std::vector<std::array<Index, 4>> corners_;
  std::vector<std::array<Index, 2>> edges_;
  Index vertex_nodes_ = 0;
};

}  // namespace

std::unique_ptr<FeSpace> make_tet_space(const PolyMesh& mesh, bool quadratic) {
  return std::make_unique<TetSpace>(mesh, quadratic);
}

}  // namespace volmesh::fem::detail
