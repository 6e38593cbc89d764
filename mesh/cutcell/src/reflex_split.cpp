#include "reflex_split.hpp"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>

#include "tangent_point.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh::cutcell {
namespace {

constexpr int kNegative = 0, kPositive = 1;

// Fractions of the cell's size: a point this near a plane lies on it (positions computed
// along different routes agree to rounding); two surface faces meet at a reflex edge when
// each sees the other's centre in front of it by more than kInFront.
constexpr double kOnPlane = 1e-9;
constexpr double kInFront = 1e-6;
// A split is taken only when both parts keep this fraction of the cell's leaf cube: a
// smaller part would be a tiny cell by the merging's default (merge_volume_ratio).
constexpr double kMinPartVolume = 1e-3;

struct Plane {
  Vec3 point, normal;
};

// A cell split in two, before it is committed: the faces of the part A behind the plane
// and the part B in front of it, oriented out of their part.
struct Split {
  // The points the plane puts on the cell's edges, numbered num_points + k in the loops.
  struct Cut {
    Vec3 position;
    Index a, b;  // the edge
  };
  std::vector<Cut> cuts;
  struct Face {
    Index face;  // the original face, or kNoIndex for the new one between A and B
    int part;
    std::vector<Index> loop;  // out of the part; new points as num_points + k
  };
  std::vector<Face> faces;
};

// The mesh as it is being split: the input's faces and cells, those the splits changed, and
// the new ones after them. Only the cells near reflex edges are ever looked at.
class ReflexSplitter {
 public:
  ReflexSplitter(PolyMesh& mesh, std::vector<double>& size, const CheckMeshLimits& limits)
      : mesh_(mesh), base_faces_(mesh.num_faces()), base_cells_(mesh.num_cells()), size_(size),
        limits_(limits), base_cell_faces_(build_cell_faces(mesh)), owner_(mesh.owner),
        neighbour_(mesh.neighbour), tag_(mesh.face_tag), region_(mesh.cell_region),
        centre_(mesh.num_cells()), centre_known_(mesh.num_cells(), 0) {}
  Index run();

 private:
  std::span<const Index> loop(Index f) const {
    if (f >= base_faces_) return new_loops_[f - base_faces_];
    if (const auto it = changed_loops_.find(f); it != changed_loops_.end()) return it->second;
    return mesh_.face(f);
  }
  void set_loop(Index f, std::vector<Index> l) {
    if (journal_) journal_->loops.emplace_back(f, saved(f, base_faces_, new_loops_, changed_loops_));
    if (f >= base_faces_) new_loops_[f - base_faces_] = std::move(l);
    else changed_loops_[f] = std::move(l);
  }
  std::span<const Index> faces_of(Index c) const {
    if (c >= base_cells_) return new_cell_faces_[c - base_cells_];
    if (const auto it = changed_cells_.find(c); it != changed_cells_.end()) return it->second;
    return base_cell_faces_.of(c);
  }
  std::vector<Index>& mutable_faces_of(Index c) {
    if (journal_) journal_->cell_faces.emplace_back(c, saved(c, base_cells_, new_cell_faces_, changed_cells_));
    if (c >= base_cells_) return new_cell_faces_[c - base_cells_];
    const auto [it, fresh] = changed_cells_.try_emplace(c);
    if (fresh) it->second.assign(base_cell_faces_.of(c).begin(), base_cell_faces_.of(c).end());
    return it->second;
  }
  std::vector<Index> outward(Index f, Index c) const {
    const std::span<const Index> l = loop(f);
    std::vector<Index> out(l.begin(), l.end());
    if (owner_[f] != c) std::reverse(out.begin(), out.end());
    return out;
  }
  std::vector<std::vector<Index>> outward_faces(Index c) const {
    std::vector<std::vector<Index>> out;
    for (Index f : faces_of(c)) out.push_back(outward(f, c));
    return out;
  }
  Index other(Index f, Index c) const { return owner_[f] == c ? neighbour_[f] : owner_[f]; }
  bool on_surface(Index f, Index c) const {
    const Index o = other(f, c);
    return o == kNoIndex || region_[o] != region_[c];
  }
  const Vec3& centre(Index c) {
    if (!centre_known_[c]) {
      centre_[c] = geometry(outward_faces(c)).centre;
      centre_known_[c] = 1;
    }
    return centre_[c];
  }
  CellGeometry geometry(const std::vector<std::vector<Index>>& faces) const;
  double badness(const std::vector<Index>& loop, const Vec3& inside, const Vec3* beyond) const {
    const FaceGeometry g = polygon_geometry(points_(), loop);
    return checkmesh_badness(g, points_(), loop, inside, beyond, limits_);
  }
  double worst(Index c) {
    double w = 0.0;
    for (Index f : faces_of(c)) {
      const Index o = other(f, c);
      w = std::max(w, badness(outward(f, c), centre(c), o == kNoIndex ? nullptr : &centre(o)));
    }
    return w;
  }
  const std::vector<Vec3>& points_() const { return mesh_.points; }
  std::vector<Plane> reflex_planes(Index c) const;
  std::optional<Split> split(Index c, const Plane& plane);
  double split_worst(Index c, const Split& s);
  std::optional<Split> best_split(Index c, const std::vector<Plane>& planes, double below);
  void insert_on_edge(Index c, Index a, Index b, Index m);
  void commit(Index c, const Split& s);
  PolyMesh rebuild();
  Index split_with_neighbours(Index c);

