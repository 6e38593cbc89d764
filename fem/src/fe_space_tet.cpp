// P1 and P2 on a mesh of tetrahedra. P2 numbers the vertex nodes first, then one node per
// mesh edge (core's sorted edge list) at its midpoint — or, given the true boundary, on it for
// the edges of boundary faces (isoparametric P2, curved_tet.hpp): the tets with such a node
// use the quadratic geometry map, the others stay affine.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "curved_tet.hpp"
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

// The rule of every integral on a curved tet: its map's Jacobian is quadratic and the inverse
// rational, so no rule is exact there; the errors' degree-5 rule serves the stiffness and the
// loads too, and its points are the ones the Jacobian is checked at.
constexpr int kCurvedDegree = 5;
// Boundary faces' data (Neumann fluxes, tractions) are integrated to degree 5.
constexpr int kFaceDegree = 5;

class TetSpace final : public FeSpace {
 public:
  TetSpace(const PolyMesh& mesh, bool quadratic, const PointMap& to_true_boundary)
      : mesh_(mesh), quadratic_(quadratic) {
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
      const std::vector<Vec3> edge_points =
          boundary_edge_nodes(mesh, edges_, to_true_boundary, edge_moved_);
      node_point.insert(node_point.end(), edge_points.begin(), edge_points.end());
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
    if (quadratic_) mark_curved();
  }

  void cell_points(Index c, Rule rule, CellPoints& out) const override {
    out.clear();
    if (is_curved(c)) return curved_cell_points(c, out);
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

  bool cell_pieces(Index c, Rule rule, CellPieces& out) const override {
    if (quadratic_) return false;
    out.clear();
    out.rule = tet_rule(degree(rule));
    const auto& t = corners_[c];
    const std::array<Vec3, 4> p{mesh_.points[t[0]], mesh_.points[t[1]], mesh_.points[t[2]],
                                mesh_.points[t[3]]};
    out.add_piece(p, tet_affine(p[0], p[1], p[2], p[3]));
    for (int k = 0; k < 4; ++k) {
      out.add_term(k, 1.0);
      out.end_corner();
    }
    return true;
  }

  bool load_is_stiffness(Index c) const override { return is_curved(c); }

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
    if (quadratic_ && any_moved(std::span<const Index>(out.nodes).subspan(3)))
      return curved_face_points(out);
    const auto loop = mesh_.face(f);
    const Vec3 &a = mesh_.points[loop[0]], &b = mesh_.points[loop[1]], &c = mesh_.points[loop[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (const auto& q : triangle_rule(kFaceDegree)) {
      const auto& l = q.barycentric;
      double* n = out.add_point(area * q.weight, l[0] * a + l[1] * b + l[2] * c);
      if (quadratic_)
        p2_triangle_values(l, std::span<double, 6>(n, 6));
      else
        std::copy(l.begin(), l.end(), n);
    }
  }

 private:
  // Whether one of the edge nodes sits off its edge's midpoint.
  bool any_moved(std::span<const Index> edge_nodes) const {
    return std::any_of(edge_nodes.begin(), edge_nodes.end(),
                       [this](Index n) { return edge_moved_[n - vertex_nodes_] != 0; });
  }

  bool is_curved(Index c) const { return !curved_.empty() && curved_[c]; }

  std::array<Vec3, 10> geometry_nodes(Index c) const {
    std::array<Vec3, 10> x;
    const auto nodes = cell_nodes(c);
    for (int k = 0; k < 10; ++k) x[k] = node_point[nodes[k]];
    return x;
  }

  void curved_cell_points(Index c, CellPoints& out) const {
    static constexpr std::array<int, 10> kLocal{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    out.begin_group(kLocal);
    const std::array<Vec3, 10> x = geometry_nodes(c);
    for (const auto& q : tet_rule(kCurvedDegree)) {
      const int i = out.add_point(0.0, Vec3::Zero());
      out.weight[i] = q.weight * curved_tet_point(x, q.barycentric, out.x[i],
                                                  out.values(i).first<10>(),
                                                  out.gradients(i).first<10>());
    }
  }

  // out.nodes holds the face's 6 nodes.
  void curved_face_points(FacePoints& out) const {
    std::array<Vec3, 6> x;
    for (int k = 0; k < 6; ++k) x[k] = node_point[out.nodes[k]];
    for (const auto& q : triangle_rule(kFaceDegree)) {
      Vec3 at;
      const double area = curved_triangle_point(x, q.barycentric, at);
      double* n = out.add_point(area * q.weight, at);
      p2_triangle_values(q.barycentric, std::span<double, 6>(n, 6));
    }
  }

  // The tets with an edge node moved onto the true boundary; throws InputError naming the
  // first whose map folds (a non-positive Jacobian at a quadrature point).
  void mark_curved() {
    if (std::find(edge_moved_.begin(), edge_moved_.end(), 1) == edge_moved_.end()) return;
    curved_.assign(corners_.size(), 0);
    for (std::size_t c = 0; c < corners_.size(); ++c)
      curved_[c] = any_moved(cell_nodes(static_cast<Index>(c)).subspan(4));
    const auto min_jacobian = [&](Index c) {
      const std::array<Vec3, 10> x = geometry_nodes(c);
      std::array<double, 10> value;
      std::array<Vec3, 10> gradient;
      double least = std::numeric_limits<double>::infinity();
      for (const auto& q : tet_rule(kCurvedDegree)) {
        Vec3 at;
        least = std::min(least, curved_tet_point(x, q.barycentric, at, value, gradient));
      }
      return least;
    };
    const Index bad = first_cell_where(static_cast<Index>(corners_.size()), [&](Index c) {
      return curved_[c] && !(min_jacobian(c) > 0.0);
    });
    if (bad == kNoIndex) return;
    const auto& t = corners_[bad];
    const double straight =
        tet_affine(mesh_.points[t[0]], mesh_.points[t[1]], mesh_.points[t[2]], mesh_.points[t[3]])
            .volume;
    std::ostringstream message;
    message << "mesh: cell " << bad
            << ": the curved P2 tetrahedron (boundary edge nodes on the true boundary) folds: "
               "its Jacobian falls to "
            << min_jacobian(bad) / straight
            << " times the straight tetrahedron's at a quadrature point; the boundary edges "
               "are too long for the surface's curvature there";
    throw InputError(message.str());
  }

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
  std::vector<char> edge_moved_;  // per edge: its node is on the true boundary, off the midpoint
  std::vector<char> curved_;      // per cell, empty when no edge node moved
  Index vertex_nodes_ = 0;
};

}  // namespace

std::unique_ptr<FeSpace> make_tet_space(const PolyMesh& mesh, bool quadratic,
                                        const PointMap& to_true_boundary) {
  return std::make_unique<TetSpace>(mesh, quadratic, to_true_boundary);
}

}  // namespace volmesh::fem::detail
