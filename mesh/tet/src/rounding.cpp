#include "volmesh/tet/rounding.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <map>
#include <string>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"

namespace volmesh::tet {

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

// The double nearest to q (mpq_get_d truncates).
double nearest(const mpq_class& q) {
  const double d = q.get_d();
  double best = d;
  mpq_class best_error = abs(q - mpq_class(d));
  for (const double n : {std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY)}) {
    const mpq_class error = abs(q - mpq_class(n));
    if (error < best_error) {
      best = n;
      best_error = error;
    }
  }
  return best;
}

bool positive(const std::vector<Vec3>& p, const std::array<Index, 4>& t) {
  const auto at = [&](Index i) { return Epick::Point_3(p[i].x(), p[i].y(), p[i].z()); };
  return CGAL::orientation(at(t[0]), at(t[1]), at(t[2]), at(t[3])) == CGAL::POSITIVE;
}

}  // namespace

TetMesh round_to_doubles(const ProjectionMesh& exact,
                         const std::vector<ProjectionSurface>& surfaces, Rounding& rounding) {
  TetMesh mesh;
  mesh.points.reserve(exact.points.size());
  for (const RationalPoint& p : exact.points) {
    const Vec3 d(nearest(p.x), nearest(p.y), nearest(p.z));
    rounding.moved_points += mpq_class(d.x()) != p.x || mpq_class(d.y()) != p.y ||
                             mpq_class(d.z()) != p.z;
    mesh.points.push_back(d);
  }
  mesh.cells = exact.tets;
  mesh.cell_region = exact.tet_region;

  // The tets of each prism share its centre, their fourth corner.
  std::map<Index, std::vector<Index>> by_centre;
  for (Index t = 0; t < mesh.num_cells(); ++t)
    if (!positive(mesh.points, mesh.cells[t])) by_centre[mesh.cells[t][3]];
  for (Index t = 0; t < mesh.num_cells() && !by_centre.empty(); ++t) {
    const auto it = by_centre.find(mesh.cells[t][3]);
    if (it != by_centre.end()) it->second.push_back(t);
  }
  for (const auto& [centre, tets] : by_centre) {
    Vec3 mean = Vec3::Zero();
    Index corners = 0;
    for (const Index t : tets)
      for (int k = 0; k < 3; ++k, ++corners) mean += mesh.points[mesh.cells[t][k]];
    mean /= static_cast<double>(corners);
    mesh.points[centre] = mean;
    for (const Index t : tets)
      if (!positive(mesh.points, mesh.cells[t]))
        throw InputError("tet-projection: rounding to doubles flattens or inverts tet " +
                         std::to_string(t) + " near (" + std::to_string(mean.x()) + ", " +
                         std::to_string(mean.y()) + ", " + std::to_string(mean.z()) +
                         "), beyond repair by moving its prism's centre; nothing written");
    ++rounding.repaired_prisms;
  }

  // The checker (validity.hpp) calls a face whose area is rounding noise degenerate; a sliver
  // prism's side triangles can be, whatever its centre.
  const double zero_area = ValidityOptions{}.zero_area_tolerance;
  for (Index t = 0; t < mesh.num_cells(); ++t)
    for (const auto& face : kTetFaces) {
      const std::array<Index, 3> loop{mesh.cells[t][face[0]], mesh.cells[t][face[1]],
                                      mesh.cells[t][face[2]]};
      const Vec3 &a = mesh.points[loop[0]], &b = mesh.points[loop[1]], &c = mesh.points[loop[2]];
      if (flatness(mesh.points, loop, 0.5 * (b - a).cross(c - a).norm()) <= zero_area)
        throw InputError("tet-projection: rounded to doubles, a face of tet " + std::to_string(t) +
                         " near (" + std::to_string(a.x()) + ", " + std::to_string(a.y()) + ", " +
                         std::to_string(a.z()) + ") has no area a double can tell from zero; "
                         "nothing written");
    }

  for (const ProjectionSurface& s : surfaces) mesh.tag_names.push_back(s.name);
  for (std::size_t f = 0; f < exact.boundary_faces.size(); ++f) {
    const Index s = exact.boundary_surface[f];
    if (!surfaces[s].outermost) continue;
    mesh.boundary_faces.push_back(exact.boundary_faces[f]);
    mesh.boundary_tag.push_back(s);
  }
  return mesh;
}

}  // namespace volmesh::tet
