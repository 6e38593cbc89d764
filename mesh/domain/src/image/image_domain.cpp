// Labelled image as a Domain: regions and crossings (normals in image_normal.cpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "common/voxel_dda.hpp"
#include "volmesh/domain/image.hpp"

namespace volmesh {

using voxel::CellGrid;

namespace {

bool consistent(const LabelImage& image) {
  const auto& labels = image.labels;
  const auto& n = image.dims;
  return n[0] >= 1 && n[1] >= 1 && n[2] >= 1 &&
         static_cast<std::int64_t>(image.codes.size()) ==
             static_cast<std::int64_t>(n[0]) * n[1] * n[2] &&
         !labels.empty() && labels[0] == 0 && labels.size() <= 65536 &&
         std::adjacent_find(labels.begin(), labels.end(), std::greater_equal<>()) == labels.end() &&
         image.spacing.minCoeff() > 0.0 && image.spacing.allFinite() && image.origin.allFinite() &&
         std::all_of(image.codes.begin(), image.codes.end(),
                     [&](std::uint16_t c) { return c < labels.size(); });
}

// The voxels with a label other than 0, as [first, last] per axis (all voxels if none).
std::array<std::array<Index, 3>, 2> labelled_voxels(const LabelImage& image) {
  const auto& n = image.dims;
  std::array<Index, 3> first = n, last{-1, -1, -1};
  for (Index k = 0; k < n[2]; ++k)
    for (Index j = 0; j < n[1]; ++j) {
      const std::uint16_t* row = image.codes.data() + image.index(0, j, k);
      Index i0 = 0, i1 = n[0] - 1;
      while (i0 < n[0] && row[i0] == 0) ++i0;
      if (i0 == n[0]) continue;
      while (row[i1] == 0) --i1;
      first = {std::min(first[0], i0), std::min(first[1], j), std::min(first[2], k)};
      last = {std::max(last[0], i1), std::max(last[1], j), std::max(last[2], k)};
    }
  if (last[0] < 0) return {{{0, 0, 0}, {n[0] - 1, n[1] - 1, n[2] - 1}}};
  return {first, last};
}

}  // namespace

ImageDomain::ImageDomain(LabelImage image, double sigma_voxels) : image_(std::move(image)) {
  if (!consistent(image_) || !(sigma_voxels > 0.0))
    throw std::invalid_argument(
        "ImageDomain: inconsistent LabelImage (see make_label_image) or sigma <= 0");
  lo_ = image_.origin - 0.5 * image_.spacing;
  inv_spacing_ = image_.spacing.cwiseInverse();
  sigma_ = sigma_voxels * image_.spacing.maxCoeff();
  const auto [first, last] = labelled_voxels(image_);
  const Vec3 f(first[0], first[1], first[2]), l(last[0] + 1, last[1] + 1, last[2] + 1);
  bounds_ = {lo_ + f.cwiseProduct(image_.spacing), lo_ + l.cwiseProduct(image_.spacing)};
}

std::uint16_t ImageDomain::code_of_voxel(std::int64_t i, std::int64_t j, std::int64_t k) const {
  if (i < 0 || j < 0 || k < 0 || i >= image_.dims[0] || j >= image_.dims[1] || k >= image_.dims[2])
    return 0;
  return image_.codes[i + image_.dims[0] * (j + image_.dims[1] * k)];
}

// u: p in voxel units from lo_, inside the closed image box. The voxels whose closed boxes
// hold p are those at floor(u) and, on each axis where u is an integer, one lower.
std::uint16_t ImageDomain::tied_code(const Vec3& u) const {
  std::uint16_t best = 0;
  const std::int64_t i = static_cast<std::int64_t>(u.x()), j = static_cast<std::int64_t>(u.y()),
                     k = static_cast<std::int64_t>(u.z());
  for (std::int64_t dk = (u.z() == k ? -1 : 0); dk <= 0; ++dk)
    for (std::int64_t dj = (u.y() == j ? -1 : 0); dj <= 0; ++dj)
      for (std::int64_t di = (u.x() == i ? -1 : 0); di <= 0; ++di)
        best = std::max(best, code_of_voxel(i + di, j + dj, k + dk));
  return best;
}

std::uint16_t ImageDomain::code_at(const Vec3& p) const {
  const Vec3 u = (p - lo_).cwiseProduct(inv_spacing_);
  const auto& n = image_.dims;
  if (!(u.x() >= 0.0 && u.y() >= 0.0 && u.z() >= 0.0 && u.x() <= n[0] && u.y() <= n[1] &&
        u.z() <= n[2]))
    return 0;  // outside (or NaN)
  const Index i = static_cast<Index>(u.x()), j = static_cast<Index>(u.y()),
              k = static_cast<Index>(u.z());
  if (u.x() == i || u.y() == j || u.z() == k) return tied_code(u);  // on a voxel face: rare
  return image_
      .codes[i + static_cast<std::int64_t>(n[0]) * (j + static_cast<std::int64_t>(n[1]) * k)];
}

Index ImageDomain::region(const Vec3& p) const { return image_.labels[code_at(p)]; }

std::vector<Crossing> ImageDomain::crossings(const Vec3& a, const Vec3& b) const {
  std::vector<Crossing> out;
  const Vec3 d = b - a;
  const CellGrid grid{lo_, image_.spacing, image_.dims};
  const auto clip = voxel::clip_segment(grid.lo, grid.hi(), a, d);
  if (!clip) return out;

  std::uint16_t current = clip->t0 > 0.0 ? 0 : code_at(a);
  // A crossing at t into `code`; the crossed face (axis, plane) gives the exact coordinate
  // and the fallback normal where the smoothed gradient vanishes.
  const auto cross = [&](double t, int axis, double plane, std::uint16_t code) {
    Crossing c;
    c.t = t;
    c.point = a + t * d;
    if (axis >= 0) c.point[axis] = plane;
    c.before = image_.labels[current];
    c.after = image_.labels[code];
    Vec3 g = smoothed_gradient(c.point, current, code);
    // Agree with the voxel face actually crossed: a staircase can pass from one label into
    // the other against the smoothed interface's direction.
    if (axis >= 0 && g[axis] * d[axis] < 0.0) g = -g;
    if (g.norm() > 0.0) {
      c.normal = g.normalized();
    } else if (axis >= 0) {
      c.normal = Vec3::Unit(axis) * (d[axis] > 0.0 ? 1.0 : -1.0);
    } else {
      c.normal = d.normalized();
    }
    out.push_back(c);
    current = code;
  };
  voxel::for_each_piece(grid, a, d, *clip, [&](const voxel::Piece& piece) {
    const std::uint16_t code = code_at(a + 0.5 * (piece.t0 + piece.t1) * d);
    if (code != current) cross(piece.t0, piece.axis, piece.plane, code);
  });
  if (clip->t1 < 1.0) {
    const int axis = clip->axis1;  // leaving through the face of the box ahead
    if (current != 0) cross(clip->t1, axis, d[axis] > 0.0 ? grid.hi()[axis] : grid.lo[axis], 0);
  } else if (const std::uint16_t end = code_at(b); end != current) {
    cross(1.0, -1, 0.0, end);  // b on a voxel face, where the higher label wins
  }
  return out;
}

Box3 ImageDomain::bounds() const { return bounds_; }

std::vector<Index> ImageDomain::regions() const {
  return std::vector<Index>(image_.labels.begin() + 1, image_.labels.end());
}

}  // namespace volmesh
