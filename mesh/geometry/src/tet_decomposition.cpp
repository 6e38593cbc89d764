#include "volmesh/geometry/tet_decomposition.hpp"

#include <array>
#include <optional>

#include "volmesh/core/cell_soup.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/geometry/cell_tessellation.hpp"

namespace volmesh {

namespace {

std::string describe_cell(const PolyMesh& mesh, const CellFaces& cell_faces, Index c) {
  return "cell " + std::to_string(c) + " (region " + std::to_string(mesh.cell_region[c]) + ", " +
         std::to_string(cell_faces.of(c).size()) + " faces)";
}

// The tetrahedra of the decomposition with the triangles of the boundary faces, tagged.
class Decomposition {
 public:
  Decomposition(const PolyMesh& mesh, const std::string& source)
      : mesh_(mesh),
        source_(source),
        cell_faces_(build_cell_faces(mesh)),
        splits_(split_faces(mesh)),
        soup_(source) {
    soup_.points = mesh.points;
    soup_.tag_names = mesh.tag_names;
    face_point_.assign(mesh.num_faces(), kNoIndex);
    for (Index f = 0; f < mesh.num_faces(); ++f)
      if (splits_.fanned(mesh, f)) face_point_[f] = add_point(face_vertex_average(mesh, f));
  }

  PolyMesh build() {
    for (Index c = 0; c < mesh_.num_cells(); ++c) {
      const CellCorners corners = classify_cell(mesh_, cell_faces_, c);
      if (corners.shape == CellShape::Tetrahedron)
        keep_tetrahedron(c, corners);
      else
        split_cell(c);
    }
    PolyMesh result = cells_to_poly(std::move(soup_));
    Index boundary_faces = 0;
    for (Index f = 0; f < result.num_faces(); ++f) boundary_faces += result.is_boundary(f);
    if (boundary_faces != boundary_triangles_)
      throw InputError(source_ + ": the tetrahedra do not conform (" +
                       std::to_string(boundary_faces) + " boundary triangles instead of " +
                       std::to_string(boundary_triangles_) + ")");
    const ValidityReport report = check_validity(result);
    if (!report.valid())
      throw InputError(source_ + ": the tetrahedra are not a valid mesh (" +
                       (report.problems.empty() ? std::string("see volmesh check")
                                                : report.problems.front()) +
                       ")");
    return result;
  }

 private:
  Index add_point(const Vec3& x) {
    if (soup_.points.size() >= static_cast<std::size_t>(kMaxIndex))
      throw InputError(source_ + ": too many points for 32-bit indices in the tetrahedra");
    soup_.points.push_back(x);
    return static_cast<Index>(soup_.points.size() - 1);
  }

  void add_tetrahedron(const std::array<Index, 4>& corners, Index region) {
    soup_.add_cell(LinearCell::Tetrahedron, corners, region);
  }

  void add_boundary_triangle(Index f, const std::array<Index, 3>& triangle) {
    soup_.add_tagged_face(triangle, mesh_.face_tag[f]);
    ++boundary_triangles_;
  }

  void keep_tetrahedron(Index c, const CellCorners& corners) {
    const auto& k = corners.corners;
    add_tetrahedron({k[0], k[1], k[2], k[3]}, mesh_.cell_region[c]);
    for (Index f : cell_faces_.of(c))
      if (mesh_.is_boundary(f)) {
        const auto loop = mesh_.face(f);
        add_boundary_triangle(f, {loop[0], loop[1], loop[2]});
      }
  }

  // One tetrahedron (apex, p, q, r) per face triangle (p, q, r) seen outward from c; the
  // star centre makes each positive.
  void split_cell(Index c) {
    const auto faces = cell_faces_.of(c);
    for (Index f : faces)
      if (splits_.folded[f])
        throw InputError(source_ + ": " + describe_cell(mesh_, cell_faces_, c) + ": face " +
                         std::to_string(f) +
                         " folds over itself; the cell cannot be split into tetrahedra");
    const std::optional<Vec3> centre = star_centre(mesh_, splits_, faces, c);
    if (!centre)
      throw InputError(source_ + ": " + describe_cell(mesh_, cell_faces_, c) +
                       ": no point inside sees all its faces; it cannot be split into "
                       "tetrahedra about one centre");
    const Index apex = add_point(*centre);
    for_each_sub_tetrahedron(mesh_, splits_, faces, c, *centre, [&](const SubTetrahedron& t) {
      const auto loop = mesh_.face(t.face);
      const std::array<Index, 3> triangle{loop[t.p], loop[t.q],
                                          t.fanned ? face_point_[t.face] : loop[t.r]};
      add_tetrahedron({apex, triangle[0], triangle[1], triangle[2]}, mesh_.cell_region[c]);
      if (mesh_.is_boundary(t.face)) add_boundary_triangle(t.face, triangle);
    });
  }

  const PolyMesh& mesh_;
  const std::string& source_;
  const CellFaces cell_faces_;
  const FaceSplits splits_;
  CellSoup soup_;
  std::vector<Index> face_point_;  // the point at each fanned face's vertex average
  Index boundary_triangles_ = 0;
};

}  // namespace

PolyMesh decompose_into_tets(const PolyMesh& mesh, const std::string& source) {
  return Decomposition(mesh, source).build();
}

}  // namespace volmesh
