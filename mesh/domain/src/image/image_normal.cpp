// Labelled-image normals: the gradient of a Gaussian-smoothed label indicator. The image is
// constant on voxel boxes, so the convolution of a voxel's indicator with the Gaussian is a
// product over axes of differences of the normal CDF at the voxel's two faces: exact and
// separable.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "volmesh/domain/image.hpp"

namespace volmesh {

namespace {

constexpr double kReach = 3.0;  // kernel truncation, in sigma: 4 sigma costs 2.4x for < 0.2 degrees

// Along one axis, for the voxels first .. first + w.size() - 1 around x: w = the smoothed
// indicator of the voxel's slab, dw = its derivative in x (both up to factors common to all
// axes).
struct AxisWeights {
  std::int64_t first = 0;
  std::vector<double> w, dw;
  double sum_w = 0.0, sum_dw = 0.0;
};

AxisWeights axis_weights(double x, double lo, double h, double sigma) {
  AxisWeights a;
  const double u = (x - lo) / h, r = kReach * sigma / h;
  a.first = static_cast<std::int64_t>(std::floor(u - r));
  const std::int64_t last = static_cast<std::int64_t>(std::floor(u + r));
  double cdf_prev = 0.0, pdf_prev = 0.0;
  for (std::int64_t m = a.first; m <= last + 1; ++m) {
    const double z = (x - (lo + m * h)) / sigma;  // from the face between voxels m - 1 and m
    const double cdf = 0.5 * std::erfc(-z / std::sqrt(2.0)), pdf = std::exp(-0.5 * z * z);
    if (m > a.first) {
      // Voxel m - 1 spans [face m - 1, face m]: Phi(z_{m-1}) - Phi(z_m), and its x-derivative.
      a.w.push_back(cdf_prev - cdf);
      a.dw.push_back(pdf_prev - pdf);
      a.sum_w += a.w.back();
      a.sum_dw += a.dw.back();
    }
    cdf_prev = cdf;
    pdf_prev = pdf;
  }
  return a;
}

}  // namespace

Vec3 ImageDomain::smoothed_gradient(const Vec3& p, std::uint16_t from, std::uint16_t to) const {
  std::array<AxisWeights, 3> ax;
  std::array<std::int64_t, 3> begin, end;  // the window's voxels inside the image
  for (int m = 0; m < 3; ++m) {
    ax[m] = axis_weights(p[m], lo_[m], image_.spacing[m], sigma_);
    begin[m] = std::max<std::int64_t>(ax[m].first, 0);
    end[m] = std::min<std::int64_t>(ax[m].first + static_cast<std::int64_t>(ax[m].w.size()),
                                    image_.dims[m]);
  }
  const auto weight = [&](std::uint16_t code) { return double(code == to) - double(code == from); };
  // Voxels outside the image are label 0 (code 0). Take the whole window as code 0 (separable:
  // a product of sums), then add the difference for the voxels inside the image.
  const double outside = weight(0);
  Vec3 g = outside * Vec3(ax[0].sum_dw * ax[1].sum_w * ax[2].sum_w,
                          ax[0].sum_w * ax[1].sum_dw * ax[2].sum_w,
                          ax[0].sum_w * ax[1].sum_w * ax[2].sum_dw);
  for (std::int64_t k = begin[2]; k < end[2]; ++k) {
    double sx_y = 0.0, dx_y = 0.0, sx_dy = 0.0;  // partial sums over x and y of this slice
    for (std::int64_t j = begin[1]; j < end[1]; ++j) {
      const std::uint16_t* row =
          image_.codes.data() + image_.index(0, static_cast<Index>(j), static_cast<Index>(k));
      const double* wx = ax[0].w.data() + (begin[0] - ax[0].first);
      const double* dwx = ax[0].dw.data() + (begin[0] - ax[0].first);
      double sx = 0.0, dx = 0.0;
      for (std::int64_t i = 0; i < end[0] - begin[0]; ++i) {
        const double w = weight(row[begin[0] + i]) - outside;
        sx += w * wx[i];
        dx += w * dwx[i];
      }
      sx_y += sx * ax[1].w[j - ax[1].first];
      dx_y += dx * ax[1].w[j - ax[1].first];
      sx_dy += sx * ax[1].dw[j - ax[1].first];
    }
    g += Vec3(dx_y * ax[2].w[k - ax[2].first], sx_dy * ax[2].w[k - ax[2].first],
              sx_y * ax[2].dw[k - ax[2].first]);
  }
  return g;
}

Vec3 ImageDomain::normal(const Vec3& p) const {
  // The nearest voxel centre with another label than p's, searched in boxes that grow up to
  // the kernel's reach: a box of half-size r holds every centre within r of p, so a find
  // within r is final. Near an interface the first box (one voxel) settles it.
  const std::uint16_t here = code_at(p);
  const Vec3 u = (p - image_.origin).cwiseProduct(inv_spacing_);  // voxel-centre units
  const double reach = kReach * sigma_;
  double best = std::numeric_limits<double>::infinity();
  std::uint16_t other = here;
  Vec3 towards = Vec3::UnitZ();
  for (double r = image_.spacing.maxCoeff();; r = std::min(2.0 * r, reach)) {
    std::array<std::int64_t, 3> lo, hi;
    for (int m = 0; m < 3; ++m) {
      lo[m] = static_cast<std::int64_t>(std::floor(u[m] - r * inv_spacing_[m]));
      hi[m] = static_cast<std::int64_t>(std::ceil(u[m] + r * inv_spacing_[m]));
    }
    for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
          const std::uint16_t code = code_of_voxel(i, j, k);
          if (code == here) continue;
          const Vec3 offset = (Vec3(i, j, k) - u).cwiseProduct(image_.spacing);
          if (offset.squaredNorm() < best)
            best = offset.squaredNorm(), other = code, towards = offset;
        }
    if (best <= r * r || r >= reach) break;
  }
  if (other == here) return Vec3::UnitZ();  // no interface within reach
  // Out of the higher label (priority) into the lower one.
  const std::uint16_t from = std::max(here, other), to = std::min(here, other);
  const Vec3 g = smoothed_gradient(p, from, to);
  if (g.norm() > 0.0) return g.normalized();
  return (from == here ? towards : -towards).normalized();
}

}  // namespace volmesh
