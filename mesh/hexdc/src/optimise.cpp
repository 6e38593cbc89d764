#include "volmesh/hexdc/optimise.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include <Eigen/Eigenvalues>

#include "active_set.hpp"
#include "feature_pins.hpp"
#include "feature_point.hpp"
#include "hex_energy.hpp"
#include "hex_mesh_geometry.hpp"
#include "lbfgs.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/quality/hex_metrics.hpp"

namespace volmesh {
namespace {

using namespace hexdc_detail;
using Eigen::VectorXd;

constexpr std::size_t kLbfgsMemory = 7;
// Armijo's sufficient decrease, and the halvings of a step before the line search gives up.
constexpr double kArmijo = 1e-4;
constexpr int kHalvings = 30;
// No node moves more than this fraction of its shortest edge (at the start) in one step.
constexpr double kMaxMove = 0.3;
// The regulariser's start: 0.2 |least determinant| when some tet is inverted (Garanzha et al.);
// the floor keeps it above round-off once every tet is positive.
constexpr double kEpsilonOfDet = 0.2;
constexpr double kMinEpsilon = 1e-9;
// Garanzha et al.'s least decrease rate σ of ε per round. Their rounds go on until the energy
// settles; here they stop at the first with every tet positive: the optimisation then raises the
// worst measures, which further rounds of the barrier would trade for less total distortion.
constexpr double kMinSigma = 0.1;
// An iteration lowering the energy by less than this relative amount ends the L-BFGS run.
constexpr double kStalled = 1e-9;
// The untangling stops, and the optimisation's line search accepts only points, with every tet
// measure above this.
constexpr double kPositive = 1e-6;
// A boundary node is a corner when its surface normals span three directions: the least
// eigenvalue of Σ n nᵀ above this fraction of (1 − cos feature angle) times the largest.
constexpr double kCornerSpan = 0.25;
// Untangling runs, the feature nodes of hexes still folded released before each after the first.
constexpr int kUntangleAttempts = 2;
// The soft minimum's sharpness grows by this factor from one round to the next.
constexpr double kSharpening = 2.0;
// A node is not taken onto the surface where that leaves an edge at it shorter than this
// fraction of its shortest edge at the start: two nodes with one closest point (beside a tip or
// a crease) would merge, which the scaled measures, ratios of lengths, do not see.
constexpr double kShortestSnapped = 0.05;
// The optimisation lets no hex edge fall below this fraction of its hex's mean edge at the start
// (or below its start, if shorter).
constexpr double kShortestEdge = 1e-3;
// An untangling round moves the nodes within this many hex rings of the hexes folded at its
// start; the rest of the mesh stays as it is.
constexpr int kUntangleRings = 3;
// An untangling attempt whose rounds neither lower the count of folded hexes nor raise the least
// determinant this many times in a row ends: the next releases their features, the last is
// refused.
constexpr int kStuckRounds = 4;
// An optimisation pass ends, and a new one is chosen, when the least term has risen by this share
// of the span that chose its nodes (kActiveSpan / β).
constexpr double kReselectShare = 0.5;
// A round ends when the soft minimum rises by less than kStallDrop (in scaled Jacobian units)
// over kStallWindow iterations.
constexpr int kStallWindow = 20;
constexpr double kStallDrop = 1e-4;
// Share of the run the untangling takes, the optimisation the rest.
constexpr double kUntangleShare = 0.5;
// A pinned node this close to its feature, relative to its shortest edge at the start, is on it.
constexpr double kOnFeature = 1e-9;

bool on_feature(const Problem& p, const FeaturePins& pins, std::size_t v) {
  const Vec3& x = p.mesh.points[v];
  return (pinned_point(pins, v, x) - x).norm() <= kOnFeature * p.reach[v];
}

// How pinned node v moves: on its feature, a corner node not at all and a chain node along its
// crease's tangent at its closest point; off it (where the projection's guard held it back), on
// the surface as a smooth node, until snap takes it onto its feature.
void hold_pinned(Problem& p, const FeaturePins& pins, std::size_t v) {
  if (!on_feature(p, pins, v)) {
    p.kind[v] = p.surface ? NodeKind::surface : NodeKind::fixed;
  } else if (pins.crease[v] == kCornerPin) {
    p.kind[v] = NodeKind::fixed;
  } else {
    p.kind[v] = NodeKind::crease;
    p.crease[v] = pinned_direction(pins, v, p.mesh.points[v]);
  }
}

// How each node may move: interior nodes freely; pinned nodes as hold_pinned says; the other
// boundary nodes, with a surface, on it (smooth) when there are pins, else on it, along the
// crease their normals find or not at all (a corner); without a surface, not at all.
void classify(Problem& p, const FeaturePins& pins, double cos_feature, OptimiseStats& stats) {
  const HexMesh& mesh = p.mesh;
  p.hexes = hexes_of_nodes(mesh);
  const std::vector<std::vector<Index>>& hexes = p.hexes;
  const std::size_t n = mesh.points.size();
  p.quads = boundary_quads_of_nodes(mesh);
  p.kind.assign(n, NodeKind::fixed);
  p.crease.assign(n, Vec3::Zero());
  p.reach.assign(n, std::numeric_limits<double>::infinity());
  p.size.assign(mesh.cells.size(), 0.0);
  for (std::size_t h = 0; h < mesh.cells.size(); ++h) {
    const auto& cell = mesh.cells[h];
    for (const auto& [a, b] : kHexEdges) {
      const auto u = static_cast<std::size_t>(cell[a]), w = static_cast<std::size_t>(cell[b]);
      const double length = (mesh.points[u] - mesh.points[w]).norm();
      p.reach[u] = std::min(p.reach[u], length);
      p.reach[w] = std::min(p.reach[w], length);
      p.size[h] += length / static_cast<double>(kHexEdges.size());
    }
  }
  // A node on a collapsed edge (two nodes the projection took onto one point) would otherwise
  // cap every step of the descent at nothing (step_cap) and probe the surface at round-off.
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    for (const Index v : mesh.cells[h]) {
      double& reach = p.reach[static_cast<std::size_t>(v)];
      reach = std::max(reach, kShortestEdge * p.size[h]);
    }
  const double corner_span = kCornerSpan * (1.0 - cos_feature);
  for (std::size_t v = 0; v < n; ++v) {
    if (hexes[v].empty()) continue;
    if (p.quads[v].empty()) {
      p.kind[v] = NodeKind::free;
      continue;
    }
    ++stats.boundary_nodes;
    if (pinned(pins, v)) {
      ++stats.pinned_nodes;
      ++(pins.crease[v] == kCornerPin ? stats.corner_nodes : stats.crease_nodes);
      hold_pinned(p, pins, v);
      continue;
    }
    if (!p.surface) continue;
    // With chains, the normals' creases would fight them (a node beside a chain found on it).
    if (!pins.crease.empty()) {
      p.kind[v] = NodeKind::surface;
      continue;
    }
    const std::vector<Vec3> normals = surface_normals_at(mesh, p.quads[v], p.surface, v, p.reach[v]);
    Vec3 sum = Vec3::Zero();
    for (const Vec3& normal : normals) sum += normal;
    const Vec3 mean = sum.normalized();
    const bool smooth = !mean.isZero() && std::all_of(normals.begin(), normals.end(), [&](const Vec3& m) {
      return m.dot(mean) >= cos_feature;
    });
    if (smooth) {
      p.kind[v] = NodeKind::surface;
      continue;
    }
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
    for (const Vec3& normal : normals) spread += normal * normal.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(spread);
    if (eigen.eigenvalues()(0) > corner_span * eigen.eigenvalues()(2)) {
      ++stats.corner_nodes;
      continue;
    }
    ++stats.crease_nodes;
    p.kind[v] = NodeKind::crease;
    p.crease[v] = eigen.eigenvectors().col(0);
  }
}

VectorXd flatten(const Active& a, const std::vector<Vec3>& points) {
  VectorXd x(static_cast<Eigen::Index>(3 * a.nodes.size()));
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    x.segment<3>(static_cast<Eigen::Index>(3 * i)) = points[static_cast<std::size_t>(a.nodes[i])];
  return x;
}

void unflatten(const Active& a, const VectorXd& x, std::vector<Vec3>& points) {
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    points[static_cast<std::size_t>(a.nodes[i])] = x.segment<3>(static_cast<Eigen::Index>(3 * i));
}

// A node's part of a step or gradient restricted to how it may move.
void restrict_moves(const Problem& p, const Active& a, VectorXd& d) {
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    const auto v = static_cast<std::size_t>(a.nodes[i]);
    auto part = d.segment<3>(static_cast<Eigen::Index>(3 * i));
    switch (p.kind[v]) {
      case NodeKind::free:
        break;
      case NodeKind::fixed:
        part.setZero();
        break;
      case NodeKind::surface: {
        const Vec3 normal = node_normal(p.mesh, p.quads[v]);
        part -= part.dot(normal) * normal;
        break;
      }
      case NodeKind::crease:
        part = part.dot(p.crease[v]) * p.crease[v];
        break;
    }
  }
}

// The least corner tet measure of node v's hexes.
double least_tet_around(const Problem& p, std::size_t v) {
  double least = std::numeric_limits<double>::infinity();
  for (const Index h : p.hexes[v]) {
    const auto q = hex_tet_qualities(hex_corners(p.mesh, h));
    least = std::min(least, *std::min_element(q.begin(), q.end()));
  }
  return least;
}

// The least of the optimised measures around node v: its hexes' tet and centre measures and its
// boundary quads' corner sines.
double least_around(const Problem& p, std::size_t v) {
  double least = least_tet_around(p, v);
  for (const Index h : p.hexes[v]) least = std::min(least, hex_centre_quality(hex_corners(p.mesh, h)));
  for (const Index q : p.quads[v]) {
    const auto sines = quad_sines(quad_corners(p.mesh, static_cast<std::size_t>(q)));
    least = std::min(least, *std::min_element(sines.begin(), sines.end()));
  }
  return least;
}

// Takes the sliding boundary nodes, which step in their tangent planes (or along their creases)
// and so leave a curved surface by the square of their steps, back onto it: each to its closest
// point, in node order, unless that makes the least measure around it (least_around) fall below
// the lesser of what it was and `floor` or an edge at it nearly collapses. A pinned node goes
// to its corner or its crease's closest point instead, under the same guard, and slides on along
// the crease's tangent there (hold_pinned). Returns how many stayed off.
Index snap(Problem& p, const FeaturePins& pins, double floor) {
  Index held = 0;
  std::vector<Vec3>& points = p.mesh.points;
  const auto slides = [&](std::size_t v) {
    return pinned(pins, v) ||
           (p.surface && (p.kind[v] == NodeKind::surface || p.kind[v] == NodeKind::crease));
  };
  std::vector<Vec3> targets(points.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), kGrain), [&](const auto& range) {
    for (std::size_t v = range.begin(); v < range.end(); ++v)
      if (pinned(pins, v))
        targets[v] = pinned_point(pins, v, points[v]);
      else if (slides(v))
        targets[v] = p.surface(points[v]);
  });
  for (std::size_t v = 0; v < points.size(); ++v) {
    if (!slides(v) || targets[v] == points[v]) continue;
    const double before = least_around(p, v), tets_before = least_tet_around(p, v);
    const Vec3 kept = points[v];
    points[v] = targets[v];
    // A reflex quad corner puts `floor` below zero; a tet may still not fold.
    if (least_around(p, v) < std::min(before, floor) ||
        least_tet_around(p, v) < std::min(tets_before, kPositive) ||
        shortest_edge(p.mesh, p.hexes[v], v) < kShortestSnapped * p.reach[v]) {
      points[v] = kept;
      ++held;
    }
    if (pinned(pins, v)) hold_pinned(p, pins, v);
  }
  return held;
}

