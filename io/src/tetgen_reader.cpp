// TetGen's .node/.ele pair (and its .face file when present), given either name.
//
// Points are numbered from the first index in .node (0 or 1) on. A tet's first attribute (the
// region attribute of `tetgen -A`) is its region, an integer; when some tet has none or 0,
// every region is the attribute + 1 (or 1 without attributes), since regions count from 1.
// Second-order tets (10 nodes) give their four corners. Faces of .face tag the boundary faces
// they match by their marker, named "marker_M" (in the order of the markers); TetGen's corner order is VTK's (the fourth
// corner above the first three, counter-clockwise).
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "msh_tokens.hpp"
#include "volmesh/core/cell_soup.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

constexpr int kLinearCorners = 4, kQuadraticCorners = 10;

class TetgenReader {
 public:
  explicit TetgenReader(const fs::path& path) : base_(path), soup_(path.string()) {
    base_.replace_extension();
  }

  PolyMesh read() {
    read_nodes(with(".node"));
    read_tets(with(".ele"));
    const fs::path faces = with(".face");
    if (fs::is_regular_file(faces)) read_faces(faces);
    PolyMesh mesh = cells_to_poly(std::move(soup_));
    drop_unused_tags(mesh);
    return mesh;
  }

 private:
  fs::path with(const char* extension) const {
    fs::path p = base_;
    p += extension;
    return p;
  }

  // A point number of the files, checked and made an index.
  Index point(msh::Tokens& tokens, const std::string& item) {
    const long long v = tokens.integer("a point number");
    const long long index = v - first_;
    if (index < 0 || index >= static_cast<long long>(soup_.points.size()))
      tokens.fail(item + ": point " + std::to_string(v) + " out of range (points " +
                  std::to_string(first_) + ".." +
                  std::to_string(first_ + static_cast<long long>(soup_.points.size()) - 1) + ")");
    return static_cast<Index>(index);
  }

  void read_nodes(const fs::path& path) {
    msh::Tokens tokens(path.string(), msh::read_text(path), '#');
    const long long n = tokens.count("number of points", 8);
    if (tokens.integer("a dimension") != 3) tokens.fail("only 3D points are read");
    const long long attributes = tokens.count("number of attributes", 2);
    const long long markers = tokens.integer("the boundary marker flag");
    if (markers != 0 && markers != 1) tokens.fail("boundary marker flag must be 0 or 1");
    soup_.points.reserve(static_cast<std::size_t>(n));
    for (long long i = 0; i < n; ++i) {
      const long long index = tokens.integer("a point number");
      if (i == 0) {
        if (index != 0 && index != 1) tokens.fail("points are numbered from 0 or 1, not " + std::to_string(index));
        first_ = index;
      } else if (index != first_ + i) {
        tokens.fail("point " + std::to_string(index) + " out of order (" +
                    std::to_string(first_ + i) + " expected)");
      }
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = tokens.real();
      if (!p.allFinite()) tokens.fail("point " + std::to_string(index) + ": coordinate is not finite");
      for (long long k = 0; k < attributes; ++k) tokens.real();
      if (markers) tokens.integer("a boundary marker");
      soup_.points.push_back(p);
    }
  }

  void read_tets(const fs::path& path) {
    msh::Tokens tokens(path.string(), msh::read_text(path), '#');
    const long long n = tokens.count("number of tetrahedra", 10);
    const long long corners = tokens.integer("nodes per tetrahedron");
    if (corners != kLinearCorners && corners != kQuadraticCorners)
      tokens.fail("tetrahedra with " + std::to_string(corners) + " nodes (4 or 10 are read)");
    const long long attributes = tokens.count("number of attributes", 2);
    if (n == 0) tokens.fail("no tetrahedra");
    std::vector<Index> cells;
    std::vector<double> regions;
    for (long long i = 0; i < n; ++i) {
      const std::string item = "tetrahedron " + std::to_string(tokens.integer("a tetrahedron number"));
      for (long long k = 0; k < corners; ++k) {
        const Index v = point(tokens, item);
        if (k < kLinearCorners) cells.push_back(v);
      }
      double region = 0.0;
      for (long long k = 0; k < attributes; ++k) {
        const double a = tokens.real();
        if (k == 0) region = a;
      }
      if (region != std::floor(region) || region < 0.0 || region >= static_cast<double>(kMaxIndex))
        tokens.fail(item + ": region attribute " + std::to_string(region) +
                    " (regions are integers >= 0)");
      regions.push_back(region);
    }
    const bool unlabelled = std::find(regions.begin(), regions.end(), 0.0) != regions.end();
    for (std::size_t c = 0; c < regions.size(); ++c)
      soup_.add_cell(LinearCell::Tetrahedron, std::span(cells).subspan(kLinearCorners * c, kLinearCorners),
                     static_cast<Index>(regions[c]) + (unlabelled ? 1 : 0));
  }

  void read_faces(const fs::path& path) {
    msh::Tokens tokens(path.string(), msh::read_text(path), '#');
    const long long n = tokens.count("number of faces", 8);
    const long long markers = tokens.integer("the boundary marker flag");
    if (markers != 0 && markers != 1) tokens.fail("boundary marker flag must be 0 or 1");
    std::vector<std::array<Index, 3>> loops;
    std::vector<long long> marker;
    for (long long i = 0; i < n; ++i) {
      const std::string item = "face " + std::to_string(tokens.integer("a face number"));
      std::array<Index, 3> loop;
      for (Index& v : loop) v = point(tokens, item);
      loops.push_back(loop);
      marker.push_back(markers ? tokens.integer("a boundary marker") : 0);
    }
    // Tags in the order of their markers.
    std::map<long long, Index> tags;
    for (const long long m : marker) tags.emplace(m, 0);
    for (auto& [m, tag] : tags) {
      tag = static_cast<Index>(soup_.tag_names.size());
      soup_.tag_names.push_back("marker_" + std::to_string(m));
    }
    for (std::size_t f = 0; f < loops.size(); ++f) soup_.add_tagged_face(loops[f], tags.at(marker[f]));
  }

  fs::path base_;
  CellSoup soup_;
  long long first_ = 0;
};

}  // namespace

PolyMesh read_tetgen(const fs::path& path) { return TetgenReader(path).read(); }

}  // namespace volmesh
