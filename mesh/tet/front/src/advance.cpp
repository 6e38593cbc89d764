#include "advance.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

#include "aux_grid.hpp"
#include "face_grid.hpp"
#include "predicates.hpp"
#include "size_field.hpp"
#include "volmesh/core/element_mesh.hpp"

namespace volmesh::tet::front {

namespace {

using Tri = std::array<Index, 3>;
using Tet = std::array<Index, 4>;

// The solid-angle count is taken on a sub-lattice of the auxiliary grid with about this many
// points along the ball's radius: an estimate that costs the same for any n.
constexpr double kSolidAngleSamplesPerRadius = 6.0;
// New-node heights tried: H, 0.75 H, ..., down to 0.75^kMaxShrinks H.
constexpr int kMaxShrinks = 8;
// 6√2: volume / (largest product of the three edges at a corner) times this is 1 for the
// regular tet.
const double kQualityScale = 6.0 * std::sqrt(2.0);
// No tet of lower quality is made, in any pass: four corners on one plane up to rounding
// (a rotated cube's face) are exactly positive or negative by chance, and their tet is flat.
constexpr double kMinQuality = 1e-3;
// An existing front node is taken as the fourth corner at once when its tet is at least this
// good (1 = regular); a worse one only when no new node does better. The paper takes any
// existing node first; this keeps the slivers four front nodes can make out of the mesh.
constexpr double kGoodQuality = 0.35;

// An oriented triangle with its smallest corner first: the same key for each rotation.
Tri canonical(const Tri& t) {
  const int m = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
  return {t[m], t[(m + 1) % 3], t[(m + 2) % 3]};
}

struct TriHash {
  std::size_t operator()(const Tri& t) const {
    std::size_t h = static_cast<std::size_t>(t[0]);
    h = h * 1000003U ^ static_cast<std::size_t>(t[1]);
    return h * 1000003U ^ static_cast<std::size_t>(t[2]);
  }
};

double quality(const std::array<Vec3, 4>& p, double volume) {
  double worst = 0.0;
  for (int v = 0; v < 4; ++v) {
    double product = 1.0;
    for (int w = 0; w < 4; ++w)
      if (w != v) product *= (p[w] - p[v]).norm();
    worst = std::max(worst, product);
  }
  return kQualityScale * volume / worst;
}

// The paper's four tests, or the exact ones only (positive, no front node inside, no front
// edge or face crossed).
enum class Tests { all, exact };

class Front {
 public:
  Front(std::vector<Vec3>& points, const std::vector<Tri>& faces, const FrontOptions& options,
        const SizeField& field)
      : pts_(points), field_(field), aux_ratio_(options.aux_ratio) {
    aux_ = make_aux_grid(points, faces, field, options.aux_ratio);
    stride_ = std::max(1, static_cast<int>(std::lround(kSolidAngleRadius * options.aux_ratio /
                                                       kSolidAngleSamplesPerRadius)));
    grid_ = make_face_grid(aux_.cells);
    for (const Tri& t : faces) add_face(t);
  }

  const AuxGrid& aux() const { return aux_; }
  long long live_faces() const { return live_faces_; }

  // The live faces, in order of creation.
  std::vector<Tri> remaining() const {
    std::vector<Tri> out;
    for (std::size_t f = 0; f < faces_.size(); ++f)
      if (live_[f]) out.push_back(faces_[f]);
    return out;
  }

  // The face to advance from: the front node with the least estimate, then its face with the
  // least sum over its corners; faces that failed since the last tet are passed over.
  // kNoIndex when every live face has failed.
  Index select() const {
    for (const auto& [estimate, v] : order_) {
      Index best = kNoIndex;
      double best_sum = 0.0;
      for (const Index f : node_faces_[v]) {
        if (!live_[f] || failed_[f]) continue;
        const Tri& t = faces_[f];
        const double sum = key(t[0]) + key(t[1]) + key(t[2]);
        if (best == kNoIndex || sum < best_sum) {
          best = f;
          best_sum = sum;
        }
      }
      if (best != kNoIndex) return best;
    }
    return kNoIndex;
  }

