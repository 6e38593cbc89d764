#pragma once
// A tet mesh open to local changes, for the improvement pass: each node's incident tets,
// each tet's cached quality (min_sine.hpp), and the faces that must stay faces (the input
// surfaces' triangles, outer and interface). Replaced tets reuse their slots, so that the
// final order depends only on the sequence of changes.
#include <array>
#include <set>
#include <vector>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh::tet::front {

using Tet = std::array<Index, 4>;

class LiveMesh {
 public:
  // Nodes below fixed_nodes and the corners of `kept` never move; `kept` are faces of m that
  // no change may remove.
  LiveMesh(TetMesh& m, Index fixed_nodes, const std::vector<std::array<Index, 3>>& kept);

  const Vec3& point(Index v) const { return m_.points[v]; }
  const Tet& tet(Index t) const { return m_.cells[t]; }
  Index region(Index t) const { return m_.cell_region[t]; }
  bool alive(Index t) const { return alive_[t]; }
  double quality(Index t) const { return quality_[t]; }
  Index num_slots() const { return m_.num_cells(); }
  Index num_points() const { return m_.num_points(); }
  bool movable(Index v) const { return !pinned_[v]; }
  bool kept(Index a, Index b, Index c) const;
  const std::vector<Index>& incident(Index v) const { return incident_[v]; }

  // Live tets holding both / all three nodes, in slot order.
  std::vector<Index> tets_with(Index a, Index b) const;
  std::vector<Index> tets_with(Index a, Index b, Index c) const;

  // The old tets give way to the fresh ones (positive, in the old ones' region).
  void replace(const std::vector<Index>& old, const std::vector<Tet>& fresh);
  // Moves a movable node (its star stays positive: the caller checks).
  void move(Index v, const Vec3& p);

  // Drops the slots of removed tets and the nodes left with no tet, keeping the others'
  // order (the mesh's boundary faces renumbered too).
  void compact();

 private:
  void attach(Index t);
  void detach(Index t);

  TetMesh& m_;
  std::vector<char> pinned_;  // per node
  std::set<std::array<Index, 3>> kept_;  // sorted corners
  std::vector<std::vector<Index>> incident_;
  std::vector<char> alive_;
  std::vector<double> quality_;
};

// Whether (a, b, c, d) is an even permutation of the tet's stored corners (so positive too).
bool even_order(const Tet& stored, Index a, Index b, Index c, Index d);

// The tet's quality from its corners' points.
double quality_of(const std::vector<Vec3>& points, const Tet& t);

}  // namespace volmesh::tet::front