  // What a tentative chain of splits changed, to undo it: the sizes before and the entries
  // before they were changed (nullopt: a base face's or cell's own, absent from the maps).
  using Saved = std::optional<std::vector<Index>>;
  struct Journal {
    std::size_t points, cells, faces;
    std::vector<std::pair<Index, Saved>> loops, cell_faces;
    std::vector<std::array<Index, 3>> sides;  // face, owner, neighbour
  };
  static Saved saved(Index i, Index base, const std::vector<std::vector<Index>>& added,
                     const std::unordered_map<Index, std::vector<Index>>& changed) {
    if (i >= base) return added[i - base];
    if (const auto it = changed.find(i); it != changed.end()) return it->second;
    return std::nullopt;
  }
  // Puts back what saved() kept, latest change first; items made since (end on) go with them.
  static void restore(const std::vector<std::pair<Index, Saved>>& entries, Index end, Index base,
                      std::vector<std::vector<Index>>& added, std::unordered_map<Index, std::vector<Index>>& changed) {
    for (auto it = entries.rbegin(); it != entries.rend(); ++it) {
      const auto& [i, value] = *it;
      if (i >= end) continue;
      if (i >= base) added[i - base] = *value;
      else if (value) changed[i] = *value;
      else changed.erase(i);
    }
  }
  void undo(const Journal& j);

