// The polyhedral space (fem.hpp): P1 on the sub-tessellation of polyhedral.hpp, face nodes
// tied to the mean of their face's vertices, one condensed node per cell at its star centre.
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
    const auto bad = std::find(seen.begin(), seen.end(), 0);
    if (bad != seen.end()) throw_not_star_shaped(static_cast<Index>(bad - seen.begin()));

    std::vector<char> used(mesh.num_points(), 0);
    for (Index v : vertices_) used[v] = 1;
    number_used_points(mesh, used, *this);
    cell_node_offsets = vertex_offsets_;
    cell_node_list.resize(vertices_.size());
    for (std::size_t i = 0; i < vertices_.size(); ++i) cell_node_list[i] = point_node[vertices_[i]];
  }

  int internal_nodes() const override { return 1; }

  void cell_points(Index c, Rule rule, CellPoints& out) const override {
    out.clear();
    const std::span<const Index> vertices = cell_vertices(c);
    const int cell_node = static_cast<int>(vertices.size());
    // Loads at each sub-tetrahedron's centroid: exact for linear data, which is what the
    // second order in L2 needs of P1 (a rule exact on polynomials of degree 2k − 2, Ciarlet),
    // at a quarter of the source evaluations of the 4-point rule.
    const auto rule_points = tet_rule(rule == Rule::accurate ? 5 : 1);
    Index current_face = kNoIndex;
    // Vertices of the current face; its group holds them in loop order, then the cell node.
    int n = 0;
    std::vector<int> group;
    for_each_sub_tetrahedron(
        mesh_, splits_, cell_faces_.of(c), c, apex_[c], [&](const SubTetrahedron& t) {
          if (t.face != current_face) {
            current_face = t.face;
            const auto loop = mesh_.face(t.face);
            n = static_cast<int>(loop.size());
            group.clear();
            for (Index v : loop)
              group.push_back(static_cast<int>(
                  std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin()));
            group.push_back(cell_node);
            out.begin_group(group);
          }
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
  std::span<const Index> cell_vertices(Index c) const {
    return {vertices_.data() + vertex_offsets_[c],
            static_cast<std::size_t>(vertex_offsets_[c + 1] - vertex_offsets_[c])};
  }

  // The message for a cell without a star centre, with the worst sub-tetrahedron seen from
  // its vertex average.
  [[noreturn]] void throw_not_star_shaped(Index c) const {
    std::vector<Index> vertices;
    sorted_cell_vertices(mesh_, cell_faces_.of(c), vertices);
    Vec3 average = Vec3::Zero();
    for (Index v : vertices) average += mesh_.points[v] / static_cast<double>(vertices.size());
    double worst = 0.0;
    Index face = kNoIndex;
    for_each_sub_tetrahedron(
        mesh_, splits_, cell_faces_.of(c), c, average, [&](const SubTetrahedron& t) {
          const double v = tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
          if (face == kNoIndex || v < worst) worst = v, face = t.face;
        });
    std::ostringstream message;
    message << "mesh: cell " << c
            << ": inverted, degenerate or not star-shaped: no point inside sees all its faces";
    if (face != kNoIndex)
      message << " (from its vertex average, face " << face << " gives a sub-tetrahedron of volume "
              << worst << ")";
    throw InputError(message.str());
  }

  const PolyMesh& mesh_;
  CellFaces cell_faces_;
  FaceSplits splits_;
  std::vector<Index> vertex_offsets_;
  std::vector<Index> vertices_;  // per cell, sorted distinct vertices
  std::vector<Vec3> apex_;       // per cell, its star centre: the cell node
};

}  // namespace

std::unique_ptr<FeSpace> make_polyhedral_space(const PolyMesh& mesh) {
  return std::make_unique<PolyhedralSpace>(mesh);
}

}  // namespace volmesh::fem::detail
