#pragma once
// Labelled images (LabelImage, core/label_image.hpp) from and to INRIA .inr / .inr.gz and
// NRRD files, and from memory: every way in goes through the same checks and the same
// palette encoding of voxel values into labels.
#include <array>
#include <filesystem>
#include <span>

#include "volmesh/core/label_image.hpp"

namespace volmesh {

// From one label per voxel, x fastest: labels are integers >= 0, at most 65536 distinct ones,
// at most 2^31 - 1 voxels. Throws InputError (naming "label image") otherwise.
LabelImage make_label_image(const std::array<Index, 3>& dims, const Vec3& spacing,
                            const Vec3& origin, std::span<const Index> voxel_labels);

// .inr, .inr.gz or .nrrd, by extension (case-insensitive). Sample types: 8-, 16-, 32-bit
// integers and floats holding integer values >= 0. Throws InputError naming the file and the
// header field or voxel on anything wrong (dims, spacing, sample type, data size).
LabelImage read_label_image(const std::filesystem::path& path);
// .inr, .inr.gz, or .nrrd (gzip encoding), in the smallest of uint8 / uint16 / int32 that
// holds the labels. The file is replaced atomically.
void write_label_image(const LabelImage& image, const std::filesystem::path& path);

}  // namespace volmesh