  PolyMesh& mesh_;
  const Index base_faces_, base_cells_;
  std::vector<double>& size_;
  const CheckMeshLimits limits_;
  const CellFaces base_cell_faces_;
  std::unordered_map<Index, std::vector<Index>> changed_loops_, changed_cells_;
  std::vector<std::vector<Index>> new_loops_, new_cell_faces_;
  std::vector<Index> owner_, neighbour_, tag_, region_;
  std::vector<Vec3> centre_;
  std::vector<char> centre_known_;
  Journal* journal_ = nullptr;
};

// Volume and centre as checkMesh computes them, from the faces' loops out of the cell.
CellGeometry ReflexSplitter::geometry(const std::vector<std::vector<Index>>& faces) const {
  std::vector<FaceGeometry> g;
  for (const auto& loop : faces) g.push_back(polygon_geometry(points_(), loop));
  return checkmesh_cell_geometry([&g](const auto& visit) {
    for (const FaceGeometry& fg : g) visit(fg.area_vector, fg.centre);
  });
}

// The planes of the planar surface faces of c that meet another surface face of c at a
// reflex edge (each sees the other's centre in front of it).
std::vector<Plane> ReflexSplitter::reflex_planes(Index c) const {
  std::vector<Index> surface;
  for (Index f : faces_of(c))
    if (on_surface(f, c)) surface.push_back(f);
  std::vector<FaceGeometry> g;
  std::vector<std::vector<Index>> loops;
  for (Index f : surface) {
    loops.push_back(outward(f, c));
    g.push_back(polygon_geometry(points_(), loops.back()));
  }
  const double tol = kInFront * size_[c];
  const auto planar = [&](std::size_t i) {
    const Vec3 n = g[i].area_vector.normalized();
    return std::all_of(loops[i].begin(), loops[i].end(),
                       [&](Index v) { return std::abs(n.dot(points_()[v] - g[i].centre)) <= kOnPlane * size_[c]; });
  };
  std::vector<Plane> out;
  for (std::size_t i = 0; i < surface.size(); ++i)
    for (std::size_t j = 0; j < surface.size(); ++j) {
      if (i == j) continue;
      const Vec3 ni = g[i].area_vector.normalized(), nj = g[j].area_vector.normalized();
      if (ni.dot(nj) > kSameSurfaceCosine || (g[j].centre - g[i].centre).dot(ni) <= tol || (g[i].centre - g[j].centre).dot(nj) <= tol)
        continue;
      // Sharing an edge, u -> v in i and v -> u in j.
      const std::vector<Index>& a = loops[i];
      const std::vector<Index>& b = loops[j];
      bool shared = false;
      for (std::size_t k = 0; k < a.size() && !shared; ++k)
        for (std::size_t m = 0; m < b.size() && !shared; ++m)
          shared = a[k] == b[(m + 1) % b.size()] && a[(k + 1) % a.size()] == b[m];
      if (!shared || !planar(i)) continue;
      const Plane p{g[i].centre, ni};
      if (std::none_of(out.begin(), out.end(), [&](const Plane& q) {
            return q.normal.dot(p.normal) > 1.0 - kSameDirection && std::abs(q.normal.dot(p.point - q.point)) <= tol;
          }))
        out.push_back(p);
    }
  return out;
}

// c cut by the plane: faces wholly on one side go to that part (a face in the plane to the
// part its cell lies on), faces across it are split along a chord; the face between the
// parts closes the edges of A's faces that no other face of A runs back along.
std::optional<Split> ReflexSplitter::split(Index c, const Plane& plane) {
  const double eps = kOnPlane * size_[c];
  Split s;
  std::map<std::pair<Index, Index>, Index> cut_of;  // edge -> new point (num_points + k)
  const Index base = mesh_.num_points();
  const auto side = [&](Index v) {
    const double d = plane.normal.dot(points_()[v] - plane.point);
    return d > eps ? 1 : (d < -eps ? -1 : 0);
  };
  const auto cut = [&](Index a, Index b) {
    const std::pair<Index, Index> key{std::min(a, b), std::max(a, b)};
    if (const auto it = cut_of.find(key); it != cut_of.end()) return it->second;
    const Vec3 &pa = points_()[key.first], &pb = points_()[key.second];
    const double da = plane.normal.dot(pa - plane.point), db = plane.normal.dot(pb - plane.point);
    const Index id = base + static_cast<Index>(s.cuts.size());
    s.cuts.push_back({pa + da / (da - db) * (pb - pa), key.first, key.second});
    cut_of.emplace(key, id);
    return id;
  };
  for (Index f : faces_of(c)) {
    const std::vector<Index> loop = outward(f, c);
    const std::size_t n = loop.size();
    std::vector<int> sign(n);
    bool negative = false, positive = false;
    for (std::size_t k = 0; k < n; ++k) {
      sign[k] = side(loop[k]);
      negative = negative || sign[k] < 0;
      positive = positive || sign[k] > 0;
    }
    if (!negative && !positive) {
      const Vec3 area = polygon_geometry(points_(), loop).area_vector;
      s.faces.push_back({f, area.dot(plane.normal) > 0.0 ? kNegative : kPositive, loop});
      continue;
    }
    if (!positive || !negative) {
      s.faces.push_back({f, positive ? kPositive : kNegative, loop});
      continue;
    }
    // One run of each sign around the loop, or the chord is not one segment.
    int changes = 0, last = 0;
    for (std::size_t k = 0; k < 2 * n; ++k) {
      const int x = sign[k % n];
      if (x == 0) continue;
      if (last != 0 && x != last && k >= n) ++changes;
      last = x;
    }
    if (changes != 2) return std::nullopt;
    // A side of the face lying in the plane belongs to the part its face lies beside; a
    // point in the plane belongs to a part when a point or a side next to it does.
    const Vec3 face_normal = polygon_geometry(points_(), loop).area_vector;
    std::vector<int> side_part(n, -1);  // side k -> k + 1 in the plane: its part
    for (std::size_t k = 0; k < n; ++k)
      if (sign[k] == 0 && sign[(k + 1) % n] == 0) {
        const Vec3 inward = face_normal.cross(points_()[loop[(k + 1) % n]] - points_()[loop[k]]);
        side_part[k] = inward.dot(plane.normal) < 0.0 ? kNegative : kPositive;
      }
    const auto in_part = [&](std::size_t k, int part) {
      const int want = part == kNegative ? -1 : 1;
      if (sign[k] != 0) return sign[k] == want;
      const std::size_t prev = (k + n - 1) % n, next = (k + 1) % n;
      return sign[prev] == want || sign[next] == want || side_part[prev] == part || side_part[k] == part;
    };
    std::vector<Index> a, b;
    std::size_t shared = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const Index v = loop[k], w = loop[(k + 1) % n];
      const bool in_a = in_part(k, kNegative), in_b = in_part(k, kPositive);
      if (in_a) a.push_back(v);
      if (in_b) b.push_back(v);
      shared += in_a && in_b;
      if (sign[k] * sign[(k + 1) % n] < 0) {
        const Index m = cut(v, w);
        a.push_back(m);
        b.push_back(m);
        ++shared;
      }
    }
    // The halves share the chord's two ends only.
    if (a.size() < 3 || b.size() < 3 || shared != 2) return std::nullopt;
    s.faces.push_back({f, kNegative, std::move(a)});
    s.faces.push_back({f, kPositive, std::move(b)});
  }
  // Directed edges of A's faces with no partner run back: the new face runs along them
  // the other way.
  std::map<std::pair<Index, Index>, int> edges;
  for (const Split::Face& face : s.faces) {
    if (face.part != kNegative) continue;
    for (std::size_t k = 0; k < face.loop.size(); ++k) {
      const Index u = face.loop[k], v = face.loop[(k + 1) % face.loop.size()];
      if (const auto it = edges.find({v, u}); it != edges.end()) {
        if (--it->second == 0) edges.erase(it);
      } else {
        ++edges[{u, v}];
      }
    }
  }
  if (edges.size() < 3) return std::nullopt;
  std::map<Index, Index> next;  // v -> u for each open edge u -> v
  for (const auto& [e, count] : edges) {
    if (count != 1 || !next.emplace(e.second, e.first).second) return std::nullopt;
  }
  std::vector<Index> section{next.begin()->first};
  while (section.size() <= next.size()) {
    const auto it = next.find(section.back());
    if (it == next.end()) return std::nullopt;
    if (it->second == section.front()) break;
    section.push_back(it->second);
  }
  if (section.size() != next.size()) return std::nullopt;
  s.faces.push_back({kNoIndex, kNegative, section});
  return s;
}