  // The best tet on face f, or false when none passes.
  bool advance(Index f, RegionFront& out) {
    const Tri t = faces_[f];
    const std::array<Vec3, 3> p{pts_[t[0]], pts_[t[1]], pts_[t[2]]};
    // The local size at the face sets the reach, Vmax and the new node's height.
    const double h = field_.at((p[0] + p[1] + p[2]) / 3.0);
    vmax_ = kMaxVolume * h * h * h;
    const double reach = kCandidateRadius * h;
    const std::vector<Index> near = nodes_near(t, reach);
    const auto [existing, existing_q] = best_existing(t, near, reach, Tests::all);
    if (existing != kNoIndex && existing_q >= kGoodQuality) {
      ++out.existing_node_tets;
      add_tet({t[0], t[1], t[2], existing}, out);
      return true;
    }
    // A new node above the face's barycentre.
    const Vec3 cross = (p[1] - p[0]).cross(p[2] - p[0]);
    const double area = 0.5 * cross.norm();
    const Vec3 normal = cross.normalized(), centre = (p[0] + p[1] + p[2]) / 3.0;
    double height = std::min(3.0 * vmax_ / area, std::sqrt(area));
    const Index id = static_cast<Index>(pts_.size());
    for (int k = 0; k <= kMaxShrinks; ++k, height *= kShrink) {
      const Vec3 q = centre + height * normal;
      if (deleted_in_ball(aux_, q, kFreeBallRadius * (h / aux_ratio_))) continue;
      if (tet_quality(t, id, q, existing_q, Tests::all) <= 0.0) continue;
      pts_.push_back(q);
      ++out.new_nodes;
      add_tet({t[0], t[1], t[2], id}, out);
      return true;
    }
    if (existing != kNoIndex) {
      ++out.existing_node_tets;
      add_tet({t[0], t[1], t[2], existing}, out);
      return true;
    }
    // Beyond the paper: before the face counts as failed, its existing candidates are tried
    // again with the exact tests only (no volume limit, no auxiliary points), so that a
    // cavity left a little too large for Vmax, or whose auxiliary points were deleted along
    // a face, still closes.
    const Index relaxed = best_existing(t, near, reach, Tests::exact).first;
    if (relaxed != kNoIndex) {
      ++out.existing_node_tets;
      ++out.relaxed_tets;
      add_tet({t[0], t[1], t[2], relaxed}, out);
      return true;
    }
    return false;
  }

  // The front nodes within `reach` of face t's box, t's corners excepted, each once, in no
  // particular order.
  std::vector<Index> nodes_near(const Tri& t, double reach) {
    Vec3 lo = pts_[t[0]].cwiseMin(pts_[t[1]]).cwiseMin(pts_[t[2]]);
    Vec3 hi = pts_[t[0]].cwiseMax(pts_[t[1]]).cwiseMax(pts_[t[2]]);
    std::vector<Index> near;
    faces_near(grid_, lo - Vec3::Constant(reach), hi + Vec3::Constant(reach), live_, nearby_);
    node_stamp_.resize(pts_.size(), 0);
    ++node_query_;
    for (const Index v : t) node_stamp_[v] = node_query_;
    for (const Index g : nearby_)
      for (const Index v : faces_[g])
        if (node_stamp_[v] != node_query_) {
          node_stamp_[v] = node_query_;
          near.push_back(v);
        }
    return near;
  }