// The pinned nodes off their corner or crease.
Index pinned_off_features(const Problem& p, const FeaturePins& pins) {
  Index off = 0;
  for (std::size_t v = 0; v < p.mesh.points.size(); ++v)
    if (pinned(pins, v) && !on_feature(p, pins, v)) ++off;
  return off;
}

// Whether hex h has a tet measure not above kPositive (a NaN one included).
bool folded(const HexMesh& mesh, Index h) {
  const auto q = hex_tet_qualities(hex_corners(mesh, h));
  return !(*std::min_element(q.begin(), q.end()) > kPositive);
}

// Makes the crease and corner nodes of every hex with a folded tet slide on the surface as the
// smooth ones do: a fold whose corners are all held on features may have no way out otherwise.
// Pinned nodes stay on their features: a fold they hold is refused. Returns how many were
// released.
Index release_folded_features(Problem& p, const FeaturePins& pins) {
  Index released = 0;
  for (Index h = 0; h < p.mesh.num_cells(); ++h) {
    if (!folded(p.mesh, h)) continue;
    for (const Index v : p.mesh.cells[static_cast<std::size_t>(h)]) {
      NodeKind& kind = p.kind[static_cast<std::size_t>(v)];
      if (p.quads[static_cast<std::size_t>(v)].empty() || !p.surface ||
          pinned(pins, static_cast<std::size_t>(v)) ||
          (kind != NodeKind::crease && kind != NodeKind::fixed))
        continue;
      kind = NodeKind::surface;
      ++released;
    }
  }
  return released;
}

