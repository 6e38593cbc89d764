#pragma once
// A tet mesh open to local changes: each point's incident tets, each tet's cached quality
// (quality.hpp), the faces that must stay faces (boundary and interface triangles) and how
// each point may move. Removed tets leave their slots empty and new tets take fresh ones at
// the end, so that the final order depends only on the sequence of changes.
#include <array>
#include <limits>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/improve/slides.hpp"

namespace volmesh::improve {

using Tet = std::array<Index, 4>;

// How a point may move.
enum class Freedom : std::uint8_t { Free, Pinned, Slides };

class TetComplex {
 public:
  // The fixed faces are the mesh's boundary faces and the faces between two regions; their
  // corners are pinned unless `slides` lets them slide (boundary points only).
  TetComplex(const TetMesh& mesh, const std::vector<Slide>& slides);

  const Vec3& point(Index v) const { return points_[v]; }
  const std::vector<Vec3>& points() const { return points_; }
  const Tet& tet(Index t) const { return tets_[t]; }
  Index region(Index t) const { return region_[t]; }
  bool alive(Index t) const { return alive_[t] != 0; }
  double quality(Index t) const { return quality_[t]; }
  Index num_slots() const { return static_cast<Index>(tets_.size()); }
  Index num_points() const { return static_cast<Index>(points_.size()); }
  Freedom freedom(Index v) const { return freedom_[v]; }
  const Slide& slide(Index v) const { return slides_[v]; }
  bool fixed_face(Index a, Index b, Index c) const;
  const std::vector<Index>& star(Index v) const { return star_[v]; }

  // Live tets holding both / all three points, in slot order.
  std::vector<Index> tets_with(Index a, Index b) const;
  std::vector<Index> tets_with(Index a, Index b, Index c) const;
  // The live tet across face (a, b, c) from tet t, or kNoIndex.
  Index across(Index t, Index a, Index b, Index c) const;

  // The smallest cached quality of the tets.
  double min_quality(std::span<const Index> tets) const;
  // The smallest quality of the given corner sets with the current points, or any value at
  // most `floor` once it is known to be no more.
  double min_quality_of(std::span<const Tet> tets, double floor = -std::numeric_limits<double>::infinity()) const;
  // Whether every tet is positive by the exact test.
  bool all_positive(std::span<const Tet> tets) const;

  // Point `gone`'s fixed faces renamed after a contraction into `kept`: those holding both
  // go, the others hold `kept` instead (boundary faces keep their slot and tag).
  void rename_fixed(Index gone, Index kept);

  // A new free point, with no tet yet.
  Index add_point(const Vec3& p);
  // The old tets (one region) give way to the fresh ones; returns the fresh ones' slots.
  std::vector<Index> replace(std::span<const Index> old, std::span<const Tet> fresh);
  // Point v moves no more.
  void pin(Index v) { freedom_[v] = Freedom::Pinned; }
  // Moves a point that may move (the caller has checked its star).
  void move(Index v, const Vec3& p);

  // The smallest quality of any live tet.
  double worst_quality() const;

  // A clock that ticks with every change: a point's stamp is the time its star last changed
  // (a tet of it replaced, or a corner of one moved), so that a failed attempt is not
  // repeated on an unchanged neighbourhood.
  long long now() const { return clock_; }
  bool changed_since(Index v, long long time) const { return stamp_[v] > time; }

  // The mesh as it stands: live tets in slot order, points without tets dropped (the others
  // keep their order), the boundary faces (`mesh`'s, renamed by contractions) and their tags
  // renumbered.
  // With `keep_numbers`, every point stays, with its number, tets or none.
  void write_to(TetMesh& mesh, bool keep_numbers = false) const;

 private:
  struct FaceHash {
    std::size_t operator()(const std::array<Index, 3>& f) const;
  };
  void attach(Index t);
  void detach(Index t);
  void touch(const Tet& t) {
    for (const Index v : t) stamp_[v] = clock_;
  }

  std::vector<Vec3> points_;
  std::vector<Tet> tets_;
  std::vector<Index> region_;
  std::vector<char> alive_;
  std::vector<double> quality_;
  std::vector<std::vector<Index>> star_;
  std::vector<Freedom> freedom_;
  std::vector<Slide> slides_;
  std::vector<long long> stamp_;
  long long clock_ = 0;
  std::unordered_set<std::array<Index, 3>, FaceHash> fixed_;  // sorted corners
  // The boundary faces in the mesh's order (a removed one: kNoIndex corners) and their tags.
  std::vector<std::array<Index, 3>> boundary_;
  std::vector<Index> boundary_tag_;
  std::unordered_map<std::array<Index, 3>, Index, FaceHash> boundary_slot_;  // sorted → slot
};

// Whether (a, b, c, d) is an even permutation of the stored corners (so positive too).
bool even_order(const Tet& stored, Index a, Index b, Index c, Index d);

// t's corners other than a and b, ordered so that (a, b, c, d) is an even permutation of t.
std::array<Index, 2> opposite_edge(const Tet& t, Index a, Index b);

bool holds(const Tet& t, Index v);

}  // namespace volmesh::improve
