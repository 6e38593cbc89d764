#include "volmesh/surfacing/remesh.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <string>
#include <vector>

#include "volmesh/core/errors.hpp"

namespace volmesh::surfacing {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// isotropic_remeshing's bound for constrained edges it cannot split: 4/3 of the target.
constexpr double kLongestConstraintPerEdge = 4.0 / 3.0;

Mesh to_mesh(const TriSurface& s) {
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  v.reserve(s.points.size());
  for (const Vec3& p : s.points) v.push_back(m.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
  for (const auto& t : s.triangles) m.add_face(v[t[0]], v[t[1]], v[t[2]]);
  return m;
}

TriSurface to_surface(Mesh& m) {
  m.collect_garbage();
  TriSurface s;
  for (const Mesh::Vertex_index v : m.vertices()) {
    const K::Point_3& p = m.point(v);
    s.points.emplace_back(p.x(), p.y(), p.z());
  }
  for (const Mesh::Face_index f : m.faces()) {
    std::array<Index, 3> t{};
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m))
      t[k++] = static_cast<Index>(v.idx());
    s.triangles.push_back(t);
  }
  return s;
}

}  // namespace

Remeshed remesh_isotropic(const TriSurface& input, double h) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw InputError("surface remeshing: the size " + std::to_string(h) +
                     " must be positive and finite");
  const Mesh original = to_mesh(input);
  Mesh m = original;
  auto sharp = m.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(m, kSharpAngleDegrees, sharp);
  std::vector<Mesh::Edge_index> constrained;
  for (const Mesh::Edge_index e : m.edges())
    if (get(sharp, e)) constrained.push_back(e);
  Remeshed r;
  r.sharp_edges = static_cast<long long>(constrained.size());
  PMP::split_long_edges(constrained, kLongestConstraintPerEdge * h, m,
                        CGAL::parameters::edge_is_constrained_map(sharp));
  PMP::isotropic_remeshing(faces(m), h, m,
                           CGAL::parameters::number_of_iterations(kRemeshIterations)
                               .edge_is_constrained_map(sharp)
                               .protect_constraints(true));
  const double error = kHausdorffErrorPerEdge * h;
  r.hausdorff_to_input = PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(m, original, error);
  r.hausdorff_from_input = PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(original, m, error);
  r.surface = to_surface(m);
  return r;
}

}  // namespace volmesh::surfacing
