// Stage 2: one constrained Delaunay triangulation of the projection plane, constrained by the
// projection of every edge of every triangle; crossing projections meet at exact
// intersection points.
#include <algorithm>
#include <utility>

#include "projection_data.hpp"

namespace volmesh::tet::detail {

void project(State& state) {
  const Surfaces& in = state.input;
  std::vector<VertexHandle> handle(in.points.size());
  VertexHandle hint;
  for (std::size_t i = 0; i < in.points.size(); ++i) {
    hint = state.plane.insert(in.projected[i],
                              hint == VertexHandle() ? Plane2::Face_handle() : hint->face());
    handle[i] = hint;
  }
  std::vector<std::pair<Index, Index>> edges;
  edges.reserve(3 * in.triangles.size());
  for (const auto& t : in.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      if (handle[a] != handle[b]) edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) state.plane.insert_constraint(handle[a], handle[b]);

  Index id = 0;
  for (auto v = state.plane.finite_vertices_begin(); v != state.plane.finite_vertices_end(); ++v) {
    v->info() = id++;
    state.vertices.push_back(v);
    state.xy.push_back({Rational(CGAL::exact(v->point().x())), Rational(CGAL::exact(v->point().y()))});
  }
  state.at_vertex.assign(state.vertices.size(), {});
  for (std::size_t i = 0; i < in.points.size(); ++i)
    state.at_vertex[handle[i]->info()].push_back(static_cast<Index>(i));
  id = 0;
  for (auto f = state.plane.finite_faces_begin(); f != state.plane.finite_faces_end(); ++f) {
    f->info() = id++;
    state.faces.push_back(f);
  }
  for (auto f = state.plane.all_faces_begin(); f != state.plane.all_faces_end(); ++f)
    if (state.plane.is_infinite(f)) f->info() = kNoIndex;
}

}  // namespace volmesh::tet::detail
