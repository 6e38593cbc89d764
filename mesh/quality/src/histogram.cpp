#include "volmesh/quality/histogram.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace volmesh {

Histogram make_histogram(double lo, double hi, int bins) {
  if (bins < 1 || !(hi >= lo))
    throw std::invalid_argument("histogram: need bins >= 1 and lo <= hi");
  return {lo, hi, std::vector<Index>(static_cast<std::size_t>(bins), 0)};
}

void add_to_histogram(Histogram& histogram, double value) {
  if (std::isnan(value)) return;
  const auto n = histogram.counts.size();
  const double width = histogram.hi - histogram.lo;
  // Clamp in floating point before converting: ±inf and far outliers stay well defined.
  const double t = width > 0.0 ? (value - histogram.lo) / width * static_cast<double>(n) : 0.0;
  const std::size_t k = t <= 0.0                      ? 0
                        : t >= static_cast<double>(n) ? n - 1
                                                      : static_cast<std::size_t>(t);
  ++histogram.counts[k];
}

MetricSummary summarize(std::string name, std::span<const double> values, Histogram bins) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  MetricSummary s{std::move(name), 0, nan, nan, nan, std::move(bins)};
  double sum = 0.0;
  for (double v : values) {
    if (std::isnan(v)) continue;
    s.min = s.count == 0 ? v : std::min(s.min, v);
    s.max = s.count == 0 ? v : std::max(s.max, v);
    sum += v;
    ++s.count;
    add_to_histogram(s.histogram, v);
  }
  if (s.count > 0) s.mean = sum / s.count;
  return s;
}

}  // namespace volmesh
