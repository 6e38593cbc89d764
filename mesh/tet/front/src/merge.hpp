#pragma once
// Merging a cavity's projection mesh whose boundary splits the cavity's faces: the tets outside
// the cavity that hold a split face or edge are refined to match. Each such tet is coned from
// its centroid to the pieces of its four faces (it is convex, so every cone tet is positive;
// each is checked exactly). A face is cut into the projection's own pieces where it is a
// cavity face, else canonically (split_canonically): the same pieces from both sides.
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

using Tri = std::array<Index, 3>;
using Edge = std::array<Index, 2>;
using Tet = std::array<Index, 4>;

// The corners of a triangle, sorted: the key of a face whatever its orientation.
Tri corners_of(const Tri& t);
Tri reversed(const Tri& t);

// The faces split so far: each by its corners, with the orientation its pieces follow.
class FaceSplits {
 public:
  void record(const Tri& face, const std::vector<Tri>& pieces);
  // The current pieces of `face` (itself when never split), oriented as it, appended to out.
  void resolve(const Tri& face, std::vector<Tri>& out) const;
  bool contains(const Tri& face) const { return by_corners_.count(corners_of(face)) > 0; }

 private:
  std::map<Tri, std::pair<Tri, std::vector<Tri>>> by_corners_;
};

// How closing one cavity cuts its faces and edges (in mesh point indices).
struct CavitySplit {
  // Points inside an edge (keyed by its sorted corners), in order from key[0] to key[1].
  std::map<Edge, std::vector<Index>> edge_points;
  // A split cavity face by its corners: the face as seen from outside the cavity, and its
  // pieces oriented the same way.
  std::map<Tri, std::pair<Tri, std::vector<Tri>>> faces;
};

// The pieces of the triangle whose edge i (t[i] to t[i+1]) holds points on_edge[i] in order:
// split at the point of least index by a segment to the opposite corner, recursively. The
// pieces depend only on the points, never on how t is rotated; orientation is kept.
void split_canonically(const Tri& t, const std::array<std::vector<Index>, 3>& on_edge,
                       std::vector<Tri>& out);

struct Refinement {
  long long tets = 0;      // tets replaced by cones
  long long centroids = 0;  // their centroids, the new points
};

// Replaces every tet of `cells` that holds a split face or edge by the cone from its centroid
// (appended to points) to its faces' pieces, and records in `splits` every face of such a tet,
// and every face of `loose` (faces of no tet: boundary triangles, other cavities' faces), that
// the split cuts. Returns false, changing nothing, when a cone tet is not positive (exactly).
bool refine_around(std::vector<Vec3>& points, std::vector<Tet>& cells, std::vector<Index>& labels,
                   const CavitySplit& split, const std::vector<Tri>& loose, FaceSplits& splits,
                   Refinement& refinement);

}  // namespace volmesh::tet::front
