// Gmsh MSH 4.1 ASCII input: nodes, linear volume elements (tetrahedra, hexahedra, prisms,
// pyramids) and surface elements (triangles, quadrangles). Volume physical groups become
// regions, surface physical groups name the boundary tags.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "volmesh/core/cell_soup.hpp"
#include "msh_format.hpp"
#include "msh_tokens.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

// Node tag → point index: dense when the tags are (nearly) contiguous, else a sorted table.
class NodeLookup {
 public:
  NodeLookup() = default;
  NodeLookup(const std::vector<long long>& tags, long long min_tag, long long max_tag) {
    // Unsigned difference: all tags lie in [min_tag, max_tag], so it cannot overflow.
    const unsigned long long span =
        static_cast<unsigned long long>(max_tag) - static_cast<unsigned long long>(min_tag);
    if (!tags.empty() && span < 4 * tags.size() + 16) {
      base_ = min_tag;
      dense_.assign(static_cast<std::size_t>(span + 1), kNoIndex);
      for (std::size_t i = 0; i < tags.size(); ++i) dense_[tags[i] - base_] = static_cast<Index>(i);
    } else {
      for (std::size_t i = 0; i < tags.size(); ++i)
        sorted_.emplace_back(tags[i], static_cast<Index>(i));
      std::sort(sorted_.begin(), sorted_.end());
    }
  }

  Index find(long long tag) const {
    if (!sorted_.empty() || dense_.empty()) {
      auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::make_pair(tag, Index{0}));
      return it != sorted_.end() && it->first == tag ? it->second : kNoIndex;
    }
    if (tag < base_ || tag - base_ >= static_cast<long long>(dense_.size())) return kNoIndex;
    return dense_[tag - base_];
  }

 private:
  long long base_ = 0;
  std::vector<Index> dense_;
  std::vector<std::pair<long long, Index>> sorted_;
};

// Element types read: cells (dimension 3), boundary faces (2), and points and lines
// (skipped).
struct ElementKind {
  int corners = 0;
  int dim = 0;
};

ElementKind element_kind(long long type) {
  switch (type) {
    case 15: return {1, 0};  // point
    case 1: return {2, 1};   // line
    case 8: return {3, 1};   // second-order line
    case msh::kTriangle: return {3, 2};
    case msh::kQuadrangle: return {4, 2};
    case msh::kTetrahedron: return {4, 3};
    case msh::kHexahedron: return {8, 3};
    case msh::kPrism: return {6, 3};
    case msh::kPyramid: return {5, 3};
    default: return {};
  }
}

LinearCell linear_cell(int type) {
  switch (type) {
    case msh::kTetrahedron: return LinearCell::Tetrahedron;
    case msh::kHexahedron: return LinearCell::Hexahedron;
    case msh::kPrism: return LinearCell::Wedge;
    default: return LinearCell::Pyramid;
  }
}

struct Element {
  long long tag;
  int type;
  Index region;
  std::size_t first_corner;  // into MshReader::corners_
};

class MshReader {
 public:
  MshReader(const fs::path& path)
      : source_(path.string()), tokens_(source_, msh::read_text(path)), soup_(source_) {}

  PolyMesh read() {
    if (tokens_.at_end() || tokens_.word() != "$MeshFormat")
      tokens_.fail("not a Gmsh MSH file (no $MeshFormat)");
    read_format();
    while (!tokens_.at_end()) {
      const std::string_view w = tokens_.word();
      if (w.size() < 2 || w[0] != '$')
        tokens_.fail("expected a section, found '" + std::string(w.substr(0, 40)) + "'");
      const std::string_view name = w.substr(1);
      if (name == "PhysicalNames")
        read_physical_names();
      else if (name == "Entities")
        read_entities();
      else if (name == "PartitionedEntities")
        tokens_.fail("partitioned MSH files are not supported");
      else if (name == "Nodes")
        read_nodes();
      else if (name == "Elements")
        read_elements();
      else
        tokens_.skip_section(name);
    }
    add_cells_in_tag_order();
    PolyMesh mesh = cells_to_poly(std::move(soup_));
    drop_unused_tags(mesh);  // interfaces and surfaces inside the volume tag no boundary face
    return mesh;
  }

