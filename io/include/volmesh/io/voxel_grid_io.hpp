#pragma once
// Scalar grids (VoxelGrid, core/voxel_grid.hpp) from and to files.
//
// The .rawiv volume format (CVC's VolRover, used by the hex paper for signed-distance voxels):
// a 68-byte big-endian header, then dimX * dimY * dimZ big-endian float32 samples, x fastest.
//   float32 minX minY minZ maxX maxY maxZ   bounding box
//   uint32  numVerts numCells               dimX*dimY*dimZ, (dimX-1)*(dimY-1)*(dimZ-1)
//   uint32  dimX dimY dimZ
//   float32 originX originY originZ         position of sample (0, 0, 0)
//   float32 spanX spanY spanZ               spacing
// The geometry is read from origin and span; min/max are written as the grid's box and only
// checked for being finite on reading.
#include <filesystem>

#include "volmesh/core/voxel_grid.hpp"

namespace volmesh {

// By extension (case-insensitive): .rawiv, .vti (VTK image data: the point scalars, or the
// only point array, of one component), .nrrd (any sample type; stored as float). Throws
// InputError naming the file and the field on anything wrong.
VoxelGrid read_voxel_grid(const std::filesystem::path& path);
VoxelGrid read_vti(const std::filesystem::path& path);

// Throws InputError naming the file and the field: dims < 2 or too many samples, counts that
// disagree with the dims, spans <= 0, a file size other than 68 + 4 * samples, non-finite values.
VoxelGrid read_rawiv(const std::filesystem::path& path);
// Origin, spacing and values are stored as float32. Writes a temporary file, renamed at the end.
void write_rawiv(const VoxelGrid& grid, const std::filesystem::path& path);

}  // namespace volmesh
