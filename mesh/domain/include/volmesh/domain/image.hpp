#pragma once
// Labelled images (segmentations) as domains: the voxel values are region labels, 0 being
// outside. The image comes from a file (label_image_io.hpp in io) or from memory.
#include <cstdint>
#include <vector>

#include "volmesh/core/label_image.hpp"
#include "volmesh/domain/domain.hpp"

namespace volmesh {

// The image as a Domain.
//  - region(p): the label of the voxel whose centre is nearest to p, 0 outside the image; on a
//    face (edge, corner) shared by voxels the highest label wins, so label value is priority.
//  - crossings: exact, where that label changes along the segment (a walk over the voxels
//    the segment passes); each crossing point lies on a voxel face. An end point on a face
//    gives a crossing at t = 0 or 1 where its (higher) label differs from the segment's next
//    to it. Not reported: a segment passing exactly through a voxel edge or corner whose
//    other voxels hold a higher label (the point alone has that label).
//  - normals: for labels A -> B, the gradient of G_sigma * (chi_B - chi_A), the indicator
//    difference convolved with an isotropic Gaussian, computed exactly for the piecewise
//    constant image and truncated at 3 sigma. sigma = sigma_voxels x the largest voxel size,
//    by default 1.5: on voxelised balls 4 to 13 voxels in radius the normals are then within
//    about 5 degrees of the true ones (9 to 12 with sigma_voxels = 1), while interfaces a few
//    voxels apart stay apart. (A kernel anisotropic like the voxels would be cheaper but errs
//    by up to 20 degrees on anisotropic images.) A crossing's normal is flipped if needed to
//    agree with the voxel face crossed (a staircase can step from A into B against the
//    smoothed direction). normal(p) uses the label at p and the nearest other label within
//    3 sigma (+z if there is none).
class ImageDomain final : public Domain {
 public:
  explicit ImageDomain(LabelImage image, double sigma_voxels = 1.5);

  using Domain::crossings;
  using Domain::region;
  Index region(const Vec3& p) const override;
  std::vector<Crossing> crossings(const Vec3& a, const Vec3& b) const override;
  Vec3 normal(const Vec3& p) const override;
  Box3 bounds() const override;  // the voxels with a label != 0
  std::vector<Index> regions() const override;

  const LabelImage& image() const { return image_; }
  double sigma() const { return sigma_; }  // the kernel's standard deviation

 private:
  std::uint16_t code_at(const Vec3& p) const;
  std::uint16_t tied_code(const Vec3& u) const;
  // Smoothed gradient of chi_to - chi_from (label codes); zero if nothing within reach.
  Vec3 smoothed_gradient(const Vec3& p, std::uint16_t from, std::uint16_t to) const;
  std::uint16_t code_of_voxel(std::int64_t i, std::int64_t j, std::int64_t k) const;

  LabelImage image_;
  Vec3 lo_, inv_spacing_;  // corner of voxel (0, 0, 0); 1 / spacing
  double sigma_;
  Box3 bounds_;
};

}  // namespace volmesh
