#pragma once
// Rebuilding a face-based PolyMesh from cells given by their own faces, as element and
// polyhedral file formats store them (VTU, Gmsh): the one face-matching mechanism behind
// the mesh readers and the element-mesh conversions.
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// Linear cells with corners in VTK order.
enum class LinearCell { Tetrahedron, Hexahedron, Wedge, Pyramid };

// Cells as lists of outward face loops, plus tagged faces (e.g. Gmsh surface elements)
// that name the boundary patches.
class CellSoup {
 public:
  // `source` names the file in error messages.
  explicit CellSoup(std::string source) : source_(std::move(source)) {}

  std::vector<Vec3> points;  // filled before cells are added; corners index into it
  std::vector<std::string> tag_names;

  // Adds a face loop (outward from the cell being built); close the cell with end_cell().
  void add_face(std::span<const Index> loop);
  void end_cell(Index region);
  void add_cell(LinearCell kind, std::span<const Index> corners, Index region);
  // A face carrying boundary tag `tag`, matched with a cell face by vertex set.
  void add_tagged_face(std::span<const Index> loop, Index tag);

  Index num_cells() const { return static_cast<Index>(cell_region_.size()); }

 private:
  friend PolyMesh cells_to_poly(CellSoup soup);
  std::string source_;
  std::vector<Index> cell_region_;
  std::vector<Index> cell_faces_{0};  // cell c: faces [cell_faces_[c], cell_faces_[c+1])
  std::vector<Index> face_offsets_{0};
  std::vector<Index> face_vertices_;
  std::vector<Index> tagged_offsets_{0};
  std::vector<Index> tagged_vertices_;
  std::vector<Index> tagged_tag_;
};

// Faces shared by two cells become internal faces, oriented as the first cell (in cell
// order) sees them; faces of one cell are boundary faces, tagged by a matching tagged face
// or else "boundary". Throws InputError naming the source when a face is used by more than two
// cells, a cell uses a face twice, two cells orient their shared face alike (one of them is
// inverted), or a face has fewer than three vertices.
PolyMesh cells_to_poly(CellSoup soup);

// Removes tag names that no boundary face uses, renumbering the others in order.
void drop_unused_tags(PolyMesh& mesh);

}  // namespace volmesh
