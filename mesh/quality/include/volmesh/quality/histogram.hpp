#pragma once
// Histograms and summaries (count, extremes, mean) of one quality metric.
#include <span>
#include <string>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

// Uniform bins over [lo, hi]; bin k covers [lo + k·w, lo + (k+1)·w), the last bin is closed.
// Values below lo count in the first bin, values above hi (and +inf) in the last, so that
// every value is counted exactly once. A zero-width range puts everything in the first bin.
struct Histogram {
  double lo = 0.0, hi = 1.0;
  std::vector<Index> counts;
};
Histogram make_histogram(double lo, double hi, int bins);
// NaN (a metric that does not apply) is not counted.
void add_to_histogram(Histogram& histogram, double value);

// min/max/mean are NaN when count == 0; mean is +inf if any value is +inf.
struct MetricSummary {
  std::string name;
  Index count = 0;
  double min = 0.0, max = 0.0, mean = 0.0;
  Histogram histogram;
};
// Summary of the values that are not NaN, binned into `bins` (an empty histogram as made by
// make_histogram).
MetricSummary summarize(std::string name, std::span<const double> values, Histogram bins);

}  // namespace volmesh
