// Abaqus .inp (flat input, no parts): *NODE, *ELEMENT (C3D4, C3D8), one *ELSET per region
// ("region_<r>"), and per boundary tag an *NSET and a *SURFACE, TYPE=ELEMENT of element-face
// pairs. Node and element numbers are the mesh's point and cell indices + 1. Set and surface
// names come from export_names().
//
// Linear C3D4 and C3D8 take VTK's corner order. Abaqus numbers the faces of an element
// (S1, S2, ...) by these node lists, each counter-clockwise seen from inside the element:
//   C3D4: S1 1-2-3, S2 1-4-2, S3 2-4-3, S4 3-4-1
//   C3D8: S1 1-2-3-4, S2 5-8-7-6, S3 1-5-6-2, S4 2-6-7-3, S5 3-7-8-4, S6 4-8-5-1
#include <algorithm>
#include <array>
#include <charconv>
#include <span>

#include "element_export.hpp"
#include "text_format.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {

namespace {

// Abaqus faces S1, S2, ... as VTK corner positions (0-based), from the table above.
constexpr std::array<std::array<int, 3>, 4> kAbaqusTetFaces{
    {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}}};
constexpr std::array<std::array<int, 4>, 6> kAbaqusHexFaces{
    {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}}};

// Each face as a bit mask of its corner positions, so that a face is found by its vertex set.
template <std::size_t N, std::size_t F>
constexpr std::array<unsigned, N> face_masks(const std::array<std::array<int, F>, N>& faces) {
  std::array<unsigned, N> masks{};
  for (std::size_t s = 0; s < N; ++s)
    for (int corner : faces[s]) masks[s] |= 1u << corner;
  return masks;
}
constexpr auto kTetFaceMasks = face_masks(kAbaqusTetFaces);
constexpr auto kHexFaceMasks = face_masks(kAbaqusHexFaces);

// Abaqus face number (1-based) of face f of its owner element `cell`.
int abaqus_face(const PolyMesh& mesh, const CellCorners& cell, Index f,
                const std::filesystem::path& path) {
  unsigned mask = 0;
  for (Index v : mesh.face(f)) {
    const auto it = std::find(cell.corners.begin(), cell.corners.end(), v);
    mask |= 1u << (it - cell.corners.begin());
  }
  const std::span<const unsigned> masks = cell.shape == CellShape::Tetrahedron
                                              ? std::span<const unsigned>(kTetFaceMasks)
                                              : std::span<const unsigned>(kHexFaceMasks);
  const auto it = std::find(masks.begin(), masks.end(), mask);
  if (it == masks.end())
    throw InputError(path.string() + ": boundary face " + std::to_string(f) +
                     " is not a face of its cell " + std::to_string(mesh.owner[f]));
  return static_cast<int>(it - masks.begin()) + 1;
}

// Abaqus reads at most 20 characters per floating-point field: the shortest round-trip form
// when it fits, else as many significant digits as fit (at least 13).
void append_abaqus_float(std::string& out, double value) {
  char buf[32];
  auto res = std::to_chars(buf, buf + sizeof buf, value);
  for (int digits = 16; res.ptr - buf > 20; --digits)
    res = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, digits);
  out.append(buf, res.ptr);
}

// Abaqus data lines hold at most 16 entries.
void append_id_lines(std::string& out, const std::vector<Index>& ids) {
  for (std::size_t i = 0; i < ids.size(); ++i) {
    append_number(out, ids[i] + 1);
    out += (i + 1) % 16 == 0 || i + 1 == ids.size() ? "\n" : ", ";
  }
}

void append_elements(std::string& out, const std::vector<CellCorners>& cells, CellShape shape,
                     const char* type, int corners) {
  bool any = false;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (cells[c].shape != shape) continue;
    if (!any) out += std::string("*ELEMENT, TYPE=") + type + "\n";
    any = true;
    append_number(out, static_cast<long long>(c) + 1);
    for (int k = 0; k < corners; ++k) {
      out += ", ";
      append_number(out, cells[c].corners[k] + 1);
    }
    out += '\n';
  }
}

}  // namespace

void write_abaqus(const PolyMesh& mesh, const std::filesystem::path& path) {
  const std::vector<CellCorners> cells =
      classify_elements(mesh, build_cell_faces(mesh), path, "Abaqus");
  const auto by_tag = boundary_faces_by_tag(mesh, path);
  const auto names = export_names(mesh.tag_names);

  std::string out = "*HEADING\nvolmesh mesh: " + std::to_string(mesh.num_points()) + " nodes, " +
                    std::to_string(mesh.num_cells()) + " elements\n*NODE\n";
  for (Index p = 0; p < mesh.num_points(); ++p) {
    append_number(out, p + 1);
    for (int k = 0; k < 3; ++k) {
      out += ", ";
      append_abaqus_float(out, mesh.points[p][k]);
    }
    out += '\n';
  }
  append_elements(out, cells, CellShape::Tetrahedron, "C3D4", 4);
  append_elements(out, cells, CellShape::Hexahedron, "C3D8", 8);

  for (const auto& [region, members] : cells_by_region(mesh)) {
    out += "*ELSET, ELSET=region_" + std::to_string(region) + "\n";
    append_id_lines(out, members);
  }
  for (std::size_t t = 0; t < by_tag.size(); ++t) {
    if (by_tag[t].empty()) continue;
    std::vector<Index> nodes;
    for (Index f : by_tag[t]) nodes.insert(nodes.end(), mesh.face(f).begin(), mesh.face(f).end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    out += "*NSET, NSET=" + names[t] + "\n";
    append_id_lines(out, nodes);

    out += "*SURFACE, TYPE=ELEMENT, NAME=" + names[t] + "\n";
    for (Index f : by_tag[t]) {
      const Index c = mesh.owner[f];
      append_number(out, c + 1);
      out += ", S";
      append_number(out, abaqus_face(mesh, cells[c], f, path));
      out += '\n';
    }
  }
  write_text_file(path, out);
}

}  // namespace volmesh