 private:
  void read_format() {
    const std::string_view version = tokens_.word();
    if (version != "4.1")
      tokens_.fail("MSH version " + std::string(version.substr(0, 20)) +
                   " is not supported (4.1 expected)");
    if (tokens_.integer("the file type") != 0)
      tokens_.fail("binary MSH is not supported; save the mesh as ASCII MSH 4.1");
    tokens_.integer("the data size");
    tokens_.expect("$EndMeshFormat");
  }

  void read_physical_names() {
    const long long n = tokens_.count("number of physical names", 6);
    for (long long i = 0; i < n; ++i) {
      const long long dim = tokens_.integer("a dimension");
      const long long tag = tokens_.integer("a physical tag");
      physical_names_[{dim, tag}] = tokens_.quoted();
    }
    tokens_.expect("$EndPhysicalNames");
  }

  // Entities of dimension 2 and 3 map to their first physical tag (0 if none).
  void read_entities() {
    long long counts[4];
    for (long long& n : counts) n = tokens_.count("number of entities", 8);
    for (int dim = 0; dim < 4; ++dim)
      for (long long i = 0; i < counts[dim]; ++i) {
        const long long tag = tokens_.integer("an entity tag");
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) tokens_.real();
        const long long num_physicals = tokens_.count("number of physical tags", 2);
        long long physical = 0;
        for (long long k = 0; k < num_physicals; ++k) {
          const long long p = tokens_.integer("a physical tag");
          if (k == 0) physical = p;
        }
        if (dim > 0) {
          const long long num_bounding = tokens_.count("number of bounding entities", 2);
          for (long long k = 0; k < num_bounding; ++k) tokens_.integer("a bounding entity tag");
        }
        if (dim >= 2) entity_physical_[{dim, tag}] = physical;
      }
    tokens_.expect("$EndEntities");
  }

  void read_nodes() {
    const long long num_blocks = tokens_.count("number of node blocks", 8);
    const long long num_nodes = tokens_.count("number of nodes", 8);
    const long long min_tag = tokens_.integer("the smallest node tag");
    const long long max_tag = tokens_.integer("the largest node tag");
    if (!soup_.points.empty()) tokens_.fail("a second $Nodes section");
    std::vector<long long> tags;
    tags.reserve(static_cast<std::size_t>(num_nodes));
    soup_.points.reserve(static_cast<std::size_t>(num_nodes));
    for (long long b = 0; b < num_blocks; ++b) {
      const long long dim = tokens_.integer("an entity dimension");
      tokens_.integer("an entity tag");
      const long long parametric = tokens_.integer("the parametric flag");
      const long long n = tokens_.count("number of nodes in the block", 8);
      if (n > num_nodes - static_cast<long long>(tags.size()))
        tokens_.fail("more nodes than the $Nodes header announces");
      for (long long i = 0; i < n; ++i) {
        const long long tag = tokens_.integer("a node tag");
        if (tag < min_tag || tag > max_tag)
          tokens_.fail("node tag " + std::to_string(tag) + " outside the announced range " +
                       std::to_string(min_tag) + ".." + std::to_string(max_tag));
        tags.push_back(tag);
      }
      const int extra = parametric != 0 ? static_cast<int>(std::clamp<long long>(dim, 0, 3)) : 0;
      for (long long i = 0; i < n; ++i) {
        const double x = tokens_.real(), y = tokens_.real(), z = tokens_.real();
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
          tokens_.fail("node " + std::to_string(tags[soup_.points.size()]) +
                       ": coordinate is not finite");
        soup_.points.emplace_back(x, y, z);
        for (int k = 0; k < extra; ++k) tokens_.real();
      }
    }
    if (static_cast<long long>(tags.size()) != num_nodes)
      tokens_.fail("$Nodes announces " + std::to_string(num_nodes) + " nodes but holds " +
                   std::to_string(tags.size()));
    tokens_.expect("$EndNodes");
    nodes_ = NodeLookup(tags, min_tag, max_tag);
    std::vector<long long> sorted = tags;
    std::sort(sorted.begin(), sorted.end());
    if (auto dup = std::adjacent_find(sorted.begin(), sorted.end()); dup != sorted.end())
      tokens_.fail("node tag " + std::to_string(*dup) + " defined twice");
  }

  Index region_of(long long entity) {
    auto it = entity_physical_.find({3, entity});
    const long long region = it != entity_physical_.end() && it->second != 0 ? it->second : entity;
    if (region < 1 || region > kMaxIndex)
      tokens_.fail("volume entity " + std::to_string(entity) + ": region " +
                   std::to_string(region) + " (regions are integers >= 1)");
    return static_cast<Index>(region);
  }

  // Surface entity → boundary tag, named after its physical group.
  Index tag_of(long long entity) {
    auto it = entity_physical_.find({2, entity});
    const long long physical =
        it != entity_physical_.end() && it->second != 0 ? it->second : entity;
    auto name = physical_names_.find({2, physical});
    const std::string tag_name =
        name != physical_names_.end() ? name->second : "surface_" + std::to_string(physical);
    auto known = std::find(soup_.tag_names.begin(), soup_.tag_names.end(), tag_name);
    if (known != soup_.tag_names.end()) return static_cast<Index>(known - soup_.tag_names.begin());
    soup_.tag_names.push_back(tag_name);
    return static_cast<Index>(soup_.tag_names.size()) - 1;
  }

  void read_elements() {
    const long long num_blocks = tokens_.count("number of element blocks", 8);
    const long long num_elements = tokens_.count("number of elements", 4);
    tokens_.integer("the smallest element tag");
    tokens_.integer("the largest element tag");
    long long seen = 0;
    std::vector<Index> corners;
    for (long long b = 0; b < num_blocks; ++b) {
      const long long dim = tokens_.integer("an entity dimension");
      const long long entity = tokens_.integer("an entity tag");
      const long long type = tokens_.integer("an element type");
      const long long n = tokens_.count("number of elements in the block", 4);
      if (n > num_elements - seen)
        tokens_.fail("more elements than the $Elements header announces");
      seen += n;
      const auto [nc, type_dim] = element_kind(type);
      if (nc == 0)
        tokens_.fail("element type " + std::to_string(type) +
                     " is not supported (linear tetrahedra, hexahedra, prisms, pyramids, "
                     "triangles and quadrangles are)");
      if (type_dim >= 2 && dim != type_dim)
        tokens_.fail("element type " + std::to_string(type) + " in an entity of dimension " +
                     std::to_string(dim));
      const Index region = type_dim == 3 ? region_of(entity) : 0;
      const Index tag = type_dim == 2 ? tag_of(entity) : 0;
      for (long long e = 0; e < n; ++e) {
        const long long element_tag = tokens_.integer("an element tag");
        corners.clear();
        for (int k = 0; k < nc; ++k) {
          const long long node = tokens_.integer("a node tag");
          const Index p = nodes_.find(node);
          if (p == kNoIndex)
            tokens_.fail("element " + std::to_string(element_tag) + ": node tag " +
                         std::to_string(node) + " not defined in $Nodes");
          corners.push_back(p);
        }
        if (type_dim == 2) soup_.add_tagged_face(corners, tag);
        if (type_dim != 3) continue;
        elements_.push_back({element_tag, static_cast<int>(type), region, corners_.size()});
        corners_.insert(corners_.end(), corners.begin(), corners.end());
      }
    }
    if (seen != num_elements)
      tokens_.fail("$Elements announces " + std::to_string(num_elements) + " elements but holds " +
                   std::to_string(seen));
    tokens_.expect("$EndElements");
  }

  // Cells in element-tag order, which is the writer's cell order and Gmsh's numbering.
  void add_cells_in_tag_order() {
    std::stable_sort(elements_.begin(), elements_.end(),
                     [](const Element& a, const Element& b) { return a.tag < b.tag; });
    for (const Element& e : elements_)
      soup_.add_cell(linear_cell(e.type),
                     std::span(corners_).subspan(e.first_corner, element_kind(e.type).corners),
                     e.region);
  }

  std::string source_;
  msh::Tokens tokens_;
  CellSoup soup_;
  std::map<std::pair<long long, long long>, std::string> physical_names_;
  std::map<std::pair<long long, long long>, long long> entity_physical_;
  NodeLookup nodes_;
  std::vector<Element> elements_;
  std::vector<Index> corners_;
};

}  // namespace

PolyMesh read_msh(const fs::path& path) { return MshReader(path).read(); }

}  // namespace volmesh
