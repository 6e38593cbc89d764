#pragma once
// Reading and writing triangulated surfaces: STL (ascii and binary), OFF, OBJ, PLY.
// Readers throw InputError with one line naming the file and what is wrong; they check
// syntax and indices only. Geometric and topological checks are in
// volmesh/geometry/surface_check.hpp.
// Counts in headers are checked against the file size and the 32-bit index limit before
// anything is allocated. Polygons with more than three corners (OFF, OBJ, PLY) are split into
// fans around their first corner, which is right for convex polygons.
#include <filesystem>

#include "volmesh/core/tri_surface.hpp"

namespace volmesh {

// Chooses the format from the extension (.stl .off .obj .ply, case-insensitive).
TriSurface read_surface(const std::filesystem::path& path);
void write_surface(const TriSurface& surface, const std::filesystem::path& path);

bool is_surface_file(const std::filesystem::path& path);

// STL: ASCII or binary (told apart by the file size, not by a leading "solid"); corners with
// equal coordinates are merged, numbered in order of first appearance.
TriSurface read_stl(const std::filesystem::path& path);
TriSurface read_off(const std::filesystem::path& path);
TriSurface read_obj(const std::filesystem::path& path);
TriSurface read_ply(const std::filesystem::path& path);

// Writers refuse a surface with out-of-range indices and leave no partial file behind.
void write_stl(const TriSurface& surface, const std::filesystem::path& path);  // binary, float
void write_off(const TriSurface& surface, const std::filesystem::path& path);
void write_obj(const TriSurface& surface, const std::filesystem::path& path);
void write_ply(const TriSurface& surface, const std::filesystem::path& path);  // binary LE

}  // namespace volmesh
