// The schedule (after Stellar): each pass smooths the points of the queued tets, then tries
// the topological changes on each queued tet, worst first; when that has not raised the
// worst tet, it inserts points at the worst tets. It ends when a pass changes nothing, after
// kMaxPasses, or at the time limit.
#include "volmesh/improve/improve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "exact.hpp"
#include "insertion.hpp"
#include "quality.hpp"
#include "smooth.hpp"
#include "tet_complex.hpp"
#include "topology.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"

namespace volmesh::improve {

namespace {

constexpr int kMaxPasses = 24;
// The queue: tets whose smallest dihedral sine is below this (30°); the better ones are left.
const double kQueueBelow = std::sin(30.0 * std::numbers::pi / 180.0);
// Points are inserted only in tets below this (20°): insertion adds tets.
const double kInsertBelow = std::sin(20.0 * std::numbers::pi / 180.0);

// A pass that raises the worst quality by less than this, and the queue's deficit by less
// than this fraction, gains nothing: the last pass.
constexpr double kPassGain = 1e-2;

class Schedule {
 public:
  Schedule(TetComplex& mesh, const ImproveOptions& options, ImproveStats& stats)
      : mesh_(mesh), options_(options), stats_(stats), start_(Clock::now()) {}

  void run() {
    double deficit = queue_deficit();
    for (int pass = 0; pass < kMaxPasses && !out_of_time(); ++pass) {
      const double worst = mesh_.worst_quality();
      smooth_queue();
      change_topology();
      if (!raises(mesh_.worst_quality(), worst)) insert_points();
      ++stats_.passes;
      report(options_.progress, "improving (pass " + std::to_string(pass + 1) + ")",
             static_cast<double>(pass + 1) / kMaxPasses);
      // A pass gains when it raises the worst tet or lifts the queue as a whole.
      const double now = queue_deficit();
      const bool gained = mesh_.worst_quality() > worst + kPassGain || now < (1.0 - kPassGain) * deficit;
      deficit = now;
      if (!gained) break;
    }
  }

 private:
  bool out_of_time() {
    if (seconds_since(start_) > options_.max_seconds) stats_.timed_out = true;
    return stats_.timed_out;
  }

  // How far the queued tets fall short of leaving it, in all.
  double queue_deficit() const {
    double sum = 0.0;
    for (Index t = 0; t < mesh_.num_slots(); ++t)
      if (mesh_.alive(t)) sum += std::max(0.0, kQueueBelow - mesh_.quality(t));
    return sum;
  }

  // The live tets below `below`, worst first (ties by slot).
  std::vector<Index> queue(double below) const {
    std::vector<Index> q;
    for (Index t = 0; t < mesh_.num_slots(); ++t)
      if (mesh_.alive(t) && mesh_.quality(t) < below) q.push_back(t);
    std::sort(q.begin(), q.end(), [&](Index a, Index b) {
      return mesh_.quality(a) != mesh_.quality(b) ? mesh_.quality(a) < mesh_.quality(b) : a < b;
    });
    return q;
  }

  bool still_queued(Index t, double below) const {
    return mesh_.alive(t) && mesh_.quality(t) < below;
  }

  // When an attempt at point or slot i last failed (kNever: not yet).
  static constexpr long long kNever = -1;
  static long long& failed_at(std::vector<long long>& failed, Index i) {
    if (static_cast<std::size_t>(i) >= failed.size()) failed.resize(i + 1, kNever);
    return failed[i];
  }

  // Whether tet t's neighbourhood changed since an attempt on it last failed.
  bool worth_trying(std::vector<long long>& failed, Index t) {
    const long long at = failed_at(failed, t);
    const Tet& corners = mesh_.tet(t);
    return at == kNever || std::any_of(corners.begin(), corners.end(),
                                       [&](Index v) { return mesh_.changed_since(v, at); });
  }

