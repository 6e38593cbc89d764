// The polyhedral space (fem.hpp): P1 on the sub-tessellation of polyhedral.hpp, face nodes
// tied to the mean of their face's vertices, one condensed node per cell at its star centre.
// A cell with no star centre (a cut cell at a junction of interfaces can be bent so that no
// point sees all its face triangles) is a lowest-order virtual element on the same face
// triangles instead, so that the space stays conforming; its cell node is idle.
// Global nodes are the mesh vertices; a cell's local nodes are its distinct vertices in
// increasing point order, then the cell node.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fe_space.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/fem/lagrange.hpp"
#include "volmesh/fem/polyhedral.hpp"
#include "volmesh/fem/quadrature.hpp"

namespace volmesh::fem::detail {
namespace {

// The degree of the error integrals' rule on each sub-tetrahedron.
constexpr int kAccurateDegree = 5;

void sorted_cell_vertices(const PolyMesh& mesh, std::span<const Index> faces,
                          std::vector<Index>& out) {
  out.clear();
  for (Index f : faces) {
    const auto loop = mesh.face(f);
    out.insert(out.end(), loop.begin(), loop.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

class PolyhedralSpace final : public FeSpace {
 public:
  explicit PolyhedralSpace(const PolyMesh& mesh)
      : mesh_(mesh), cell_faces_(build_cell_faces(mesh)), splits_(split_faces(mesh)) {
    const Index nc = mesh.num_cells();
    // Each cell's sorted distinct vertices, counted then filled (in parallel).
    vertex_offsets_.assign(nc + 1, 0);
    const auto for_cells = [nc](auto&& body) {
      tbb::parallel_for(tbb::blocked_range<Index>(0, nc), [&](const tbb::blocked_range<Index>& r) {
        std::vector<Index> scratch;
        for (Index c = r.begin(); c != r.end(); ++c) body(c, scratch);
      });
    };
    for_cells([&](Index c, std::vector<Index>& scratch) {
      sorted_cell_vertices(mesh, cell_faces_.of(c), scratch);
      vertex_offsets_[c + 1] = static_cast<Index>(scratch.size());
    });
    for (Index c = 0; c < nc; ++c) {
      if (static_cast<std::int64_t>(vertex_offsets_[c]) + vertex_offsets_[c + 1] > kMaxIndex)
        throw InputError("mesh: too many cell vertices for 32-bit indices");
      vertex_offsets_[c + 1] += vertex_offsets_[c];
    }
    vertices_.resize(vertex_offsets_[nc]);
    apex_.resize(nc);
    std::vector<char> seen(nc, 0);
    for_cells([&](Index c, std::vector<Index>& scratch) {
      sorted_cell_vertices(mesh, cell_faces_.of(c), scratch);
      std::copy(scratch.begin(), scratch.end(), vertices_.begin() + vertex_offsets_[c]);
      if (const auto apex = star_centre(mesh, splits_, cell_faces_.of(c), c)) {
        apex_[c] = *apex;
        seen[c] = 1;
      }
    });
    virtual_of_.assign(nc, kNoIndex);
    for (Index c = 0; c < nc; ++c) {
      if (seen[c]) continue;
      auto element = virtual_element(mesh, splits_, cell_faces_.of(c), c, cell_vertices(c));
      if (!element) throw_folded(c);
      virtual_of_[c] = static_cast<Index>(virtual_.size());
      virtual_.push_back(std::move(*element));
    }

    std::vector<char> used(mesh.num_points(), 0);
    for (Index v : vertices_) used[v] = 1;
    number_used_points(mesh, used, *this);
    cell_node_offsets = vertex_offsets_;
    cell_node_list.resize(vertices_.size());
    for (std::size_t i = 0; i < vertices_.size(); ++i) cell_node_list[i] = point_node[vertices_[i]];
  }

  int internal_nodes() const override { return 1; }

  // A sub-tessellated cell takes the same one-point rule for both (cell_points).
  bool load_is_stiffness(Index c) const override { return virtual_of_[c] == kNoIndex; }

  void cell_points(Index c, Rule rule, CellPoints& out) const override {
    out.clear();
    if (virtual_of_[c] != kNoIndex) return virtual_points(virtual_[virtual_of_[c]], c, rule, out);
    const auto rule_points = points_of(rule);
    for_each_piece(c, [&](const SubTetrahedron& t, const std::vector<int>& group, bool new_face) {
      // The group holds the face's vertices in loop order, then the cell node.
      const int n = static_cast<int>(group.size()) - 1;
      if (new_face) out.begin_group(group);
      const TetAffine a = tet_affine(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
      const double spread = 1.0 / n;
      for (const auto& q : rule_points) {
        const auto& l = q.barycentric;
        const Vec3 at = l[0] * t.corners[0] + l[1] * t.corners[1] + l[2] * t.corners[2] +
                        l[3] * t.corners[3];
        const int i = out.add_point(a.volume * q.weight, at);
        auto value = out.values(i);
        auto gradient = out.gradients(i);
        value[n] += l[0];
        gradient[n] += a.gradient[0];
        value[t.p] += l[1];
        gradient[t.p] += a.gradient[1];
        value[t.q] += l[2];
        gradient[t.q] += a.gradient[2];
        if (t.fanned) {
          // The face node's shape function is shared equally by the face's vertices.
          for (int k = 0; k < n; ++k) {
            value[k] += spread * l[3];
            gradient[k] += spread * a.gradient[3];
          }
        } else {
          value[t.r] += l[3];
          gradient[t.r] += a.gradient[3];
        }
      }
    });
  }

  bool cell_pieces(Index c, Rule rule, CellPieces& out) const override {
    if (virtual_of_[c] != kNoIndex) return false;
    out.clear();
    out.rule = points_of(rule);
    for_each_piece(c, [&](const SubTetrahedron& t, const std::vector<int>& group, bool) {
      const int n = static_cast<int>(group.size()) - 1;
      out.add_piece(t.corners, tet_affine(t.corners[0], t.corners[1], t.corners[2], t.corners[3]));
      for (const int corner : {n, t.p, t.q}) {
        out.add_term(group[corner], 1.0);
        out.end_corner();
      }
      if (t.fanned)
        for (int k = 0; k < n; ++k) out.add_term(group[k], 1.0 / n);
      else
        out.add_term(group[t.r], 1.0);
      out.end_corner();
    });
    return true;
  }

  void face_nodes(Index f, std::vector<Index>& out) const override {
    out.clear();
    for (Index v : mesh_.face(f)) out.push_back(point_node[v]);
  }

  void face_points(Index f, FacePoints& out) const override {
    out.clear();
    face_nodes(f, out.nodes);
    const auto loop = mesh_.face(f);
    const int n = static_cast<int>(loop.size());
    const auto rule = triangle_rule(5);
    if (n == 3) {
      const Vec3 &a = mesh_.points[loop[0]], &b = mesh_.points[loop[1]], &c = mesh_.points[loop[2]];
      const double area = 0.5 * (b - a).cross(c - a).norm();
      for (const auto& q : rule) {
        const auto& l = q.barycentric;
        double* values = out.add_point(area * q.weight, l[0] * a + l[1] * b + l[2] * c);
        std::copy(l.begin(), l.end(), values);
      }
      return;
    }
    if (!splits_.fanned(mesh_, f)) {
      for (Index i = splits_.offsets[f]; i < splits_.offsets[f + 1]; ++i) {
        const auto& tri = splits_.triangles[i];
        const Vec3 &a = mesh_.points[loop[tri[0]]], &b = mesh_.points[loop[tri[1]]],
                   &c = mesh_.points[loop[tri[2]]];
        const double area = 0.5 * (b - a).cross(c - a).norm();
        for (const auto& q : rule) {
          const auto& l = q.barycentric;
          double* values = out.add_point(area * q.weight, l[0] * a + l[1] * b + l[2] * c);
          for (int j = 0; j < 3; ++j) values[tri[j]] = l[j];
        }
      }
      return;
    }
    const Vec3 m = face_vertex_average(mesh_, f);
    for (int k = 0; k < n; ++k) {
      const Vec3 &a = mesh_.points[loop[k]], &b = mesh_.points[loop[(k + 1) % n]];
      const double area = 0.5 * (b - a).cross(m - a).norm();
      for (const auto& q : rule) {
        const auto& l = q.barycentric;
        double* values = out.add_point(area * q.weight, l[0] * a + l[1] * b + l[2] * m);
        for (int j = 0; j < n; ++j) values[j] = l[2] / n;
        values[k] += l[0];
        values[(k + 1) % n] += l[1];
      }
    }
  }

 private:
  // Loads at each sub-tetrahedron's centroid: exact for linear data, which is what the second
  // order in L2 needs of P1 (a rule exact on polynomials of degree 2k − 2, Ciarlet), at a
  // quarter of the source evaluations of the 4-point rule.
  static std::span<const TetQuadraturePoint> points_of(Rule rule) {
    return tet_rule(rule == Rule::accurate ? kAccurateDegree : 1);
  }

  // Calls fn(t, group, new_face) for every sub-tetrahedron t of the star-shaped cell c, group
  // being the local nodes of t's face (its vertices in loop order, then the cell node) and
  // new_face whether t is the first of its face.
  template <class Fn>
  void for_each_piece(Index c, Fn&& fn) const {
    const std::span<const Index> vertices = cell_vertices(c);
    const int cell_node = static_cast<int>(vertices.size());
    Index current_face = kNoIndex;
    std::vector<int> group;
    for_each_sub_tetrahedron(
        mesh_, splits_, cell_faces_.of(c), c, apex_[c], [&](const SubTetrahedron& t) {
          const bool new_face = t.face != current_face;
          if (new_face) {
            current_face = t.face;
            group.clear();
            for (Index v : mesh_.face(t.face))
              group.push_back(static_cast<int>(
                  std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin()));
            group.push_back(cell_node);
          }
          fn(t, group, new_face);
        });
  }

  // The virtual element's points: its projection Π u_h, exact for the consistency term in one
  // point at the centroid, on signed cones from the vertex average for loads and errors; the
  // stabilisation h_E Σ_l ((I − Π)u)(x_l) ((I − Π)v)(x_l) over its vertices (the "dofi-dofi"
  // choice), and the idle cell node held at 0 by a term of the same size.
  void virtual_points(const VirtualElement& e, Index c, Rule rule, CellPoints& out) const {
    const std::span<const Index> vertices = cell_vertices(c);
    const int n = static_cast<int>(vertices.size());
    std::vector<int> all(n + 1);
    for (int i = 0; i <= n; ++i) all[i] = i;
    out.begin_group(all);
    const auto add = [&](double w, const Vec3& x) {
      const int i = out.add_point(w, x);
      auto value = out.values(i);
      auto gradient = out.gradients(i);
      for (int k = 0; k < n; ++k) {
        value[k] = 1.0 / n + e.gradient[k].dot(x - e.vertex_average);
        gradient[k] = e.gradient[k];
      }
    };
    if (rule == Rule::stiffness) {
      add(e.volume, e.centroid);
      const double scale = std::cbrt(e.volume);
      for (int l = 0; l < n; ++l) {
        out.stabilization_scale.push_back(scale);
        const Vec3 offset = mesh_.points[vertices[l]] - e.vertex_average;
        for (int k = 0; k < n; ++k)
          out.stabilization_rows.push_back((k == l) - 1.0 / n - e.gradient[k].dot(offset));
        out.stabilization_rows.push_back(0.0);
      }
      out.stabilization_scale.push_back(scale);
      out.stabilization_rows.resize(out.stabilization_rows.size() + n, 0.0);
      out.stabilization_rows.push_back(1.0);
      return;
    }
    const auto rule_points = points_of(rule);
    for_each_sub_tetrahedron(
        mesh_, splits_, cell_faces_.of(c), c, e.vertex_average, [&](const SubTetrahedron& t) {
          const double volume = tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
          for (const auto& q : rule_points) {
            const auto& l = q.barycentric;
            add(volume * q.weight, l[0] * t.corners[0] + l[1] * t.corners[1] +
                                       l[2] * t.corners[2] + l[3] * t.corners[3]);
          }
        });
  }

  std::span<const Index> cell_vertices(Index c) const {
    return {vertices_.data() + vertex_offsets_[c],
            static_cast<std::size_t>(vertex_offsets_[c + 1] - vertex_offsets_[c])};
  }

  // The message for a cell neither star-shaped nor a valid virtual element: its volume as
  // its face triangles give it, and its first folded face.
  [[noreturn]] void throw_folded(Index c) const {
    const std::span<const Index> vertices = cell_vertices(c);
    Vec3 average = Vec3::Zero();
    for (Index v : vertices) average += mesh_.points[v] / static_cast<double>(vertices.size());
    double volume = 0.0;
    for_each_sub_tetrahedron(mesh_, splits_, cell_faces_.of(c), c, average, [&](const SubTetrahedron& t) {
      volume += tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
    });
    std::ostringstream message;
    message << "mesh: cell " << c << ": inverted, degenerate or folded: volume " << volume;
    for (Index f : cell_faces_.of(c))
      if (splits_.folded[f]) {
        message << ", face " << f << " folds over itself";
        break;
      }
    throw InputError(message.str());
  }

  const PolyMesh& mesh_;
  CellFaces cell_faces_;
  FaceSplits splits_;
  std::vector<Index> vertex_offsets_;
  std::vector<Index> vertices_;  // per cell, sorted distinct vertices
  std::vector<Vec3> apex_;       // per cell, its star centre: the cell node
  std::vector<Index> virtual_of_;  // per cell, into virtual_, or kNoIndex
  std::vector<VirtualElement> virtual_;
};

}  // namespace

std::unique_ptr<FeSpace> make_polyhedral_space(const PolyMesh& mesh) {
  return std::make_unique<PolyhedralSpace>(mesh);
}

}  // namespace volmesh::fem::detail
