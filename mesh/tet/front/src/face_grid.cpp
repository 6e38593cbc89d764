#include "face_grid.hpp"

#include <algorithm>

namespace volmesh::tet::front {

FaceGrid make_face_grid(const AuxCells& cells) {
  FaceGrid g;
  g.cells = &cells;
  g.faces.resize(cells.leaves.size());
  return g;
}

void insert_face(FaceGrid& g, Index face, const Vec3& lo, const Vec3& hi) {
  for_each_leaf(*g.cells, lo, hi, [&](int leaf) { g.faces[leaf].push_back(face); });
  if (static_cast<std::size_t>(face) >= g.stamp.size()) g.stamp.resize(face + 1, 0);
}

void faces_near(FaceGrid& g, const Vec3& lo, const Vec3& hi, const std::vector<char>& live,
                std::vector<Index>& out) {
  ++g.query;
  out.clear();
  for_each_leaf(*g.cells, lo, hi, [&](int leaf) {
    auto& cell = g.faces[leaf];
    std::erase_if(cell, [&](Index f) { return !live[f]; });
    for (const Index f : cell)
      if (g.stamp[f] != g.query) {
        g.stamp[f] = g.query;
        out.push_back(f);
      }
  });
}

}  // namespace volmesh::tet::front
