#pragma once
// Volume measurements of a Domain for the analytic-domain tests: a deterministic line
// quadrature (exact chords from crossings(), midpoint rule across the lines) and Monte-Carlo.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "volmesh/domain/domain.hpp"

namespace volmesh::test {

// Region volumes from n x n lines along x through the bounds: the length of each region
// on a line is exact, the integral across lines is the midpoint rule. Faces that lie on
// cell boundaries of the line grid (the bounds' faces, say) cost no accuracy.
inline std::map<Index, double> line_quadrature_volumes(const Domain& d, int n) {
  const Box3 box = d.bounds();
  const Vec3 lo = box.lo, size = box.size();
  std::vector<Vec3> a, b;
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) {
      const Vec3 p(lo.x(), lo.y() + (j + 0.5) / n * size.y(), lo.z() + (k + 0.5) / n * size.z());
      a.push_back(p);
      b.push_back(p + Vec3(size.x(), 0, 0));
    }
  std::vector<std::vector<Crossing>> crossings;
  d.crossings(a, b, crossings);
  std::map<Index, double> volume;
  const double cross_section = size.y() * size.z() / (double(n) * n);
  for (std::size_t i = 0; i < a.size(); ++i) {
    Index current = d.region(a[i]);
    double t0 = 0.0;
    for (const Crossing& c : crossings[i]) {
      volume[current] += (c.t - t0) * size.x() * cross_section;
      current = c.after;
      t0 = c.t;
    }
    volume[current] += (1.0 - t0) * size.x() * cross_section;
  }
  volume.erase(0);
  return volume;
}

struct MonteCarloVolumes {
  std::map<Index, double> volume, sigma;  // estimate and its standard deviation
};

// Uniform samples in the bounds (fixed seed), classified with the batch region query.
inline MonteCarloVolumes monte_carlo_volumes(const Domain& d, int samples, unsigned seed) {
  const Box3 box = d.bounds();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> points(samples);
  for (Vec3& p : points)
    p = box.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.size());
  std::vector<Index> region(samples);
  d.region(points, region);
  std::map<Index, int> count;
  for (Index r : region) ++count[r];
  const double box_volume = box.size().prod();
  MonteCarloVolumes out;
  for (Index r : d.regions()) {
    const double p = double(count[r]) / samples;
    out.volume[r] = box_volume * p;
    out.sigma[r] = box_volume * std::sqrt(p * (1.0 - p) / samples);
  }
  return out;
}

// Both measurements against exact region volumes: Monte-Carlo within 4 sigma (fixed seed),
// the line quadrature within a relative tolerance.
inline void expect_region_volumes(const Domain& d, const std::map<Index, double>& exact,
                                  int samples, int lines, double quadrature_tolerance) {
  std::vector<Index> labels;
  for (const auto& [r, v] : exact) labels.push_back(r);
  EXPECT_EQ(d.regions(), labels);
  const MonteCarloVolumes mc = monte_carlo_volumes(d, samples, 12345);
  const std::map<Index, double> quadrature = line_quadrature_volumes(d, lines);
  for (const auto& [r, v] : exact) {
    EXPECT_NEAR(mc.volume.at(r), v, 4.0 * mc.sigma.at(r)) << "region " << r;
    EXPECT_NEAR(quadrature.at(r), v, quadrature_tolerance * v) << "region " << r;
  }
}

// A rotation from a random unit quaternion.
inline Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

}  // namespace volmesh::test