  // The best tet joining t to a node of `near` within `reach` of its corners, and its quality
  // (kNoIndex and 0 if none passes): the best shape that passes the tests, the least index
  // among equals. The tests, the costly part, run in order of shape until one passes.
  std::pair<Index, double> best_existing(const Tri& t, const std::vector<Index>& near,
                                         double reach, Tests tests) {
    ranked_.clear();
    for (const Index d : near) {
      const Vec3& q = pts_[d];
      if ((q - pts_[t[0]]).norm() > reach || (q - pts_[t[1]]).norm() > reach ||
          (q - pts_[t[2]]).norm() > reach)
        continue;
      const double qd = shape(t, q, tests);
      if (qd > kMinQuality) ranked_.emplace_back(qd, d);
    }
    std::sort(ranked_.begin(), ranked_.end(), [](const auto& a, const auto& b) {
      return a.first > b.first || (a.first == b.first && a.second < b.second);
    });
    for (const auto& [qd, d] : ranked_)
      if (passes(t, d, pts_[d], tests)) return {d, qd};
    return {kNoIndex, 0.0};
  }

  void mark_failed(Index f) {
    failed_[f] = 1;
    ++failed_live_;
  }

  bool all_failed() const { return failed_live_ == live_faces_; }

 private:
  // The quality of tet (t, d) with d at q if it passes every test and beats `floor`, else 0.
  double tet_quality(const Tri& t, Index d, const Vec3& q, double floor, Tests tests) {
    const double qd = shape(t, q, tests);
    if (qd <= std::max(floor, kMinQuality)) return 0.0;
    return passes(t, d, q, tests) ? qd : 0.0;
  }

  // The quality of tet (t, q) if it is positive (and within Vmax for Tests::all), else 0.
  double shape(const Tri& t, const Vec3& q, Tests tests) const {
    const std::array<Vec3, 4> p{pts_[t[0]], pts_[t[1]], pts_[t[2]], q};
    if (!positive(p[0], p[1], p[2], p[3])) return 0.0;
    const double volume = (p[1] - p[0]).cross(p[2] - p[0]).dot(p[3] - p[0]) / 6.0;
    if (tests == Tests::all && volume > vmax_) return 0.0;
    return quality(p, volume);
  }

  // Whether tet (t, d) with d at q, positive, passes the tests beyond its shape: the cheapest
  // rejections first (a front face on it facing away, a deleted auxiliary point inside), then
  // the front faces at its corners, reached through the front's adjacency (where most of the
  // rejections are; the flat-gap rule too), and last the faces near its box that share no
  // corner with it.
  bool passes(const Tri& t, Index d, const Vec3& q, Tests tests) {
    const std::array<Vec3, 4> p{pts_[t[0]], pts_[t[1]], pts_[t[2]], q};
    // A front face on the tet facing out of it: the other side of it is meshed already.
    const Tet corners{t[0], t[1], t[2], d};
    for (const auto& f : kTetFaces)
      if (by_key_.count(canonical({corners[f[0]], corners[f[1]], corners[f[2]]}))) return false;
    if (tests == Tests::all && deleted_strictly_inside(aux_, p)) return false;
    const std::array<Corner, 4> tet{Corner{p[0], t[0]}, Corner{p[1], t[1]}, Corner{p[2], t[2]},
                                    Corner{q, d}};
    const auto corners_of_face = [&](Index g) {
      const Tri& u = faces_[g];
      return std::array<Corner, 3>{Corner{pts_[u[0]], u[0]}, Corner{pts_[u[1]], u[1]},
                                   Corner{pts_[u[2]], u[2]}};
    };
    const auto meets = [&](Index g) { return tet_meets_triangle(tet, corners_of_face(g)); };
    ++face_query_;
    face_stamp_.resize(faces_.size(), 0);
    for (const Index v : corners) {
      if (static_cast<std::size_t>(v) >= node_faces_.size()) continue;  // a new node
      for (const Index g : node_faces_[v]) {
        if (face_stamp_[g] == face_query_) continue;
        face_stamp_[g] = face_query_;
        if (meets(g) || leaves_flat_gap(tet, corners_of_face(g))) return false;
      }
    }
    Vec3 lo = p[0], hi = p[0];
    for (const Vec3& x : p) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    // No margin for the faces' own extent: the grid lists a face in every cell its box overlaps.
    faces_near(grid_, lo, hi, live_, nearby_);
    for (const Index g : nearby_)
      if (face_stamp_[g] != face_query_ && meets(g)) return false;
    return true;
  }

