#include "fallback.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "cavity_pieces.hpp"
#include "nesting.hpp"
#include "predicates.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/tet/directions.hpp"
#include "volmesh/tet/projection.hpp"
#include "volmesh/tet/rounding.hpp"

namespace volmesh::tet::front {

namespace {

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

// A projection of the cavity that rounded to doubles, with the cuts it makes in the faces.
struct Candidate {
  ProjectionMesh exact;
  TetMesh rounded;
  CavitySplit split;  // in the projection's point indices
  std::size_t loose_cut = 0;  // cut faces of no tet (boundary triangles, other cavities')
};

// The candidate's tets and split in mesh indices, its Steiner points appended to `points`.
std::pair<std::vector<Tet>, CavitySplit> to_mesh(const Candidate& c, const std::vector<Index>& global,
                                                  std::vector<Vec3>& points) {
  std::vector<Index> index(c.rounded.points.size(), kNoIndex);
  for (std::size_t i = 0; i < global.size(); ++i) index[i] = global[i];
  std::vector<Tet> tets;
  for (std::size_t t = 0; t < c.rounded.cells.size(); ++t)
    if (c.rounded.cell_region[t] == kCavity) tets.push_back(c.rounded.cells[t]);
  // Steiner points numbered in the projection's order, for determinism.
  std::vector<char> used(index.size(), 0);
  for (const Tet& t : tets)
    for (const Index v : t) used[v] = 1;
  for (std::size_t v = global.size(); v < index.size(); ++v)
    if (used[v]) {
      index[v] = static_cast<Index>(points.size());
      points.push_back(c.rounded.points[v]);
    }
  for (Tet& t : tets)
    for (Index& v : t) v = index[v];
  CavitySplit split;
  for (const auto& [e, on] : c.split.edge_points) {
    Edge g{index[e[0]], index[e[1]]};
    std::vector<Index> mapped;
    for (const Index v : on) mapped.push_back(index[v]);
    if (g[0] > g[1]) {
      std::swap(g[0], g[1]);
      std::reverse(mapped.begin(), mapped.end());
    }
    split.edge_points[g] = std::move(mapped);
  }
  const auto map3 = [&](const Tri& t) { return Tri{index[t[0]], index[t[1]], index[t[2]]}; };
  for (const auto& [key, face] : c.split.faces) {
    std::vector<Tri> pieces;
    for (const Tri& p : face.second) pieces.push_back(map3(p));
    split.faces[corners_of(map3(face.first))] = {map3(face.first), std::move(pieces)};
  }
  return {std::move(tets), std::move(split)};
}

}  // namespace

void close_cavity(TetMesh& mesh, Index label, const std::vector<Tri>& current,
                  const std::vector<Tri>& loose, FaceSplits& splits, FrontStats& stats) {
  std::vector<Tri> faces;
  for (const Tri& t : current) splits.resolve(t, faces);
  std::vector<Vec3>& points = mesh.points;
  const auto add = [&](const std::vector<Tet>& tets) {
    mesh.cells.insert(mesh.cells.end(), tets.begin(), tets.end());
    mesh.cell_region.insert(mesh.cell_region.end(), tets.size(), label);
    stats.fallback_tets += static_cast<long long>(tets.size());
  };
  ++stats.stalls;
  stats.cavity_faces += static_cast<long long>(faces.size());
  stats.largest_cavity = std::max(stats.largest_cavity, static_cast<long long>(faces.size()));
  // Components by shared corners, each an outward surface (the faces reversed).
  std::vector<Index> up(points.size());
  std::iota(up.begin(), up.end(), 0);
  for (const Tri& t : faces) {
    up[find(up, t[1])] = find(up, t[0]);
    up[find(up, t[2])] = find(up, t[0]);
  }
  std::map<Index, std::vector<Tri>> by_root;
  for (const Tri& t : faces) by_root[find(up, t[0])].push_back(reversed(t));
  std::vector<std::vector<Tri>> components;
  for (auto& [root, tris] : by_root) components.push_back(std::move(tris));
  // Separate cavities, each a tet or seen whole from one point (a fan of tets).
  std::vector<Tet> tets;
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
  if (closed == components.size()) {
    stats.steiner_points += static_cast<long long>(points.size() - first_new);
    add(tets);
    return;
  }
  points.resize(first_new);
  const std::vector<Index> parent = parents(points, components);
  std::vector<ProjectionSurface> surfaces;
  std::vector<Index> global;       // projection input point -> mesh point
  std::vector<Tri> outward;        // the components' faces in projection input points
  for (std::size_t c = 0; c < components.size(); ++c) {
    int depth = 0;
    for (Index p = parent[c]; p != kNoIndex; p = parent[p]) ++depth;
    ProjectionSurface s;
    s.label = depth % 2 == 0 ? kCavity : kSolid;
    s.outermost = depth == 0;
    s.name = "cavity";
    const Index offset = static_cast<Index>(global.size());
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
      // The projection takes each surface outward from its own inside: a hole's (odd depth)
      // faces point out of it, into the cavity, as the front's faces do.
      s.surface.triangles.push_back(depth % 2 == 0 ? lt : reversed(lt));
      outward.push_back({offset + lt[0], offset + lt[1], offset + lt[2]});
    }
    surfaces.push_back(std::move(s));
  }
  std::set<Tri> loose_corners;
  for (const Tri& t : loose) loose_corners.insert(corners_of(t));
  // The projection directions in turn (directions.hpp, from z) until one cuts no face of no
  // tet (a boundary triangle, another cavity's face); else the one that cuts the fewest such
  // faces, then the fewest faces.
  std::vector<Candidate> candidates;
  for (const ProjectionOptions& direction : projection_directions(Axis::z)) {
    Candidate c;
    try {
      c.exact = tetrahedralize_by_projection(surfaces, direction);
      Rounding rounding;
      c.rounded = round_to_doubles(c.exact, surfaces, rounding);
      c.split = pieces_of_faces(c.exact, c.rounded, kCavity, outward);
    } catch (const InputError&) {
      continue;
    }
    for (const auto& [key, face] : c.split.faces)
      c.loose_cut += loose_corners.count(corners_of(
          {global[face.first[0]], global[face.first[1]], global[face.first[2]]}));
    const bool enough = c.loose_cut == 0;
    candidates.push_back(std::move(c));
    if (enough) break;
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return std::pair{a.loose_cut, a.split.faces.size()} < std::pair{b.loose_cut, b.split.faces.size()};
  });
  std::vector<Tri> cuttable = loose;
  cuttable.insert(cuttable.end(), faces.begin(), faces.end());
  for (const Candidate& c : candidates) {
    auto [cavity_tets, split] = to_mesh(c, global, points);
    Refinement refinement;
    if (!refine_around(points, mesh.cells, mesh.cell_region, split, cuttable, splits, refinement)) {
      points.resize(first_new);
      continue;
    }
    stats.split_cavity_faces += static_cast<long long>(split.faces.size());
    stats.refined_tets += refinement.tets;
    stats.steiner_points += static_cast<long long>(points.size() - first_new);
    add(cavity_tets);
    return;
  }
  throw InputError("tet-front: the front stalled and no projection direction closes the " +
                   std::to_string(faces.size()) +
                   "-face cavity with tets that stay positive in doubles (exact orientation)");
}

}  // namespace volmesh::tet::front
