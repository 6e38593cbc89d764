// MEDIT ASCII .mesh (MeshVersionFormatted 2: double precision), as read by MMG, Gmsh, FreeFEM
// and meshio.
//
// Corner order: Tetrahedra and Hexahedra take VTK's order. MEDIT tets are positively oriented
// when det(p1-p0, p2-p0, p3-p0) > 0 (MMG's orvol, which MMG flips otherwise), as in VTK;
// hexes list the bottom quad, then the top quad above it, as in VTK.
// References: a cell's reference is its region (>= 1). A boundary face's reference is its tag
// + 1 (tags count from 0, and MEDIT reserves 0 for "no reference"); its normal points out of
// the mesh. Faces between regions a < b follow with references T+1, T+2, ... (T tags) in the
// order of the sorted pairs (a, b), oriented from a to b. Comment lines name every face
// reference (tag names as export_names() makes them).
#include <algorithm>

#include "element_export.hpp"
#include "text_format.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {

namespace {

// A boundary or interface face with its reference, reversed when `flip`.
struct SurfaceFace {
  Index face;
  Index ref;
  bool flip;
};

void append_section_header(std::string& out, const char* keyword, std::size_t count) {
  out += keyword;
  out += '\n';
  append_number(out, static_cast<long long>(count));
  out += '\n';
}

void append_cells(std::string& out, const std::vector<CellCorners>& cells, const PolyMesh& mesh,
                  CellShape shape, const char* keyword, int corners) {
  const auto count = std::count_if(cells.begin(), cells.end(),
                                   [&](const CellCorners& c) { return c.shape == shape; });
  if (count == 0) return;
  append_section_header(out, keyword, count);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (cells[c].shape != shape) continue;
    for (int k = 0; k < corners; ++k) {
      append_number(out, cells[c].corners[k] + 1);
      out += ' ';
    }
    append_number(out, mesh.cell_region[c]);
    out += '\n';
  }
}

void append_faces(std::string& out, const std::vector<SurfaceFace>& surface, const PolyMesh& mesh,
                  const char* keyword, std::size_t corners) {
  const auto count = std::count_if(surface.begin(), surface.end(), [&](const SurfaceFace& s) {
    return mesh.face(s.face).size() == corners;
  });
  if (count == 0) return;
  append_section_header(out, keyword, count);
  for (const SurfaceFace& s : surface) {
    const auto loop = mesh.face(s.face);
    if (loop.size() != corners) continue;
    for (std::size_t k = 0; k < corners; ++k) {
      append_number(out, (s.flip ? loop[(corners - k) % corners] : loop[k]) + 1);
      out += ' ';
    }
    append_number(out, s.ref);
    out += '\n';
  }
}

}  // namespace

void write_medit(const PolyMesh& mesh, const std::filesystem::path& path) {
  const std::vector<CellCorners> cells =
      classify_elements(mesh, build_cell_faces(mesh), path, "MEDIT");
  const auto by_tag = boundary_faces_by_tag(mesh, path);
  const auto interfaces = region_interfaces(mesh);

  std::string out = "MeshVersionFormatted 2\n\nDimension 3\n\n";
  std::vector<SurfaceFace> surface;
  const auto tags = static_cast<Index>(by_tag.size());
  const auto names = export_names(mesh.tag_names);
  out += "# References of Triangles and Quadrilaterals:\n";
  for (Index t = 0; t < tags; ++t) {
    out += "# " + std::to_string(t + 1) + " boundary " + names[t] + "\n";
    for (Index f : by_tag[t]) surface.push_back({f, t + 1, false});
  }
  for (std::size_t i = 0; i < interfaces.size(); ++i) {
    const RegionInterface& in = interfaces[i];
    const Index ref = tags + 1 + static_cast<Index>(i);
    out += "# " + std::to_string(ref) + " interface between regions " +
           std::to_string(in.region_a) + " and " + std::to_string(in.region_b) + "\n";
    for (Index f : in.faces)
      surface.push_back({f, ref, mesh.cell_region[mesh.owner[f]] != in.region_a});
  }
  out += '\n';

  append_section_header(out, "Vertices", mesh.points.size());
  for (const Vec3& p : mesh.points) {
    for (int k = 0; k < 3; ++k) {
      append_number(out, p[k]);
      out += ' ';
    }
    out += "0\n";
  }
  append_cells(out, cells, mesh, CellShape::Tetrahedron, "Tetrahedra", 4);
  append_cells(out, cells, mesh, CellShape::Hexahedron, "Hexahedra", 8);
  append_faces(out, surface, mesh, "Triangles", 3);
  append_faces(out, surface, mesh, "Quadrilaterals", 4);
  out += "End\n";

  write_text_file(path, out);
}

}  // namespace volmesh
