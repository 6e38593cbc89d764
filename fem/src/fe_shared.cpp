#include "fe_shared.hpp"

#include <algorithm>

namespace volmesh::fem::detail {

std::vector<Index> lowest_marked_tag(const PolyMesh& mesh, const FeSpace& space,
                                     const std::vector<char>& marked) {
  std::vector<Index> tag_of(space.num_nodes(), kNoIndex);
  std::vector<Index> nodes;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f) || !marked[mesh.face_tag[f]]) continue;
    const Index tag = mesh.face_tag[f];
    space.face_nodes(f, nodes);
    for (Index n : nodes)
      if (tag_of[n] == kNoIndex || tag < tag_of[n]) tag_of[n] = tag;
  }
  return tag_of;
}

void add_boundary_load(const PolyMesh& mesh, const FeSpace& space, int components,
                       const std::vector<char>& marked, const PointMap& to_true_boundary,
                       const BoundaryData& data, Eigen::VectorXd& rhs) {
  FacePoints points;
  std::vector<double> g(components);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f) || !marked[mesh.face_tag[f]]) continue;
    space.face_points(f, points);
    const std::size_t n = points.nodes.size();
    for (std::size_t p = 0; p < points.weight.size(); ++p) {
      data(mesh.face_tag[f], on_true_boundary(to_true_boundary, points.x[p]), g.data());
      const double* shape = points.value.data() + p * n;
      for (std::size_t a = 0; a < n; ++a)
        for (int i = 0; i < components; ++i)
          rhs[std::int64_t(points.nodes[a]) * components + i] += points.weight[p] * shape[a] * g[i];
    }
  }
}

}  // namespace volmesh::fem::detail
