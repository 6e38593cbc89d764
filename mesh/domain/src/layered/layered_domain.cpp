// Layered domains: the model's checks, regions, nearest interfaces and normals (crossings in
// layered_crossings.cpp).
#include "volmesh/domain/layered.hpp"

#include <cmath>
#include <limits>

#include "layered_model.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {

namespace layers {

namespace {

// Triangles [first, end) of a geometry, as much of one as a tree of exact segment queries
// needs.
surface::SurfaceGeometry triangles_of(const surface::SurfaceGeometry& g, Index first, Index end) {
  surface::SurfaceGeometry part;
  part.points = g.points;
  part.triangles.assign(g.triangles.begin() + first, g.triangles.begin() + end);
  part.triangle_surface.assign(g.triangle_surface.begin() + first,
                               g.triangle_surface.begin() + end);
  part.first_triangle = {0, end - first};
  return part;
}

constexpr const char* kFaceNames[] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};

void check_box(const Box3& box, const std::string& name) {
  if (!box.lo.allFinite() || !box.hi.allFinite() || !(box.lo.array() < box.hi.array()).all())
    throw InputError(name + ": box: min must be below max in x, y and z (finite)");
}

}  // namespace

Model::Model(LayeredModel in) : box(in.box), name(std::move(in.name)) {
  check_box(box, name);
  if (in.faults.size() > 4)
    throw InputError(name + ": " + std::to_string(in.faults.size()) + " faults (at most 4)");
  faults = static_cast<Index>(in.faults.size());
  if (in.blocks.size() != (std::size_t{1} << faults))
    throw InputError(name + ": " + std::to_string(in.blocks.size()) + " blocks for " +
                     std::to_string(faults) + " faults (expected 2^faults)");
  for (int k = 0; k < 6; ++k) {
    const Vec3 at = k % 2 ? box.hi : box.lo;
    sheets.emplace_back(plane_sheet(box, k / 2, at, Vec3::Unit(k / 2), kFaceNames[k]), box, name);
  }
  for (const Sheet& f : in.faults) sheets.emplace_back(f, box, name);
  for (std::size_t b = 0; b < in.blocks.size(); ++b) {
    const LayerBlock& block = in.blocks[b];
    const std::string which = in.blocks.size() > 1 ? " of block " + std::to_string(b) : "";
    if (block.labels.size() != block.horizons.size() + 1)
      throw InputError(name + ": " + std::to_string(block.labels.size()) + " labels for the " +
                       std::to_string(block.horizons.size()) + " horizons" + which +
                       " (expected one more)");
    for (Index l : block.labels)
      if (l < 1) throw InputError(name + ": label " + std::to_string(l) + which + " is not >= 1");
    const Index first = static_cast<Index>(sheets.size());
    for (const Sheet& h : block.horizons) {
      if (h.axis != 2)
        throw InputError(name + ": horizon '" + h.name + "'" + which +
                         ": must be a graph over the x-y rectangle (axis z)");
      sheets.emplace_back(h, box, name);
    }
    for (std::size_t i = 1; i < block.horizons.size(); ++i)
      check_order(sheets[first + i - 1], sheets[first + i], name);
    blocks.push_back({first, static_cast<Index>(block.horizons.size()), block.labels});
  }

  for (const GraphSheet& s : sheets) add_sheet(geometry, s);
  first_horizon_triangle = geometry.first_triangle[kFirstFault + faults];
  exact_planes =
      std::make_unique<surface::ExactTree>(triangles_of(geometry, 0, first_horizon_triangle));
  if (first_horizon_triangle < geometry.num_triangles())
    exact_horizons = std::make_unique<surface::ExactTree>(
        triangles_of(geometry, first_horizon_triangle, geometry.num_triangles()));
  nearest_built_ = std::make_unique<std::once_flag[]>(blocks.size());
  nearest_.resize(blocks.size());
}

std::vector<surface::SegmentHit> Model::hits(const Vec3& a, const Vec3& b) const {
  std::vector<surface::SegmentHit> out = exact_planes->hits(a, b);
  if (!exact_horizons) return out;
  // A short segment (a leaf's edge) finds its candidates in each horizon's buckets, most
  // horizons passing by below or above: a few comparisons instead of a tree's descent.
  constexpr std::size_t kMaxBuckets = 16;
  const std::size_t planes = out.size();
  const Vec3 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  std::vector<Index> near;
  surface::SegmentHit hit;
  for (std::size_t s = kFirstFault + faults; s < sheets.size(); ++s) {
    if (!sheets[s].triangles_near(lo, hi, kMaxBuckets, near)) {
      out.resize(planes);
      for (surface::SegmentHit h : exact_horizons->hits(a, b)) {
        h.triangle += first_horizon_triangle;
        out.push_back(h);
      }
      return out;
    }
    for (const Index k : near)
      if (surface::segment_hit(geometry, geometry.first_triangle[s] + k, a, b, hit)) out.push_back(hit);
  }
  return out;
}

