#pragma once
// A CellList's cells and tagged faces handed to a CellSoup, the points renumbered by `point`
// (a piece's own index → the soup's): the one replay behind reading a VTU and stitching the
// pieces of a PVTU.
#include <vector>

#include "volmesh/core/cell_soup.hpp"
#include "volmesh/io/partitioned_io.hpp"

namespace volmesh::detail {

template <class PointMap>
void add_cell(const CellList& list, Index c, const PointMap& point, CellSoup& soup) {
  std::vector<Index> loop;
  const Index* item = list.items.data() + list.cell_begin[c];
  const Index* end = list.items.data() + list.cell_begin[c + 1];
  if (list.cell_kind[c] != CellList::kPolyhedron) {
    for (; item != end; ++item) loop.push_back(point(*item));
    soup.add_cell(static_cast<LinearCell>(list.cell_kind[c]), loop, list.cell_region[c]);
    return;
  }
  while (item != end) {
    const Index n = *item++;
    loop.clear();
    for (Index i = 0; i < n; ++i) loop.push_back(point(*item++));
    soup.add_face(loop);
  }
  soup.end_cell(list.cell_region[c]);
}

// Tagged face t, its tag renumbered by `tag`.
template <class PointMap, class TagMap>
void add_tagged_face(const CellList& list, std::size_t t, const PointMap& point,
                     const TagMap& tag, CellSoup& soup) {
  std::vector<Index> loop;
  for (Index i = list.tagged_begin[t]; i < list.tagged_begin[t + 1]; ++i)
    loop.push_back(point(list.tagged_vertices[i]));
  soup.add_tagged_face(loop, tag(list.tagged_tag[t]));
}

}  // namespace volmesh::detail
