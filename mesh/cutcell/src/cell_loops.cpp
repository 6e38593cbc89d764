// The face contours of a cell joined into closed components per pair of regions: cycles of
// surface segments, and paths between face interface points closed through the link
// between two of them or through the cell interface point.
#include <map>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "cell_split_state.hpp"

namespace volmesh::cutcell {

void build_loops(SplitState& st) {
  for (CellSegment s : st.in.segments) {
    if (s.left > s.right) {
      std::swap(s.a, s.b);
      std::swap(s.left, s.right);
      std::swap(s.left_polygon, s.right_polygon);
    }
    st.segments.push_back(s);
  }
  std::vector<int> face_points;
  for (int i = 0; i < static_cast<int>(st.in.points.size()); ++i)
    if (st.in.points[i].is_face_interface()) face_points.push_back(i);
  const int nif = static_cast<int>(face_points.size());
  const int centre = cell_interface_point(st, face_points);

  // Segments by (pair, start point), sorted for lookup.
  using Key = std::tuple<Index, Index, int>;
  std::map<Key, int> from;
  std::map<Key, int> into;
  for (int i = 0; i < static_cast<int>(st.segments.size()); ++i) {
    const CellSegment& s = st.segments[i];
    if (!from.emplace(Key{s.left, s.right, s.a}, i).second ||
        !into.emplace(Key{s.left, s.right, s.b}, i).second)
      throw std::logic_error("split_cell: two contour segments of one pair leave one point");
  }
  std::vector<char> used(st.segments.size(), 0);
  const auto walk = [&](int first, Loop& loop) {
    int i = first;
    while (true) {
      used[i] = 1;
      const CellSegment& s = st.segments[i];
      loop.points.push_back(s.a);
      loop.segments.push_back(i);
      const auto next = from.find(Key{s.left, s.right, s.b});
      if (next == from.end()) return s.b;  // an open end
      if (next->second == first) return -1;
      i = next->second;
    }
  };
  // Paths first: they start at a point no segment of the pair enters.
  for (int i = 0; i < static_cast<int>(st.segments.size()); ++i) {
    const CellSegment& s = st.segments[i];
    if (used[i] || into.count(Key{s.left, s.right, s.a})) continue;
    Loop loop{{}, {}, s.left, s.right, false};
    const int end = walk(i, loop);
    if (end < 0 || nif < 2 || !st.in.points[s.a].is_face_interface() ||
        !st.in.points[end].is_face_interface() || end == s.a)
      throw std::logic_error("split_cell: a contour component does not close");
    loop.points.push_back(end);
    if (centre >= 0) {
      loop.points.push_back(centre);
      loop.through_cell_point = true;
    }
    st.loops.push_back(std::move(loop));
  }
  for (int i = 0; i < static_cast<int>(st.segments.size()); ++i) {
    if (used[i]) continue;
    Loop loop{{}, {}, st.segments[i].left, st.segments[i].right, false};
    if (walk(i, loop) >= 0) throw std::logic_error("split_cell: a contour component does not close");
    st.loops.push_back(std::move(loop));
  }
}

}  // namespace volmesh::cutcell
