#include "fallback.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

#include "nesting.hpp"
#include "predicates.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/tet/projection.hpp"
#include "volmesh/tet/rounding.hpp"

namespace volmesh::tet::front {

namespace {

using Tri = std::array<Index, 3>;

// The region label of the cavity inside the projection's surfaces; kSolid marks the insides
// of holes (surfaces at odd depth), whose tets are dropped.
constexpr Index kCavity = 1, kSolid = 2;

Index find(std::vector<Index>& up, Index v) {
  while (up[v] != v) v = up[v] = up[up[v]];
  return v;
}

// The positive tet a 4-face cavity is, if it is one.
std::optional<std::array<Index, 4>> single_tet(const std::vector<Vec3>& points,
                                               const std::vector<Tri>& faces) {
  if (faces.size() != 4) return std::nullopt;
  const Tri& t = faces[0];
  Index apex = kNoIndex;
  for (const Index v : faces[1])
    if (v != t[0] && v != t[1] && v != t[2]) apex = v;
  if (apex == kNoIndex || !positive(points[t[0]], points[t[2]], points[t[1]], points[apex]))
    return std::nullopt;
  return std::array<Index, 4>{t[0], t[2], t[1], apex};
}

// Relaxation steps looking for a point that sees every face of a cavity, and how far inside
// each face's plane it is kept, relative to the cavity's size.
constexpr int kKernelSteps = 500;
constexpr std::array<double, 4> kKernelMargins{1e-2, 1e-3, 1e-5, 1e-8};

// A point strictly on the inner side of every face (outward faces), found by projecting
// onto the most violated face's plane in turn from the mean of the corners; none if the
// steps run out. Such a point sees the whole closed cavity: the fan of tets joining it to
// the faces fills it.
std::optional<Vec3> kernel_point(const std::vector<Vec3>& points, const std::vector<Tri>& faces) {
  Vec3 p = Vec3::Zero(), lo = points[faces[0][0]], hi = lo;
  for (const Tri& t : faces)
    for (const Index v : t) {
      p += points[v] / (3.0 * double(faces.size()));
      lo = lo.cwiseMin(points[v]);
      hi = hi.cwiseMax(points[v]);
    }
  const Vec3 start = p;
  for (const double relative : kKernelMargins) {
  const double margin = relative * (hi - lo).norm();
  p = start;
  for (int step = 0; step < kKernelSteps; ++step) {
    double worst = margin;
    Vec3 normal = Vec3::Zero();
    for (const Tri& t : faces) {
      const Vec3 n = (points[t[2]] - points[t[0]]).cross(points[t[1]] - points[t[0]]).normalized();
      const double d = n.dot(p - points[t[0]]);
      if (d < worst) {
        worst = d;
        normal = n;
      }
    }
    if (worst >= margin) {
      if (std::all_of(faces.begin(), faces.end(), [&](const Tri& t) {
            return positive(points[t[0]], points[t[2]], points[t[1]], p);
          }))
        return p;
      break;
    }
    p += (margin - worst) * normal;
  }
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::array<Index, 4>> close_cavity(std::vector<Vec3>& points,
                                               const std::vector<Tri>& faces) {
  // Components by shared corners, each an outward surface (the faces reversed).
  std::vector<Index> up(points.size());
  std::iota(up.begin(), up.end(), 0);
  for (const Tri& t : faces) {
    up[find(up, t[1])] = find(up, t[0]);
    up[find(up, t[2])] = find(up, t[0]);
  }
  std::map<Index, std::vector<Tri>> by_root;
  for (const Tri& t : faces) by_root[find(up, t[0])].push_back({t[0], t[2], t[1]});
  std::vector<std::vector<Tri>> components;
  for (auto& [root, tris] : by_root) components.push_back(std::move(tris));
  // Separate cavities, each a tet or seen whole from one point (a fan of tets).
  std::vector<std::array<Index, 4>> tets;
  const std::size_t first_new = points.size();
  std::size_t closed = 0;
  for (const auto& c : components) {
    const bool nested = components.size() > 1 &&
                        std::any_of(components.begin(), components.end(), [&](const auto& d) {
                          return &d != &c && std::abs(winding_number(points, d, points[c[0][0]])) > 0.5;
                        });
    if (nested) break;
    if (const auto tet = single_tet(points, c)) {
      tets.push_back(*tet);
      ++closed;
      continue;
    }
    const auto centre = kernel_point(points, c);
    if (!centre) break;
    const Index apex = static_cast<Index>(points.size());
    points.push_back(*centre);
    for (const Tri& t : c) tets.push_back({t[0], t[2], t[1], apex});
    ++closed;
  }
  if (closed == components.size()) return tets;
  points.resize(first_new);
  const std::vector<Index> parent = parents(points, components);
  std::vector<ProjectionSurface> surfaces;
  std::vector<Index> global;  // projection input point -> mesh point
  for (std::size_t c = 0; c < components.size(); ++c) {
    int depth = 0;
    for (Index p = parent[c]; p != kNoIndex; p = parent[p]) ++depth;
    ProjectionSurface s;
    s.label = depth % 2 == 0 ? kCavity : kSolid;
    s.outermost = depth == 0;
    s.name = "cavity";
    std::map<Index, Index> local;
    for (const Tri& t : components[c]) {
      Tri lt;
      for (int i = 0; i < 3; ++i) {
        const auto [it, added] = local.emplace(t[i], static_cast<Index>(local.size()));
        if (added) {
          s.surface.points.push_back(points[t[i]]);
          global.push_back(t[i]);
        }
        lt[i] = it->second;
      }
      s.surface.triangles.push_back(lt);
    }
    surfaces.push_back(std::move(s));
  }
  // Each direction in turn until one leaves the cavity's faces whole.
  std::vector<ProjectionOptions> directions;
  for (const Axis a : {Axis::z, Axis::x, Axis::y})
    for (int tilt = 0; tilt <= kTilts; ++tilt)
      directions.push_back({.auto_axis = false, .axis = a, .tilt = tilt});
  for (const ProjectionOptions& d : directions) {
    ProjectionMesh exact;
    TetMesh mesh;
    try {
      exact = tetrahedralize_by_projection(surfaces, d);
      if (exact.stats.boundary_steiner > 0) continue;
      Rounding rounding;
      mesh = round_to_doubles(exact, surfaces, rounding);
    } catch (const InputError&) {
      continue;
    }
    std::vector<Index> to_mesh(mesh.points.size(), kNoIndex);
    for (std::size_t i = 0; i < global.size(); ++i) to_mesh[i] = global[i];
    std::vector<std::array<Index, 4>> tets;
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
      if (mesh.cell_region[c] != kCavity) continue;
      std::array<Index, 4> t;
      for (int i = 0; i < 4; ++i) {
        Index& m = to_mesh[mesh.cells[c][i]];
        if (m == kNoIndex) {
          m = static_cast<Index>(points.size());
          points.push_back(mesh.points[mesh.cells[c][i]]);
        }
        t[i] = m;
      }
      tets.push_back(t);
    }
    return tets;
  }
  throw InputError("tet-front: the front stalled and no projection direction closes the " +
                   std::to_string(faces.size()) + "-face cavity without splitting its faces");
}

}  // namespace volmesh::tet::front
