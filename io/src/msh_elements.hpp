#pragma once
// MSH 4.1 elements as both writers (whole mesh and partitioned) build and print them.
#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::msh {

// A Gmsh element: its tag and vertices (3, 4 or 8 of them).
struct Element {
  Index tag = 0;
  int size = 0;
  std::array<Index, 8> vertices{};
  std::span<const Index> corners() const { return {vertices.data(), static_cast<std::size_t>(size)}; }
};

template <typename Loop>
Element make_element(Index tag, const Loop& loop, std::size_t size) {
  Element e{tag, static_cast<int>(size), {}};
  std::copy(loop.begin(), loop.begin() + size, e.vertices.begin());
  return e;
}

// Gmsh blocks hold one element type: smaller elements first. Cells keep their order within
// a type (it is the cell order the reader restores), faces are sorted by vertices.
void sort_by_size(std::vector<Element>& elements);
void sort_by_vertices(std::vector<Element>& elements);

// The elements of one entity of dimension dim (2 or 3).
struct ElementGroup {
  int dim = 0;
  Index entity_tag = 0;
  std::span<const Element> elements;
};

// The $Elements section: one block per entity and element type, in the groups' order.
void append_elements(std::string& text, std::span<const ElementGroup> groups);

}  // namespace volmesh::msh
