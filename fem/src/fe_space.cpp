#include "fe_space.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <limits>
#include <string>

#include "volmesh/core/errors.hpp"

namespace volmesh::fem::detail {

void CellPoints::clear() {
  groups.clear();
  nodes.clear();
  weight.clear();
  x.clear();
  shape_begin.clear();
  value.clear();
  gradient.clear();
  stabilization_scale.clear();
  stabilization_rows.clear();
}

void CellPoints::begin_group(std::span<const int> local_nodes) {
  groups.push_back({static_cast<int>(nodes.size()), static_cast<int>(local_nodes.size()),
                    static_cast<int>(weight.size()), 0});
  nodes.insert(nodes.end(), local_nodes.begin(), local_nodes.end());
}

int CellPoints::add_point(double w, const Vec3& at) {
  Group& g = groups.back();
  ++g.point_count;
  weight.push_back(w);
  x.push_back(at);
  shape_begin.push_back(value.size());
  value.resize(value.size() + g.node_count, 0.0);
  gradient.resize(gradient.size() + g.node_count, Vec3::Zero());
  return static_cast<int>(weight.size()) - 1;
}

void CellPieces::clear() {
  pieces.clear();
  term_begin.assign(1, 0);
  node.clear();
  coefficient.clear();
}

void CellPieces::add_piece(std::span<const Vec3, 4> corners, const TetAffine& affine) {
  pieces.push_back({{corners[0], corners[1], corners[2], corners[3]}, affine});
}

void FacePoints::clear() {
  nodes.clear();
  weight.clear();
  x.clear();
  value.clear();
}

double* FacePoints::add_point(double w, const Vec3& at) {
  weight.push_back(w);
  x.push_back(at);
  value.resize(value.size() + nodes.size(), 0.0);
  return value.data() + value.size() - nodes.size();
}

}  // namespace volmesh::fem::detail

namespace volmesh::fem {

const char* space_name(Space space) {
  switch (space) {
    case Space::p1:
      return "p1";
    case Space::p2:
      return "p2";
    case Space::q1:
      return "q1";
    case Space::polyhedral:
      return "polyhedral";
  }
  return "unknown";
}

std::optional<Space> space_from_name(std::string_view name) {
  for (Space s : {Space::p1, Space::p2, Space::q1, Space::polyhedral})
    if (name == space_name(s)) return s;
  return std::nullopt;
}

}  // namespace volmesh::fem

namespace volmesh::fem::detail {

std::unique_ptr<FeSpace> make_space(const PolyMesh& mesh, Space space,
                                    const PointMap& to_true_boundary) {
  switch (space) {
    case Space::p1:
      return make_tet_space(mesh, false, {});
    case Space::p2:
      return make_tet_space(mesh, true, to_true_boundary);
    case Space::q1:
      return make_q1_space(mesh);
    case Space::polyhedral:
      return make_polyhedral_space(mesh);
  }
  throw std::invalid_argument("unknown finite-element space");
}

void number_used_points(const PolyMesh& mesh, const std::vector<char>& used, FeSpace& space) {
  space.point_node.assign(mesh.num_points(), kNoIndex);
  space.node_point.clear();
  for (Index p = 0; p < mesh.num_points(); ++p)
    if (used[p]) {
      space.point_node[p] = static_cast<Index>(space.node_point.size());
      space.node_point.push_back(mesh.points[p]);
    }
}

std::vector<std::array<Index, 8>> element_corners(const PolyMesh& mesh, CellShape shape,
                                                  Space space) {
  const CellFaces cell_faces = build_cell_faces(mesh);
  std::vector<std::array<Index, 8>> corners(mesh.num_cells());
  std::vector<char> wrong(mesh.num_cells(), 0);
  tbb::parallel_for(tbb::blocked_range<Index>(0, mesh.num_cells()),
                    [&](const tbb::blocked_range<Index>& r) {
                      for (Index c = r.begin(); c != r.end(); ++c) {
                        const CellCorners cc = classify_cell(mesh, cell_faces, c);
                        corners[c] = cc.corners;
                        wrong[c] = cc.shape != shape;
                      }
                    });
  const auto bad = std::find(wrong.begin(), wrong.end(), 1);
  if (bad != wrong.end()) {
    const Index c = static_cast<Index>(bad - wrong.begin());
    const char* needed = shape == CellShape::Tetrahedron ? "tetrahedron" : "hexahedron";
    throw InputError(std::string("mesh: cell ") + std::to_string(c) + " (" +
                     std::to_string(cell_faces.of(c).size()) + " faces) is not a " + needed +
                     ": the " + space_name(space) + " space needs a mesh of " + needed +
                     "s (the polyhedral space takes any cell)");
  }
  return corners;
}

Index first_cell_where(Index num_cells, const std::function<bool(Index)>& bad) {
  constexpr Index none = std::numeric_limits<Index>::max();
  const Index first = tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, num_cells), none,
      [&](const tbb::blocked_range<Index>& r, Index found) {
        for (Index c = r.begin(); c != r.end() && c < found; ++c)
          if (bad(c)) return c;
        return found;
      },
      [](Index a, Index b) { return std::min(a, b); });
  return first == none ? kNoIndex : first;
}

double largest_of(Index count, const std::function<double(Index)>& value) {
  return tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, count), 0.0,
      [&](const tbb::blocked_range<Index>& r, double largest) {
        for (Index i = r.begin(); i != r.end(); ++i) largest = std::max(largest, value(i));
        return largest;
      },
      [](double a, double b) { return std::max(a, b); });
}

}  // namespace volmesh::fem::detail
