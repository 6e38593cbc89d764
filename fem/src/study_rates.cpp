#include <algorithm>
#include <cmath>
#include <limits>

#include "volmesh/fem/study.hpp"

namespace volmesh::fem {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool usable(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

std::vector<double> pairwise_rates(std::span<const double> h, std::span<const double> error) {
  const std::size_t n = std::min(h.size(), error.size());
  std::vector<double> rates;
  for (std::size_t i = 1; i < n; ++i) {
    const bool ok = usable(h[i - 1]) && usable(h[i]) && usable(error[i - 1]) &&
                    usable(error[i]) && h[i - 1] != h[i];
    rates.push_back(ok ? std::log(error[i - 1] / error[i]) / std::log(h[i - 1] / h[i]) : kNaN);
  }
  return rates;
}

double least_squares_slope(std::span<const double> h, std::span<const double> error) {
  const std::size_t n = std::min(h.size(), error.size());
  // Centred sums: the logs of small errors are large and alike, and the uncentred normal
  // equations would lose digits to cancellation.
  std::vector<double> x, y;
  for (std::size_t i = 0; i < n; ++i)
    if (usable(h[i]) && usable(error[i])) {
      x.push_back(std::log(h[i]));
      y.push_back(std::log(error[i]));
    }
  if (x.size() < 2) return kNaN;
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(x.size());
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  return sxx > 0.0 ? sxy / sxx : kNaN;
}

const char* norm_name(Norm norm) {
  switch (norm) {
    case Norm::l2: return "L2";
    case Norm::linf: return "Linf";
    case Norm::h1: return "H1";
  }
  return "";
}

double norm_value(const ErrorNorms& errors, Norm norm) {
  switch (norm) {
    case Norm::l2: return errors.l2;
    case Norm::linf: return errors.linf;
    case Norm::h1: return errors.h1;
  }
  return kNaN;
}

SeriesRates convergence_rates(const ConvergenceSeries& series) {
  std::vector<double> h;
  for (const LevelResult& r : series.levels) h.push_back(r.h);
  SeriesRates rates;
  for (std::size_t k = 0; k < kNorms.size(); ++k) {
    std::vector<double> e;
    for (const LevelResult& r : series.levels) e.push_back(norm_value(r.errors, kNorms[k]));
    rates.pairwise[k] = pairwise_rates(h, e);
    rates.slope[k] = least_squares_slope(h, e);
  }
  return rates;
}

}  // namespace volmesh::fem