// The largest step along d that moves no node by more than kMaxMove of its reach.
double step_cap(const Problem& p, const Active& a, const VectorXd& d) {
  double cap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    const double move = d.segment<3>(static_cast<Eigen::Index>(3 * i)).norm();
    if (move > 0.0) cap = std::min(cap, kMaxMove * p.reach[static_cast<std::size_t>(a.nodes[i])] / move);
  }
  return cap;
}

// Each node's part of d shortened to kMaxMove of its reach.
void clamp_moves(const Problem& p, const Active& a, VectorXd& d) {
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    auto part = d.segment<3>(static_cast<Eigen::Index>(3 * i));
    const double most = kMaxMove * p.reach[static_cast<std::size_t>(a.nodes[i])];
    const double move = part.norm();
    if (move > most) part *= most / move;
  }
}

// How a descent keeps each node's move within kMaxMove of its reach: by one step length for
// them all (step_cap), which keeps L-BFGS's direction; or by shortening each node's part of the
// direction alone (clamp_moves), so that the few nodes beside a collapsed edge or a deep fold do
// not hold every other node of a large region to their steps.
enum class StepLimit : std::uint8_t { shared, per_node };

// L-BFGS on `evaluate` (an Evaluation of mesh.points) over the active nodes from mesh.points,
// for at most `iterations` iterations or until `stop` (given the accepted point and the
// iterations done) says so; a point is accepted only when `feasible` says so. Returns the
// iterations taken and leaves mesh.points at the last accepted point.
template <class Evaluate, class Feasible, class Tick, class Stop>
int descend(const Problem& p, const Active& a, int iterations, StepLimit limit,
            const Evaluate& evaluate, const Feasible& feasible, const Tick& tick, const Stop& stop,
            Evaluation& at) {
  const bool per_node = limit == StepLimit::per_node;
  std::vector<Vec3>& points = p.mesh.points;
  Lbfgs lbfgs(kLbfgsMemory);
  VectorXd x = flatten(a, points);
  VectorXd g = at.gradient;
  restrict_moves(p, a, g);
  int done = 0;
  while (done < iterations) {
    tick(done);
    VectorXd d = lbfgs.direction(g);
    restrict_moves(p, a, d);
    if (!(g.dot(d) < 0.0)) {
      lbfgs.reset();
      d = -g;
    }
    // A steepest-descent step, without curvature to scale it, is capped for every node alike.
    const bool clamped = per_node && !lbfgs.empty();
    if (clamped) clamp_moves(p, a, d);
    if (!(g.dot(d) < 0.0)) break;  // no descent left in the allowed moves
    // Clamped, the direction is already a step no node takes too far.
    double alpha = clamped ? 1.0
                           : std::min(lbfgs.empty() ? std::numeric_limits<double>::infinity() : 1.0,
                                      step_cap(p, a, d));
    bool accepted = false;
    Evaluation trial;
    for (int k = 0; k <= kHalvings && !accepted; ++k, alpha *= 0.5) {
      unflatten(a, x + alpha * d, points);
      trial = evaluate();
      const VectorXd moved = flatten(a, points) - x;
      accepted = feasible(trial) &&
                 trial.energy <= at.energy + kArmijo * std::min(g.dot(moved), 0.0) &&
                 trial.energy < at.energy;
    }
    if (!accepted) {
      unflatten(a, x, points);
      break;
    }
    ++done;
    const VectorXd x_new = flatten(a, points);
    VectorXd g_new = trial.gradient;
    restrict_moves(p, a, g_new);
    lbfgs.push(x_new - x, g_new - g);
    const double drop = at.energy - trial.energy;
    x = x_new;
    g = std::move(g_new);
    at = std::move(trial);
    if (drop <= kStalled * std::abs(at.energy) || stop(at, done)) break;
  }
  return done;
}