// The worst badness of the two parts' faces, infinity when a part is flat or inverted.
double ReflexSplitter::split_worst(Index c, const Split& s) {
  const std::size_t old_points = mesh_.points.size();
  for (const Split::Cut& cut : s.cuts) mesh_.points.push_back(cut.position);
  std::array<std::vector<std::vector<Index>>, 2> parts;
  for (const Split::Face& f : s.faces) {
    parts[f.part].push_back(f.loop);
    if (f.face == kNoIndex) parts[kPositive].emplace_back(f.loop.rbegin(), f.loop.rend());
  }
  double w = std::numeric_limits<double>::infinity();
  const double floor = kMinPartVolume * std::pow(size_[c], 3);
  const CellGeometry a = geometry(parts[kNegative]), b = geometry(parts[kPositive]);
  // A part of three faces would be a closed fold of no volume, not a cell.
  if (a.volume > floor && b.volume > floor && parts[0].size() > 3 && parts[1].size() > 3) {
    const std::array<Vec3, 2> centre{a.centre, b.centre};
    w = 0.0;
    for (const Split::Face& f : s.faces) {
      if (f.face == kNoIndex) {
        const FaceGeometry g = polygon_geometry(points_(), f.loop);
        w = std::max(w, checkmesh_badness(g, points_(), f.loop, centre[kNegative], &centre[kPositive], limits_));
      } else {
        const Index o = other(f.face, c);
        w = std::max(w, badness(f.loop, centre[f.part], o == kNoIndex ? nullptr : &this->centre(o)));
      }
    }
  }
  mesh_.points.resize(old_points);
  return w;
}