  void add_tet(const Tet& tet, RegionFront& out) {
    out.tets.push_back(tet);
    std::array<Vec3, 4> p;
    for (int i = 0; i < 4; ++i) p[i] = pts_[tet[i]];
    deleted_.clear();
    out.aux_deleted += delete_covered(aux_, p, stride_, deleted_);
    // Each face of the tet closes the front face it matches (facing into the tet), or opens
    // a new one facing out of it.
    for (const auto& f : kTetFaces) {
      const Tri face{tet[f[0]], tet[f[1]], tet[f[2]]};
      const auto it = by_key_.find(canonical({face[0], face[2], face[1]}));
      if (it != by_key_.end())
        remove_face(it->second);
      else
        add_face(face);
    }
    Vec3 lo = p[0], hi = p[0];
    for (const Vec3& x : p) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    // The largest size of a face or node near the tet: the reach of the faces and balls that
    // may meet it.
    double h = 0.0;
    for (const Vec3& x : p) h = std::max(h, field_.at(x));
    // A failed face may advance once the front near it has changed: when its box is within
    // reach of a fourth corner of it (a test on the boxes, so that the faces retried do not
    // depend on the grid's cells).
    const Vec3 candidates =
        Vec3::Constant(kCandidateRadius * field_.largest_reaching(h, kCandidateRadius));
    if (failed_live_ > 0) faces_near(grid_, lo - candidates, hi + candidates, live_, nearby_);
    else nearby_.clear();
    for (const Index g : nearby_) {
      if (!live_[g] || !failed_[g]) continue;
      const Tri& u = faces_[g];
      const Vec3 ulo = pts_[u[0]].cwiseMin(pts_[u[1]]).cwiseMin(pts_[u[2]]);
      const Vec3 uhi = pts_[u[0]].cwiseMax(pts_[u[1]]).cwiseMax(pts_[u[2]]);
      if (((ulo - candidates).array() > hi.array()).any() ||
          ((uhi + candidates).array() < lo.array()).any())
        continue;
      failed_[g] = 0;
      --failed_live_;
    }
    // The solid-angle estimates of the front nodes whose ball meets a point deleted on the
    // counting lattice, less those points.
    if (deleted_.empty()) return;
    Vec3 dlo = deleted_.front().p, dhi = dlo;
    for (const LatticePoint& x : deleted_) {
      dlo = dlo.cwiseMin(x.p);
      dhi = dhi.cwiseMax(x.p);
    }
    const Vec3 reach =
        Vec3::Constant(kSolidAngleRadius * field_.largest_reaching(h, kSolidAngleRadius));
    faces_near(grid_, dlo - reach, dhi + reach, live_, nearby_);
    stale_.clear();
    for (const Index g : nearby_) stale_.insert(stale_.end(), faces_[g].begin(), faces_[g].end());
    std::sort(stale_.begin(), stale_.end());
    stale_.erase(std::unique(stale_.begin(), stale_.end()), stale_.end());
    for (const Index v : stale_) {
      const double r2 = radius_[v] * radius_[v];
      double gone = 0.0;
      for (const LatticePoint& x : deleted_)
        if ((x.p - pts_[v]).squaredNorm() <= r2) gone += x.weight;
      if (gone == 0.0) continue;
      order_.erase({key(v), v});
      estimate_[v] -= gone;
      order_.insert({key(v), v});
    }
  }

  // A node's live auxiliary volume within √2 h(v) (in units of the finest points'), and its
  // order key: that volume over its ball's, up to a constant (the cap's ball).
  double estimate(Index v) const {
    return count_live_in_ball(aux_, pts_[v], radius_[v], stride_);
  }
  double key(Index v) const { return estimate_[v] * scale_[v]; }

