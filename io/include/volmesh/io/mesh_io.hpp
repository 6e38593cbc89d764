#pragma once
// Volume mesh readers and writers. Every writer writes to a temporary name in the target's
// directory and renames it at the end, so a failed run never leaves a partial file.
#include <filesystem>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// An extra cell or point array written beside the mesh (VTU only).
struct Field {
  std::string name;
  int components = 1;
  std::vector<double> values;  // size = entities * components
};
struct IntField {
  std::string name;
  std::vector<Index> values;
};
struct MeshFields {
  std::vector<IntField> cell_ints;  // e.g. "partition"; "region" is always written
  std::vector<Field> cell;          // e.g. quality metrics, errors
  std::vector<Field> point;         // e.g. "u", "displacement"
};

// Writes by extension: .vtu, .msh (Gmsh 4.1), .mesh (MEDIT), .inp (Abaqus), or a directory
// ending in .foam (OpenFOAM case with constant/polyMesh). Element formats (msh, mesh, inp)
// take tetrahedra and hexahedra and throw InputError naming the first polyhedral cell
// (decompose_into_tets, geometry/tet_decomposition.hpp, makes any mesh tetrahedra).
void write_mesh(const PolyMesh& mesh, const std::filesystem::path& path,
                const MeshFields& fields = {});
// Throws the InputError write_mesh would for a path of no known output format: checked
// before a long run, so that a typo does not cost it.
void require_writable_mesh_path(const std::filesystem::path& path);
// Reads by extension: .vtu, .pvtu (a partitioned set, stitched: partitioned_io.hpp), .msh,
// .mesh (MEDIT), .node or .ele (TetGen), or an OpenFOAM case (a directory ending in .foam or
// holding constant/polyMesh, or its .foam marker file).
PolyMesh read_mesh(const std::filesystem::path& path);

bool is_mesh_file(const std::filesystem::path& path);

void write_vtu(const PolyMesh& mesh, const std::filesystem::path& path,
               const MeshFields& fields = {});
PolyMesh read_vtu(const std::filesystem::path& path);

void write_msh(const PolyMesh& mesh, const std::filesystem::path& path);
PolyMesh read_msh(const std::filesystem::path& path);

void write_medit(const PolyMesh& mesh, const std::filesystem::path& path);
// ASCII MEDIT: tetrahedra and hexahedra; references as write_medit writes them.
PolyMesh read_medit(const std::filesystem::path& path);
// TetGen's BASE.node and BASE.ele (and BASE.face when present), given either name.
PolyMesh read_tetgen(const std::filesystem::path& path);
void write_abaqus(const PolyMesh& mesh, const std::filesystem::path& path);
void write_foam(const PolyMesh& mesh, const std::filesystem::path& case_dir);
// ASCII constant/polyMesh (plain or .gz); cellZones "region_<r>" give regions, patches tags.
PolyMesh read_foam(const std::filesystem::path& case_dir);

}  // namespace volmesh