// Puts m between a and b in every face around the edge a-b but c's own: walking from each
// of c's two faces on the edge through the cells around it, face to face.
void ReflexSplitter::insert_on_edge(Index c, Index a, Index b, Index m) {
  const auto on_edge = [a, b](std::span<const Index> l) {
    for (std::size_t i = 0; i < l.size(); ++i) {
      const Index u = l[i], v = l[(i + 1) % l.size()];
      if ((u == a && v == b) || (u == b && v == a)) return static_cast<std::ptrdiff_t>(i + 1);
    }
    return std::ptrdiff_t{-1};
  };
  std::vector<Index> start;
  for (Index f : faces_of(c))
    if (on_edge(loop(f)) >= 0) start.push_back(f);
  for (Index from : start) {
    Index cell = other(from, c);
    while (cell != kNoIndex && cell != c) {
      Index next = kNoIndex;
      std::ptrdiff_t at = -1;
      for (Index g : faces_of(cell))
        if (g != from && (at = on_edge(loop(g))) >= 0) {
          next = g;
          break;
        }
      if (next == kNoIndex) break;
      const std::span<const Index> l = loop(next);
      std::vector<Index> with(l.begin(), l.end());
      with.insert(with.begin() + at, m);
      set_loop(next, std::move(with));
      from = next;
      cell = other(next, cell);
    }
  }
}