double least_scaled_jacobian(const HexMesh& mesh) {
  double least = std::numeric_limits<double>::infinity();
  for (Index h = 0; h < mesh.num_cells(); ++h)
    least = std::min(least, hex_scaled_jacobian(hex_corners(mesh, h)));
  return least;
}

// Marks the corners of every folded hex; returns how many hexes.
Index mark_folded(const Problem& p, std::vector<char>& marked) {
  Index count = 0;
  for (Index h = 0; h < p.mesh.num_cells(); ++h) {
    if (!folded(p.mesh, h)) continue;
    ++count;
    for (const Index v : p.mesh.cells[static_cast<std::size_t>(h)]) marked[static_cast<std::size_t>(v)] = 1;
  }
  return count;
}

bool any_folded(const HexMesh& mesh) {
  for (Index h = 0; h < mesh.num_cells(); ++h)
    if (folded(mesh, h)) return true;
  return false;
}

// Whether untangling rounds still get anywhere: a round counts as stuck unless it starts with
// fewer folded hexes, or ends with a least determinant greater by kPositive, than every round
// before.
class UntangleProgress {
 public:
  // The rounds stuck in a row, this one included.
  int stuck(Index folded, double least) {
    const bool better = folded < fewest_ || least > best_ + kPositive;
    fewest_ = std::min(fewest_, folded);
    best_ = std::max(best_, least);
    stuck_ = better ? 0 : stuck_ + 1;
    return stuck_;
  }

