#pragma once
// A logarithmic axis fitted to the data with a small margin: where values map to pixels,
// where the ticks go (every 1..9 x 10^d inside the range) and which ones carry labels.
#include <string>
#include <vector>

namespace volmesh::plot {

struct Tick {
  double value;
  bool major;  // a power of ten
  bool labelled;
};

struct LogAxis {
  double lo = 0.0, hi = 1.0;        // log10 of the ends, hi > lo
  int pixel_lo = 0, pixel_hi = 1;   // pixels of the ends (either order)

  // [min, max] (0 < min <= max) widened by 5% of its span in log10 on both sides, and to at
  // least half a decade around a single value.
  static LogAxis covering(double min, double max, int pixel_lo, int pixel_hi);
  int pixel(double value) const;
  // Powers of ten are labelled (every k-th one when they would be closer than
  // `min_label_spacing` pixels); an axis with fewer than two of them labels 2 and 5 x 10^d too.
  std::vector<Tick> ticks(int min_label_spacing) const;
};

// Short tick labels: "0.05", "0.1", "20", else "1e-05" style.
std::string tick_label(double value);

}  // namespace volmesh::plot