  void add_face(const Tri& t) {
    const Index f = static_cast<Index>(faces_.size());
    faces_.push_back(t);
    live_.push_back(1);
    failed_.push_back(0);
    ++live_faces_;
    by_key_.emplace(canonical(t), f);
    if (pts_.size() > node_faces_.size()) {
      node_faces_.resize(pts_.size());
      node_live_.resize(pts_.size(), 0);
      estimate_.resize(pts_.size(), 0.0);
      radius_.resize(pts_.size(), 0.0);
      scale_.resize(pts_.size(), 0.0);
    }
    Vec3 lo = pts_[t[0]], hi = lo;
    for (const Index v : t) {
      lo = lo.cwiseMin(pts_[v]);
      hi = hi.cwiseMax(pts_[v]);
      node_faces_[v].push_back(f);
      if (node_live_[v]++ == 0) {
        const double hv = field_.at(pts_[v]), ratio = field_.cap() / hv;
        radius_[v] = kSolidAngleRadius * hv;
        scale_[v] = ratio * ratio * ratio;
        estimate_[v] = estimate(v);
        order_.insert({key(v), v});
      }
    }
    insert_face(grid_, f, lo, hi);
  }

  void remove_face(Index f) {
    live_[f] = 0;
    --live_faces_;
    if (failed_[f]) --failed_live_;
    by_key_.erase(canonical(faces_[f]));
    for (const Index v : faces_[f]) {
      auto& list = node_faces_[v];
      list.erase(std::find(list.begin(), list.end(), f));
      if (--node_live_[v] == 0) order_.erase({key(v), v});
    }
  }

  std::vector<Vec3>& pts_;
  const SizeField& field_;
  int aux_ratio_;
  double vmax_ = 0.0;  // Vmax at the face advance() works on
  int stride_ = 1;
  AuxGrid aux_;
  FaceGrid grid_;
  std::vector<Tri> faces_;
  std::vector<char> live_, failed_;
  long long live_faces_ = 0, failed_live_ = 0;
  std::unordered_map<Tri, Index, TriHash> by_key_;
  std::vector<std::vector<Index>> node_faces_;  // by point: its live faces
  std::vector<int> node_live_;
  std::vector<double> estimate_, radius_, scale_;  // by point: estimate(), √2 h(v), key's factor
  std::set<std::pair<double, Index>> order_;  // the front nodes by key
  // Buffers reused by the candidate tests.
  std::vector<Index> nearby_;
  std::vector<std::pair<double, Index>> ranked_;
  std::vector<Index> stale_;  // add_tet's front nodes near the new tet, sorted
  std::vector<LatticePoint> deleted_;  // add_tet's deleted points on the counting lattice
  std::vector<unsigned> node_stamp_;  // by point: the nodes_near query that last listed it
  unsigned node_query_ = 0;
  std::vector<unsigned> face_stamp_;  // by face: the passes() query that last tested it
  unsigned face_query_ = 0;
};

// Progress is reported every this many tets.
constexpr std::size_t kProgressEvery = 256;

}  // namespace

RegionFront advance_front(std::vector<Vec3>& points, const std::vector<Tri>& faces,
                          const FrontOptions& options, const SizeField& field,
                          const Progress& progress) {
  RegionFront out;
  Front front(points, faces, options, field);
  out.aux_points = front.aux().initial;
  while (front.live_faces() > 0) {
    if (options.stop_after >= 0 && static_cast<long long>(out.tets.size()) >= options.stop_after)
      break;
    const Index f = front.select();
    if (f == kNoIndex) break;  // a stall: no face can advance
    if (!front.advance(f, out)) {
      front.mark_failed(f);
      continue;
    }
    if (out.tets.size() % kProgressEvery == 0 && front.aux().initial > 0)
      report(progress, "advancing the front",
             1.0 - double(front.aux().live) / double(front.aux().initial));
  }
  out.cavity = front.remaining();
  return out;
}

}  // namespace volmesh::tet::front
