#include "log_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace volmesh::plot {
namespace {

// The axis extends beyond the data by kMarginShare of its span in log10 on both sides, and to
// at least kLeastSpan decades in all (a single value).
constexpr double kMarginShare = 0.05;
constexpr double kLeastSpan = 0.5;
// Tick values in [kPlainFrom, kPlainTo) are labelled as plain numbers ("0.05", "20"), the
// others in exponent form ("1e-05").
constexpr double kPlainFrom = 1e-3, kPlainTo = 1e4;

}  // namespace

LogAxis LogAxis::covering(double min, double max, int pixel_lo, int pixel_hi) {
  LogAxis a;
  a.lo = std::log10(min);
  a.hi = std::log10(max);
  const double margin = std::max(kMarginShare * (a.hi - a.lo), 0.5 * (kLeastSpan - (a.hi - a.lo)));
  a.lo -= margin;
  a.hi += margin;
  a.pixel_lo = pixel_lo;
  a.pixel_hi = pixel_hi;
  return a;
}

int LogAxis::pixel(double value) const {
  const double t = (std::log10(value) - lo) / (hi - lo);
  return static_cast<int>(std::lround(pixel_lo + t * (pixel_hi - pixel_lo)));
}

std::vector<Tick> LogAxis::ticks(int min_label_spacing) const {
  const int first = static_cast<int>(std::floor(lo)), last = static_cast<int>(std::ceil(hi));
  const double pixels_per_decade = std::abs(pixel_hi - pixel_lo) / (hi - lo);
  int step = 1;
  while (step * pixels_per_decade < min_label_spacing) ++step;
  int decades_inside = 0;
  for (int d = first; d <= last; ++d) decades_inside += d >= lo && d <= hi;
  std::vector<Tick> ticks;
  for (int d = first; d <= last; ++d)
    for (int m = 1; m <= 9; ++m) {
      const double l = d + std::log10(static_cast<double>(m));
      if (l < lo || l > hi) continue;
      const bool labelled = m == 1 ? (d % step + step) % step == 0
                                   : decades_inside < 2 && (m == 2 || m == 5);
      ticks.push_back({m * std::pow(10.0, d), m == 1, labelled});
    }
  return ticks;
}

std::string tick_label(double value) {
  char buffer[32];
  if (value >= kPlainFrom && value < kPlainTo)
    std::snprintf(buffer, sizeof buffer, "%.4g", value);
  else
    std::snprintf(buffer, sizeof buffer, "%.0e", value);
  return buffer;
}

}  // namespace volmesh::plot
