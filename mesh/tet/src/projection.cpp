// The projection mesher's driver: the stages in order, timed, and the exact result in the
// caller's frame.
#include "volmesh/tet/projection.hpp"

#include "projection_data.hpp"
#include "volmesh/core/stopwatch.hpp"

namespace volmesh::tet {

namespace {

// Back from the projection frame: classify.cpp's shear, then its cyclic permutation.
void from_frame(RationalPoint& p, Axis axis, const std::array<mpq_class, 2>& shear) {
  p.x -= shear[0] * p.z;
  p.y -= shear[1] * p.z;
  switch (axis) {
    case Axis::x: p = {p.z, p.x, p.y}; break;
    case Axis::y: p = {p.y, p.z, p.x}; break;
    case Axis::z: break;
  }
}

mpq_class enclosed_volume(const std::vector<ProjectionSurface>& surfaces) {
  mpq_class six_volume = 0;
  for (const ProjectionSurface& s : surfaces) {
    if (!s.outermost) continue;
    for (const auto& t : s.surface.triangles) {
      const Vec3& a = s.surface.points[t[0]];
      const Vec3& b = s.surface.points[t[1]];
      const Vec3& c = s.surface.points[t[2]];
      const mpq_class ax(a.x()), ay(a.y()), az(a.z());
      const mpq_class ux = mpq_class(b.x()) - ax, uy = mpq_class(b.y()) - ay,
                      uz = mpq_class(b.z()) - az;
      const mpq_class vx = mpq_class(c.x()) - ax, vy = mpq_class(c.y()) - ay,
                      vz = mpq_class(c.z()) - az;
      six_volume += ax * (uy * vz - uz * vy) + ay * (uz * vx - ux * vz) + az * (ux * vy - uy * vx);
    }
  }
  return six_volume / 6;
}

}  // namespace

const char* axis_name(Axis axis) {
  switch (axis) {
    case Axis::x: return "x";
    case Axis::y: return "y";
    case Axis::z: break;
  }
  return "z";
}

std::string direction_name(Axis axis, int tilt) {
  std::string name = axis_name(axis);
  if (tilt == 0) return name;
  const auto shear = detail::shear_of(tilt);
  return name + " tilted by (" + shear[0].get_str() + ", " + shear[1].get_str() + ")";
}

ProjectionMesh tetrahedralize_by_projection(const std::vector<ProjectionSurface>& surfaces,
                                            const ProjectionOptions& options,
                                            const Progress& progress) {
  ProjectionMesh mesh;
  ProjectionStats& stats = mesh.stats;
  detail::State state;
  auto clock = Clock::now();
  const auto stage = [&](const char* name, double fraction) {
    stats.seconds.emplace_back(name, seconds_since(clock));
    clock = Clock::now();
    report(progress, name, fraction);
  };
  report(progress, "classify", 0.0);
  stats.axis = options.auto_axis ? detail::choose_axis(surfaces) : options.axis;
  stats.tilt = options.tilt;
  detail::classify(surfaces, stats.axis, stats.tilt, state.input);
  stage("classify", 0.05);
  detail::project(state);
  stage("project", 0.3);
  detail::build_prisms(state);
  stage("prisms", 0.5);
  detail::stitch(state);
  stage("stitch", 0.8);
  const Index boundary_points = static_cast<Index>(state.points.size());
  detail::fill(state, mesh);
  stage("fill", 1.0);

  mesh.points = std::move(state.points);
  const std::array<mpq_class, 2> shear = detail::shear_of(stats.tilt);
  for (RationalPoint& p : mesh.points) from_frame(p, stats.axis, shear);

  const detail::Surfaces& in = state.input;
  stats.triangles = static_cast<Index>(in.triangles.size());
  for (const detail::Facing f : in.facing)
    ++(f == detail::Facing::top ? stats.top : f == detail::Facing::bot ? stats.bot : stats.wall);
  stats.plane_vertices = static_cast<Index>(state.vertices.size());
  stats.plane_triangles = static_cast<Index>(state.faces.size());
  stats.prisms = static_cast<Index>(state.prisms.size());
  for (std::size_t p = 0; p < state.prisms.size(); ++p) {
    const auto& bottom = state.prism_boundary[p][0].points;
    const auto& top = state.prism_boundary[p][1].points;
    stats.degenerate_prisms += bottom[0] == top[0] || bottom[1] == top[2] || bottom[2] == top[1];
  }
  stats.tets = static_cast<Index>(mesh.tets.size());
  stats.boundary_steiner = boundary_points - static_cast<Index>(in.points.size());
  stats.interior_steiner = stats.prisms;
  stats.enclosed_volume = enclosed_volume(surfaces);
  return mesh;
}

}  // namespace volmesh::tet