  void smooth_queue() {
    std::vector<Index> points;
    for (const Index t : queue(kQueueBelow))
      for (const Index v : mesh_.tet(t))
        if (mesh_.freedom(v) != Freedom::Pinned) points.push_back(v);
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    long long moved = 0;
    for (const Index v : points) {
      if (out_of_time()) break;
      long long& failed = failed_at(smooth_failed_, v);
      if (failed != kNever && !mesh_.changed_since(v, failed)) continue;
      if (!smooth_point(mesh_, v)) {
        failed = mesh_.now();
        continue;
      }
      ++moved;
      stats_.operations.slid += mesh_.freedom(v) == Freedom::Slides;
    }
    stats_.operations.smoothed += moved;
  }

  bool topology_at(Index t) {
    OperationCounts& ops = stats_.operations;
    const Tet corners = mesh_.tet(t);
    for (const auto& e : kTetEdges)
      if (const int ring = remove_edge(mesh_, corners[e[0]], corners[e[1]])) {
        ++(ring == 3 ? ops.flips_3_2 : ring == 4 ? ops.flips_4_4 : ops.edge_removals);
        return true;
      }
    for (int f = 0; f < 4; ++f)
      if (const int faces = remove_faces(mesh_, t, f)) {
        ++(faces == 1 ? ops.flips_2_3 : ops.face_removals);
        return true;
      }
    // The shortest edges first: a bad tet around a short edge is one a contraction removes.
    std::array<int, 6> order{0, 1, 2, 3, 4, 5};
    const auto length = [&](int e) {
      return (mesh_.point(corners[kTetEdges[e][0]]) - mesh_.point(corners[kTetEdges[e][1]]))
          .squaredNorm();
    };
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return length(x) < length(y); });
    for (const int e : order) {
      const Index a = corners[kTetEdges[e][0]], b = corners[kTetEdges[e][1]];
      if (contract_edge(mesh_, a, b) || contract_edge(mesh_, b, a)) {
        ++ops.contractions;
        return true;
      }
    }
    return false;
  }

  void change_topology() {
    for (const Index t : queue(kQueueBelow)) {
      if (out_of_time()) break;
      if (!still_queued(t, kQueueBelow) || !worth_trying(topology_failed_, t)) continue;
      if (!topology_at(t)) failed_at(topology_failed_, t) = mesh_.now();
    }
  }

  void insert_points() {
    long long inserted = 0;
    for (const Index t : queue(kInsertBelow)) {
      if (out_of_time()) break;
      if (!still_queued(t, kInsertBelow) || !worth_trying(insert_failed_, t)) continue;
      // A failed insertion leaves a point with no tet behind, which changes no stamp.
      if (insert_point(mesh_, t))
        ++inserted;
      else
        failed_at(insert_failed_, t) = mesh_.now();
    }
    stats_.operations.insertions += inserted;
  }

  TetComplex& mesh_;
  const ImproveOptions& options_;
  ImproveStats& stats_;
  Clock::time_point start_;
  std::vector<long long> smooth_failed_;  // per point
  std::vector<long long> topology_failed_, insert_failed_;  // per slot
};

}  // namespace

void require_positive_tets(const TetMesh& mesh, const std::string& source) {
  for (Index t = 0; t < mesh.num_cells(); ++t) {
    const auto& c = mesh.cells[t];
    if (!positive(mesh.points[c[0]], mesh.points[c[1]], mesh.points[c[2]], mesh.points[c[3]]))
      throw InputError(source + ": tet " + std::to_string(t) +
                       " is flat or inverted (exact orientation test)");
  }
}

ImproveStats improve_tet_mesh(TetMesh& mesh, const ImproveOptions& options) {
  const auto start = Clock::now();
  require_positive_tets(mesh, "the mesh to improve");
  ImproveStats stats;
  stats.before = summarize_quality(mesh);
  TetComplex complex(mesh, options.slides);
  Schedule(complex, options, stats).run();
  complex.write_to(mesh);
  stats.after = summarize_quality(mesh);
  stats.seconds = seconds_since(start);
  return stats;
}

}  // namespace volmesh::improve
