// MEDIT ASCII .mesh input: Vertices, Tetrahedra, Hexahedra, Triangles and Quadrilaterals;
// the other keywords of the format are skipped by their known sizes.
//
// A cell's reference is its region; when some cell has reference 0 (MEDIT's "none"), every
// region is its reference + 1, since regions count from 1. Triangles and quadrilaterals tag
// the boundary faces they match by their reference, named as the writer's comment lines
// "# REF boundary NAME" name them, else "ref_REF"; the ones inside the mesh (interfaces) tag
// nothing.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "msh_tokens.hpp"
#include "text_format.hpp"
#include "volmesh/core/cell_soup.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {

namespace {

// Keywords read for their sizes only: integers and reals per item.
struct Skipped {
  std::string_view keyword;
  int integers, reals;
};
constexpr std::array<Skipped, 11> kSkipped{{{"Edges", 3, 0},
                                            {"Corners", 1, 0},
                                            {"Ridges", 1, 0},
                                            {"RequiredVertices", 1, 0},
                                            {"RequiredEdges", 1, 0},
                                            {"RequiredTriangles", 1, 0},
                                            {"RequiredQuadrilaterals", 1, 0},
                                            {"Normals", 0, 3},
                                            {"Tangents", 0, 3},
                                            {"NormalAtVertices", 2, 0},
                                            {"TangentAtVertices", 2, 0}}};

// The names of the comment lines "# REF boundary NAME".
std::map<long long, std::string> boundary_names(const std::string& text) {
  std::map<long long, std::string> names;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + at, end - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    at = end + 1;
    if (!line.starts_with("# ")) continue;
    line.remove_prefix(2);
    const std::size_t space = line.find(' ');
    long long ref = 0;
    constexpr std::string_view kBoundary = " boundary ";
    if (space == std::string_view::npos || !parse_number(line.substr(0, space), ref) ||
        !line.substr(space).starts_with(kBoundary))
      continue;
    names[ref] = std::string(line.substr(space + kBoundary.size()));
  }
  return names;
}

class MeditReader {
 public:
  explicit MeditReader(const std::filesystem::path& path)
      : text_(msh::read_text(path)), tokens_(path.string(), text_, '#'), soup_(path.string()) {}

  PolyMesh read() {
    if (tokens_.at_end() || tokens_.word() != "MeshVersionFormatted")
      tokens_.fail("not a MEDIT mesh (no MeshVersionFormatted)");
    const long long version = tokens_.integer("a format version");
    if (version < 1 || version > 3) tokens_.fail("unknown MEDIT version " + std::to_string(version));
    while (!tokens_.at_end()) {
      const std::string keyword(tokens_.word());
      if (keyword == "End") break;
      if (keyword == "Dimension") {
        if (tokens_.integer("a dimension") != 3) tokens_.fail("only 3D meshes are read");
      } else if (keyword == "Vertices") {
        read_vertices();
      } else if (keyword == "Tetrahedra") {
        read_items(keyword, 4, true);
      } else if (keyword == "Hexahedra") {
        read_items(keyword, 8, true);
      } else if (keyword == "Triangles") {
        read_items(keyword, 3, false);
      } else if (keyword == "Quadrilaterals") {
        read_items(keyword, 4, false);
      } else {
        skip(keyword);
      }
    }
    if (cells_.empty()) tokens_.fail("no Tetrahedra or Hexahedra");
    add_cells();
    add_faces();
    PolyMesh mesh = cells_to_poly(std::move(soup_));
    drop_unused_tags(mesh);
    return mesh;
  }

 private:
  struct Item {
    int corners;
    std::size_t first;  // into corners_
    long long ref;
  };

  void read_vertices() {
    if (!soup_.points.empty()) tokens_.fail("a second Vertices section");
    const long long n = tokens_.count("number of vertices", 8);
    soup_.points.reserve(static_cast<std::size_t>(n));
    for (long long i = 0; i < n; ++i) {
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = tokens_.real();
      if (!p.allFinite()) tokens_.fail("vertex " + std::to_string(i + 1) + ": coordinate is not finite");
      tokens_.integer("a vertex reference");
      soup_.points.push_back(p);
    }
  }

  void read_items(const std::string& keyword, int corners, bool cell) {
    const long long n = tokens_.count("number of elements", 2 * (corners + 1));
    std::vector<Item>& items = cell ? cells_ : faces_;
    for (long long i = 0; i < n; ++i) {
      items.push_back({corners, corners_.size(), 0});
      for (int k = 0; k < corners; ++k) {
        const long long v = tokens_.integer("a vertex number");
        if (v < 1 || v > static_cast<long long>(soup_.points.size()))
          tokens_.fail(keyword + " " + std::to_string(i + 1) + ": vertex " + std::to_string(v) +
                       " out of range (" + std::to_string(soup_.points.size()) + " vertices)");
        corners_.push_back(static_cast<Index>(v - 1));
      }
      items.back().ref = tokens_.integer("a reference");
      if (cell && (items.back().ref < 0 || items.back().ref >= kMaxIndex))
        tokens_.fail(keyword + " " + std::to_string(i + 1) + ": reference " +
                     std::to_string(items.back().ref) + " (regions are integers >= 0)");
    }
  }

  void skip(const std::string& keyword) {
    const auto it = std::find_if(kSkipped.begin(), kSkipped.end(),
                                 [&](const Skipped& s) { return s.keyword == keyword; });
    if (it == kSkipped.end())
      tokens_.fail("unsupported keyword '" + keyword.substr(0, 40) +
                   "' (read: Vertices Tetrahedra Hexahedra Triangles Quadrilaterals)");
    const long long n = tokens_.count("number of items", 2 * (it->integers + it->reals));
    for (long long i = 0; i < n; ++i) {
      for (int k = 0; k < it->integers; ++k) tokens_.integer("an integer");
      for (int k = 0; k < it->reals; ++k) tokens_.real();
    }
  }

  void add_cells() {
    const bool unlabelled = std::any_of(cells_.begin(), cells_.end(), [](const Item& c) { return c.ref == 0; });
    for (const Item& c : cells_)
      soup_.add_cell(c.corners == 4 ? LinearCell::Tetrahedron : LinearCell::Hexahedron,
                     std::span(corners_).subspan(c.first, c.corners),
                     static_cast<Index>(unlabelled ? c.ref + 1 : c.ref));
  }

  // Tags in the order of their references.
  void add_faces() {
    const std::map<long long, std::string> names = boundary_names(text_);
    std::map<long long, Index> tag;
    for (const Item& f : faces_) tag.emplace(f.ref, 0);
    for (auto& [ref, index] : tag) {
      index = static_cast<Index>(soup_.tag_names.size());
      const auto name = names.find(ref);
      soup_.tag_names.push_back(name != names.end() ? name->second : "ref_" + std::to_string(ref));
    }
    for (const Item& f : faces_)
      soup_.add_tagged_face(std::span(corners_).subspan(f.first, f.corners), tag.at(f.ref));
  }

  std::string text_;
  msh::Tokens tokens_;
  CellSoup soup_;
  std::vector<Item> cells_, faces_;
  std::vector<Index> corners_;
};

}  // namespace

PolyMesh read_medit(const std::filesystem::path& path) { return MeditReader(path).read(); }

}  // namespace volmesh