const Nearest& Model::nearest(Index b) const {
  std::call_once(nearest_built_[b], [&] {
    // The box faces, the faults and the block's horizons.
    const Block& block = blocks[b];
    surface::SurfaceGeometry g;
    std::vector<Index> ids;
    for (Index s = 0; s < static_cast<Index>(sheets.size()); ++s)
      if (s < kFirstFault + faults ||
          (s >= block.first_horizon && s < block.first_horizon + block.horizons)) {
        add_sheet(g, sheets[s]);
        ids.push_back(s);
      }
    nearest_[b] = std::make_unique<Nearest>(std::move(g));
    nearest_[b]->sheet = std::move(ids);
  });
  return *nearest_[b];
}

namespace {

struct NearestSheet {
  Index sheet;
  Vec3 normal;  // out of the higher label
};

// The sheet of p's block nearest to p, and its pseudo-normal there, pointing out of the
// higher of the two labels on its sides next to p.
NearestSheet nearest_sheet(const Model& m, const Vec3& p) {
  const Model::State at(m, p.cwiseMax(m.box.lo).cwiseMin(m.box.hi));
  const Nearest& n = m.nearest(m.block(at));
  const surface::ClosestPoint c = n.tree.closest(p);
  const Index s = n.sheet[n.geometry.triangle_surface[c.triangle]];
  const Vec3 normal = n.geometry.normal(c.triangle, c.feature);
  const auto forced = [&](int side) {
    return m.region([&](Index x) { return x == s ? side : at(x); });
  };
  return {s, forced(1) > forced(-1) ? Vec3(-normal) : normal};
}

}  // namespace

}  // namespace layers

LayeredDomain::LayeredDomain(LayeredModel model)
    : model_(std::make_unique<layers::Model>(std::move(model))) {
  // The labels met along vertical lines through the box.
  const Box3& box = model_->box;
  constexpr int kLines = 32;
  constexpr double kLineMargin = 0.01;  // of the box's height, below and above it: region 0
  std::vector<Vec3> a, b;
  for (int j = 0; j < kLines; ++j)
    for (int i = 0; i < kLines; ++i) {
      const double x = box.lo.x() + (i + 0.5) / kLines * (box.hi.x() - box.lo.x());
      const double y = box.lo.y() + (j + 0.5) / kLines * (box.hi.y() - box.lo.y());
      const double margin = kLineMargin * (box.hi.z() - box.lo.z());
      a.emplace_back(x, y, box.lo.z() - margin);
      b.emplace_back(x, y, box.hi.z() + margin);
    }
  std::vector<std::vector<Crossing>> hits;
  crossings(a, b, hits);
  std::vector<Index> seen;
  for (const auto& line : hits)
    for (const Crossing& c : line)
      for (Index r : {c.before, c.after})
        if (r != 0) seen.push_back(r);
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  model_->regions = std::move(seen);
}

LayeredDomain::~LayeredDomain() = default;
LayeredDomain::LayeredDomain(LayeredDomain&&) noexcept = default;
LayeredDomain& LayeredDomain::operator=(LayeredDomain&&) noexcept = default;

Index LayeredDomain::region(const Vec3& p) const { return p.allFinite() ? model_->region(p) : 0; }

std::vector<Crossing> LayeredDomain::crossings(const Vec3& a, const Vec3& b) const {
  return layers::crossings(*model_, a, b);
}

Vec3 LayeredDomain::normal(const Vec3& p) const {
  return p.allFinite() ? layers::nearest_sheet(*model_, p).normal : Vec3::UnitZ();
}

Box3 LayeredDomain::bounds() const { return model_->box; }

std::vector<Index> LayeredDomain::regions() const { return model_->regions; }

std::string LayeredDomain::boundary_name(const Vec3& p) const {
  if (!p.allFinite()) return {};
  const Box3& box = model_->box;
  const Vec3 inside = p.cwiseMax(box.lo).cwiseMin(box.hi);
  int nearest = 0;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 6; ++k) {
    Vec3 q = inside;
    q[k / 2] = (k % 2 ? box.hi : box.lo)[k / 2];
    if (const double d = (p - q).norm(); d < nearest_distance) {
      nearest_distance = d;
      nearest = k;
    }
  }
  return layers::kFaceNames[nearest];
}

std::string LayeredDomain::surface_name(const Vec3& p) const {
  if (!p.allFinite()) return {};
  return model_->sheets[layers::nearest_sheet(*model_, p).sheet].name;
}

}  // namespace volmesh