void ReflexSplitter::commit(Index c, const Split& s) {
  for (const Split::Cut& cut : s.cuts) {
    insert_on_edge(c, cut.a, cut.b, mesh_.num_points());
    mesh_.points.push_back(cut.position);
  }
  const Index part_b = static_cast<Index>(region_.size());
  region_.push_back(region_[c]);
  size_.push_back(size_[c]);
  new_cell_faces_.emplace_back();
  centre_.emplace_back();
  centre_known_.push_back(0);
  centre_known_[c] = 0;
  const auto add_face = [&](std::vector<Index> l, Index owner, Index neighbour, Index tag) {
    const Index f = base_faces_ + static_cast<Index>(new_loops_.size());
    new_loops_.push_back(std::move(l));
    owner_.push_back(owner);
    neighbour_.push_back(neighbour);
    tag_.push_back(tag);
    return f;
  };
  const auto stored = [&](std::vector<Index> l, Index f) {
    if (owner_[f] != c) std::reverse(l.begin(), l.end());
    return l;
  };
  std::vector<Index> faces_a, faces_b;
  for (const Split::Face& face : s.faces) {
    const Index f = face.face;
    if (f == kNoIndex) {
      const Index g = add_face(face.loop, c, part_b, kNoIndex);
      faces_a.push_back(g);
      faces_b.push_back(g);
    } else if (face.part == kNegative) {
      set_loop(f, stored(face.loop, f));
      faces_a.push_back(f);
    } else if (std::any_of(s.faces.begin(), s.faces.end(),
                           [f](const Split::Face& o) { return o.face == f && o.part == kNegative; })) {
      // The positive half of a split face: a new face beside the original, one more face of
      // the cell beyond.
      const Index g = add_face(stored(face.loop, f), owner_[f] == c ? part_b : owner_[f],
                               neighbour_[f] == c ? part_b : neighbour_[f], tag_[f]);
      faces_b.push_back(g);
      if (const Index o = other(g, part_b); o != kNoIndex) mutable_faces_of(o).push_back(g);
    } else {
      if (journal_) journal_->sides.push_back({f, owner_[f], neighbour_[f]});
      (owner_[f] == c ? owner_[f] : neighbour_[f]) = part_b;
      faces_b.push_back(f);
    }
  }
  mutable_faces_of(c) = std::move(faces_a);
  new_cell_faces_.back() = std::move(faces_b);
}

// The split of c along one of the planes whose parts' worst face scores lowest, below `below`.
std::optional<Split> ReflexSplitter::best_split(Index c, const std::vector<Plane>& planes, double below) {
  std::optional<Split> best;
  for (const Plane& p : planes) {
    std::optional<Split> s = split(c, p);
    if (!s) continue;
    if (const double w = split_worst(c, *s); w < below) {
      below = w;
      best = std::move(s);
    }
  }
  return best;
}

Index ReflexSplitter::run() {
  // The cells with a reflex edge, found in parallel; a split changes only its cell's
  // faces and points on the faces around, so the cells are then taken in order.
  std::vector<char> reflex(base_cells_, 0);
  tbb::parallel_for(tbb::blocked_range<Index>(0, base_cells_), [&](const tbb::blocked_range<Index>& r) {
    for (Index c = r.begin(); c != r.end(); ++c) reflex[c] = !reflex_planes(c).empty();
  });
  Index splits = 0;
  std::vector<Index> left;  // rejected cells no split of their own leaves as checkMesh wants
  for (Index c = 0; c < base_cells_; ++c) {
    if (!reflex[c]) continue;
    const std::vector<Plane> planes = reflex_planes(c);
    if (planes.empty() || worst(c) <= 1.0) continue;
    // Only a split that leaves both parts as checkMesh wants them: a part still rejected is
    // better merged whole, as the agglomeration would have done.
    const std::optional<Split> best = best_split(c, planes, 1.0);
    if (!best) {
      left.push_back(c);
      continue;
    }
    commit(c, *best);
    ++splits;
  }
  for (Index c : left) splits += split_with_neighbours(c);
  if (splits > 0) mesh_ = rebuild();
  return splits;
}

