#include "msh_elements.hpp"

#include <tuple>

#include "msh_format.hpp"
#include "text_format.hpp"

namespace volmesh::msh {

void sort_by_size(std::vector<Element>& elements) {
  std::stable_sort(elements.begin(), elements.end(),
                   [](const Element& a, const Element& b) { return a.size < b.size; });
}

void sort_by_vertices(std::vector<Element>& elements) {
  std::sort(elements.begin(), elements.end(), [](const Element& a, const Element& b) {
    return std::tie(a.size, a.vertices) < std::tie(b.size, b.vertices);
  });
}

void append_elements(std::string& text, std::span<const ElementGroup> groups) {
  struct Block {
    const ElementGroup* group;
    std::size_t begin, end;
  };
  std::vector<Block> blocks;
  long long count = 0, max_tag = 0;
  for (const ElementGroup& group : groups) {
    const auto& elements = group.elements;
    for (std::size_t begin = 0, end; begin < elements.size(); begin = end) {
      for (end = begin + 1; end < elements.size() && elements[end].size == elements[begin].size;) ++end;
      blocks.push_back({&group, begin, end});
    }
    count += static_cast<long long>(elements.size());
    for (const Element& e : elements) max_tag = std::max<long long>(max_tag, e.tag);
  }
  text += "$Elements\n";
  for (long long v : {static_cast<long long>(blocks.size()), count, count > 0 ? 1LL : 0LL, max_tag})
    append_number(text, v), text += ' ';
  text.back() = '\n';
  for (const Block& block : blocks) {
    const int dim = block.group->dim;
    const int size = block.group->elements[block.begin].size;
    const int type = dim == 2 ? (size == 3 ? kTriangle : kQuadrangle) : (size == 4 ? kTetrahedron : kHexahedron);
    for (long long v : {static_cast<long long>(dim), static_cast<long long>(block.group->entity_tag),
                        static_cast<long long>(type)})
      append_number(text, v), text += ' ';
    append_number(text, static_cast<long long>(block.end - block.begin));
    text += '\n';
    for (std::size_t i = block.begin; i < block.end; ++i) {
      const Element& e = block.group->elements[i];
      append_number(text, e.tag);
      for (Index v : e.corners()) text += ' ', append_number(text, v + 1);
      text += '\n';
    }
  }
  text += "$EndElements\n";
}

}  // namespace volmesh::msh
