#pragma once
// Log-log charts as PNG images: the convergence plots of `volmesh study` (error against h,
// one line with markers per series, dashed reference slopes, decade ticks, legend, title).
#include <cstdint>
#include <string>
#include <vector>

namespace volmesh::plot {

struct Series {
  std::string label;
  std::vector<double> x, y;  // same length; points with a coordinate <= 0 or not finite are left out
  int colour = -1;           // index into the palette (series_colour); -1: the series' own index
  int marker = -1;           // 0 disc, 1 square, 2 triangle, 3 diamond; -1: the series' own index
};

struct LogLogChart {
  std::string title, x_label, y_label;
  std::vector<Series> series;
  // Dashed lines y ∝ x^slope through the first drawable point of the first series, over the
  // x range of the data, each labelled "slope p".
  std::vector<double> reference_slopes;
  int width = 800, height = 600;  // pixels, at least 320 x 240
};

// The chart encoded as PNG. Deterministic: the same chart gives the same bytes. Throws
// InputError when no series has a drawable point or the size is too small.
std::vector<std::uint8_t> render_loglog_png(const LogLogChart& chart);

// Palette colour i (0xRRGGBB), cycling: what render_loglog_png draws series with colour i in.
std::uint32_t series_colour(int i);

}  // namespace volmesh::plot