 private:
  Index fewest_ = std::numeric_limits<Index>::max();
  double best_ = -std::numeric_limits<double>::infinity();
  int stuck_ = 0;
};

Index count_negative(const HexMesh& mesh) {
  Index n = 0;
  for (Index h = 0; h < mesh.num_cells(); ++h)
    for (const double q : hex_tet_qualities(hex_corners(mesh, h))) n += q > 0.0 ? 0 : 1;
  return n;
}

}  // namespace

OptimiseStats optimise_hexes(HexMesh& mesh, const SurfaceProjector& surface,
                             const OptimiseOptions& options) {
  if (options.untangle_rounds < 0 || options.untangle_iterations < 0 ||
      options.quality_iterations < 0)
    throw InputError("optimise_hexes: iteration counts must not be negative");
  if (!(options.theta >= 0.0 && options.theta < 1.0))
    throw InputError("optimise_hexes: theta must lie in [0, 1)");
  if (!(options.softmin_sharpness > 0.0))
    throw InputError("optimise_hexes: the soft minimum's sharpness must be positive");
  const double cos_feature = feature_cosine("optimise_hexes", options.feature_angle_deg);
  OptimiseStats stats;
  if (mesh.cells.empty()) return stats;
  const Clock::time_point start = Clock::now();
  Problem p{mesh, surface, {}, {}, {}, {}, {}, {}};
  const FeaturePins pins = feature_pins(mesh.points.size(), options.features, options.feature_layer);
  classify(p, pins, cos_feature, stats);
  stats.invalid_tets_before = count_negative(mesh);
  stats.min_scaled_jacobian_before = least_scaled_jacobian(mesh);
  const std::vector<Vec3> given = mesh.points;

  const Active all = everything(p);

  // 1. Untangling: Garanzha et al.'s rounds, ε following the least determinant, each over the
  // nodes near the hexes folded at its start.
  Barrier barrier{.epsilon = 0.0, .theta = options.theta};
  Evaluation at = barrier_energy(p, all, barrier);
  barrier.epsilon = std::max(kMinEpsilon, kEpsilonOfDet * std::max(-at.least, 0.0));
  at = barrier_energy(p, all, barrier);
  stats.untangle_energy_before = at.energy;
  const auto any_point = [](const Evaluation&) { return true; };
  const auto no_tick = [](int) {};
  const auto no_stop = [](const Evaluation&, int) { return false; };
  // A mesh whose tets are all positive goes straight to the optimisation, which raises its worst
  // measures: the barrier's rounds would trade them for a lower total distortion. A mesh left
  // folded has the feature nodes of its folded hexes released onto the surface, and is
  // untangled again.
  // Untangled: every det J and every tet measure above kPositive (the optimisation's start).
  const auto untangled = [&](const Evaluation& e) { return e.least > kPositive && !any_folded(mesh); };
  // Every node a round has moved.
  std::vector<char> moved(mesh.points.size(), 0);
  for (int attempt = 0; attempt < kUntangleAttempts && !untangled(at); ++attempt) {
    if (attempt > 0) stats.features_released += release_folded_features(p, pins);
    UntangleProgress progress;
    for (int round = 0; round < options.untangle_rounds; ++round) {
      report(options.progress, "untangling",
             kUntangleShare * round / std::max(options.untangle_rounds, 1));
      // Only the hexes folded now and their rings move: the rest, every tet positive, stays, so
      // a round costs what its folds cover, not the whole mesh.
      std::vector<char> near_folds(mesh.points.size(), 0);
      const Index folded = mark_folded(p, near_folds);
      const Active active = grow_active(p, std::move(near_folds), kUntangleRings);
      for (const Index v : active.nodes) moved[static_cast<std::size_t>(v)] = 1;
      at = barrier_energy(p, active, barrier);
      const double before = at.energy;
      stats.untangle_iterations +=
          descend(p, active, options.untangle_iterations, StepLimit::per_node,
                  [&] { return barrier_energy(p, active, barrier); }, any_point, no_tick, no_stop, at);
      ++stats.untangle_rounds;
      const double sigma = std::max(1.0 - at.energy / before, kMinSigma);
      const double d = at.least, root = std::hypot(d, barrier.epsilon);
      barrier.epsilon *= d >= 0.0 ? 1.0 - sigma : 1.0 - sigma * root / (std::abs(d) + root);
      // ε is never above what a fresh start would take (kEpsilonOfDet |d|): far above the least
      // determinant, the barrier no longer sees the last folds, which then open by a few per cent
      // a round.
      if (d < 0.0) barrier.epsilon = std::min(barrier.epsilon, kEpsilonOfDet * -d);
      barrier.epsilon = std::max(barrier.epsilon, kMinEpsilon);
      if (untangled(at)) break;
      // Folds that rounds on end neither reduce nor open up end the attempt: the first's wait
      // for their features' release, the last's are refused.
      if (progress.stuck(folded, d) == kStuckRounds) break;
    }
    at = barrier_energy(p, all, barrier);
    // The sliding nodes step in their tangent planes and stay off the surface until every tet is
    // positive: taken back after each round, a node moved across a thin part would go to the
    // far side's closest point and fold again what the round untangled (snap's test compares
    // the scaled measures around a node, which in a folded neighbourhood accept a move that
    // leaves them no worse however far it goes). Untangled, they go back as far as no tet folds.
    if (untangled(at)) {
      // Each region ends at the first round that opens its last fold, often barely positive and
      // far from the barrier's minimum: one more round over every node the rounds moved, no tet
      // allowed to fold, gives the optimisation a smoother start.
      const Active region = grow_active(p, moved, 0);
      const auto positive = [](const Evaluation& e) { return e.least > kPositive; };
      const std::vector<Vec3> kept = mesh.points;
      at = barrier_energy(p, region, barrier);
      stats.untangle_iterations +=
          descend(p, region, options.untangle_iterations, StepLimit::shared,
                  [&] { return barrier_energy(p, region, barrier); }, positive, no_tick, no_stop, at);
      at = barrier_energy(p, all, barrier);
      // (A tet measure, not a det J, may have fallen to the floor: then back.)
      if (!untangled(at)) {
        mesh.points = kept;
        at = barrier_energy(p, all, barrier);
      }
    }
    if (untangled(at)) {
      const std::vector<Vec3> kept = mesh.points;
      snap(p, pins, kPositive);
      at = barrier_energy(p, all, barrier);
      // snap guards each node's scaled tet measures, not the barrier's determinants (unscaled):
      // a return that leaves one at or below kPositive is undone.
      if (!untangled(at)) {
        mesh.points = kept;
        at = barrier_energy(p, all, barrier);
      }
    }
    if (!untangled(at)) {
      // The last round's ε may hide a fold the barrier has not yet seen: restart from a fresh ε.
      barrier.epsilon = std::max(kMinEpsilon, kEpsilonOfDet * std::max(-at.least, 0.0));
      at = barrier_energy(p, all, barrier);
    }
  }
  stats.untangle_energy_after = at.energy;

  // 2. The worst measure raised, no tet allowed to turn negative: rounds of a sharper soft
  // minimum each (its gap to the true minimum, log(terms) / β, halves each round), the sliding
  // nodes taken back onto the surface between them. Each round runs in passes over the nodes
  // near the worst terms (select_softmin), a new pass when the least term has risen by half the
  // span that chose them, and ends when the soft minimum stalls.
  double beta = options.softmin_sharpness;
  at = softmin_energy(p, all, beta);
  stats.min_quality_before = at.least;
  stats.quality_energy_before = at.energy;
  const int budget = std::max(options.quality_iterations * options.sharpening_rounds, 1);
  const auto tick = [&](int done) {
    report(options.progress, "optimisation",
           kUntangleShare + (1.0 - kUntangleShare) * (stats.quality_iterations + done) / budget);
  };
  for (int round = 0; round < options.sharpening_rounds && at.least > kPositive; ++round) {
    // A hex's centre or a boundary quad's corner may not fold, nor a folded one get worse.
    const double other_floor = std::min(at.least_other, kPositive);
    // Nor an edge shrink toward nothing.
    const double edge_floor = std::min(at.least_edge, kShortestEdge);
    const auto feasible = [&](const Evaluation& e) {
      return e.least > kPositive && e.least_other >= other_floor && e.least_edge >= edge_floor;
    };
    for (int left = options.quality_iterations; left > 0;) {
      double least = 0.0;
      const Active active = select_softmin(p, beta, least);
      if (active.nodes.empty()) break;
      at = softmin_energy(p, active, beta);
      const double next_pass = least + kReselectShare * kActiveSpan / beta;
      bool risen = false;
      std::vector<double> energies{at.energy};
      const auto stop = [&](const Evaluation& e, int done) {
        energies.push_back(e.energy);
        risen = std::min(e.least, e.least_other) > next_pass;
        return risen || (done >= kStallWindow &&
                         energies[static_cast<std::size_t>(done - kStallWindow)] - e.energy < kStallDrop);
      };
      const int done = descend(p, active, left, StepLimit::shared,
                               [&] { return softmin_energy(p, active, beta); }, feasible, tick,
                               stop, at);
      stats.quality_iterations += done;
      left -= done;
      if (!risen) break;
    }
    stats.held_off_surface = snap(p, pins, std::min(at.least, at.least_other));
    beta *= kSharpening;
    at = softmin_energy(p, all, beta);
  }
  stats.min_quality_after = at.least;
  stats.quality_energy_after = at.energy;
  stats.invalid_tets_after = count_negative(mesh);
  stats.min_scaled_jacobian_after = least_scaled_jacobian(mesh);
  // The soft minimum is not the scaled Jacobian alone (the inner tets, the quads): a mesh given with
  // every tet positive is given back as it was if the optimisation lowered its worst one.
  if (stats.invalid_tets_before == 0 &&
      stats.min_scaled_jacobian_after < stats.min_scaled_jacobian_before) {
    mesh.points = given;
    stats.reverted = true;
    stats.invalid_tets_after = 0;
    stats.min_scaled_jacobian_after = stats.min_scaled_jacobian_before;
  }
  stats.pinned_off_features = pinned_off_features(p, pins);
  stats.seconds = seconds_since(start);
  return stats;
}

}  // namespace volmesh