// Two cells of different regions bent into each other: each one's centre lies behind a
// face they share (where a pinched-out layer meets a fault), so a split of either
// alone still leaves the face rejected, by the other side. c is split where that lowers its
// worst face, then in turn each cell across a face the split leaves rejected, and the
// splits are kept only when none of their parts' faces is rejected. Where c is rejected only
// across faces between regions, which no merge can take away, the splits are also kept when
// they leave no inverted pyramid: a skewed face is left to the merging. Otherwise all of
// them are undone. Returns the number of splits kept.
Index ReflexSplitter::split_with_neighbours(Index c) {
  const auto rejected = [&](Index f, Index x) {
    const Index o = other(f, x);
    return badness(outward(f, x), centre(x), o == kNoIndex ? nullptr : &centre(o)) > 1.0;
  };
  if (worst(c) <= 1.0) return 0;
  bool interfaces_only = true;
  for (Index f : faces_of(c))
    if (rejected(f, c) && (other(f, c) == kNoIndex || region_[other(f, c)] == region_[c])) interfaces_only = false;
  Journal journal{mesh_.points.size(), region_.size(), owner_.size(), {}, {}, {}};
  journal_ = &journal;
  std::vector<Index> queue{c}, parts;
  // A few splits at most: the cells bent into each other come in pairs.
  for (std::size_t next = 0; next < queue.size() && parts.size() < 8; ++next) {
    const Index x = queue[next];
    const double before = worst(x);
    if (before <= 1.0) continue;
    const std::optional<Split> best = best_split(x, reflex_planes(x), before);
    if (!best) continue;
    commit(x, *best);
    const Index part_b = static_cast<Index>(region_.size()) - 1;
    for (const Index y : {x, part_b}) {
      parts.push_back(y);
      for (Index f : faces_of(y))
        if (const Index o = other(f, y); o != kNoIndex && rejected(f, y) &&
                                         std::find(queue.begin(), queue.end(), o) == queue.end())
          queue.push_back(o);
    }
  }
  journal_ = nullptr;
  double after = 0.0;
  for (Index y : parts) after = std::max(after, worst(y));
  if (!parts.empty() && (after <= 1.0 || (interfaces_only && after < kInvertedFace)))
    return static_cast<Index>(parts.size() / 2);
  undo(journal);
  return 0;
}

void ReflexSplitter::undo(const Journal& j) {
  const Index faces = static_cast<Index>(j.faces), cells = static_cast<Index>(j.cells);
  restore(j.loops, faces, base_faces_, new_loops_, changed_loops_);
  restore(j.cell_faces, cells, base_cells_, new_cell_faces_, changed_cells_);
  for (auto it = j.sides.rbegin(); it != j.sides.rend(); ++it) {
    owner_[(*it)[0]] = (*it)[1];
    neighbour_[(*it)[0]] = (*it)[2];
  }
  mesh_.points.resize(j.points);
  new_loops_.resize(j.faces - base_faces_);
  owner_.resize(j.faces);
  neighbour_.resize(j.faces);
  tag_.resize(j.faces);
  new_cell_faces_.resize(j.cells - base_cells_);
  region_.resize(j.cells);
  size_.resize(j.cells);
  centre_.resize(j.cells);
  centre_known_.resize(j.cells);
  // The restored cells, and those on a restored face (their centres were taken with the
  // point the chain put on it), need their centres again.
  for (const auto& [c, list] : j.cell_faces)
    if (c < cells) centre_known_[c] = 0;
  for (const auto& [f, loop] : j.loops)
    if (f < faces)
      for (const Index c : {owner_[f], neighbour_[f]})
        if (c != kNoIndex && c < cells) centre_known_[c] = 0;
}

// The split mesh; the points move into it.
PolyMesh ReflexSplitter::rebuild() {
  const auto faces = static_cast<Index>(owner_.size());
  std::size_t corners = 0;
  for (Index f = 0; f < faces; ++f) corners += loop(f).size();
  PolyMesh out;
  out.reserve_faces(static_cast<std::size_t>(faces), corners);
  for (Index f = 0; f < faces; ++f) out.add_face(loop(f), owner_[f], neighbour_[f], tag_[f]);
  out.points = std::move(mesh_.points);
  out.cell_region = region_;
  out.tag_names = mesh_.tag_names;
  return out;
}

}  // namespace

Index split_reflex_cells(PolyMesh& mesh, std::vector<double>& cell_size, const CheckMeshLimits& limits) {
  return ReflexSplitter(mesh, cell_size, limits).run();
}

}  // namespace volmesh::cutcell
