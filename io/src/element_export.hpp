#pragma once
// Helpers shared by the writers of external formats (MEDIT, Abaqus, OpenFOAM): element shapes,
// boundary faces per tag, faces between regions, names those formats accept, and the atomic
// write of a text file.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// Writes `text` to `path` through a temporary file renamed at the end (AtomicOutput); throws
// InputError naming `path` when it cannot.
void write_text_file(const std::filesystem::path& path, std::string_view text);

// Shape and VTK-ordered corners of every cell. Throws InputError naming the first cell that is
// neither a tetrahedron nor a hexahedron, e.g.
//   "out.mesh: cell 12 is a polyhedron with 9 faces; MEDIT output takes tetrahedra and
//    hexahedra only (write it with --decompose tets)".
std::vector<CellCorners> classify_elements(const PolyMesh& mesh, const CellFaces& cell_faces,
                                           const std::filesystem::path& file,
                                           std::string_view format);

// Boundary faces of each tag (indexed like mesh.tag_names), in face order. Throws InputError
// naming `file` and the first boundary face whose tag is out of range.
std::vector<std::vector<Index>> boundary_faces_by_tag(const PolyMesh& mesh,
                                                      const std::filesystem::path& file);

// Cells of each region, by increasing region, each list in cell order.
std::map<Index, std::vector<Index>> cells_by_region(const PolyMesh& mesh);

// Internal faces between two different regions a < b, in face order; the interfaces are
// sorted by (a, b).
struct RegionInterface {
  Index region_a = 0, region_b = 0;
  std::vector<Index> faces;
};
std::vector<RegionInterface> region_interfaces(const PolyMesh& mesh);

// One name per input name, made of [A-Za-z0-9_], starting with a letter and distinct ignoring
// case, so that it is a valid OpenFOAM word and a valid Abaqus set or surface name (Abaqus
// names are case-insensitive and at most 80 characters). Other characters become '_'; a name
// not starting with a letter gets "tag_" in front; the result is cut to 64 characters; a name
// that clashes with an earlier one gets "_<index>" appended.
std::vector<std::string> export_names(const std::vector<std::string>& names);

}  // namespace volmesh
