#include "volmesh/plot/loglog_png.hpp"

#include <gd.h>
#include <gdfontmb.h>
#include <gdfonts.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include "log_axis.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh::plot {

namespace {

// Tableau 10 order without its grey and olive, so that no series looks like the grid or the
// reference lines.
constexpr std::array<std::uint32_t, 8> kPalette{0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e,
                                                0x9467bd, 0x8c564b, 0xe377c2, 0x17becf};

int gd_colour(std::uint32_t rgb) {
  return gdTrueColor(static_cast<int>(rgb >> 16 & 0xff), static_cast<int>(rgb >> 8 & 0xff),
                     static_cast<int>(rgb & 0xff));
}

struct Point {
  double x, y;
};

bool drawable(double v) { return std::isfinite(v) && v > 0.0; }

std::vector<Point> drawable_points(const Series& s) {
  std::vector<Point> points;
  const std::size_t n = std::min(s.x.size(), s.y.size());
  for (std::size_t i = 0; i < n; ++i)
    if (drawable(s.x[i]) && drawable(s.y[i])) points.push_back({s.x[i], s.y[i]});
  return points;
}

using Image = std::unique_ptr<gdImage, decltype(&gdImageDestroy)>;

// gd's string functions take unsigned char* but do not modify the text.
unsigned char* text(const std::string& s) {
  return reinterpret_cast<unsigned char*>(const_cast<char*>(s.c_str()));
}

int text_width(gdFontPtr font, const std::string& s) {
  return font->w * static_cast<int>(s.size());
}

void draw_marker(gdImagePtr im, int marker, int x, int y, int colour) {
  constexpr int r = 4;
  switch (marker % 4) {
    case 0:
      gdImageFilledEllipse(im, x, y, 2 * r + 1, 2 * r + 1, colour);
      break;
    case 1:
      gdImageFilledRectangle(im, x - r, y - r, x + r, y + r, colour);
      break;
    case 2: {
      gdPoint p[3] = {{x, y - r - 1}, {x - r - 1, y + r}, {x + r + 1, y + r}};
      gdImageFilledPolygon(im, p, 3, colour);
      break;
    }
    default: {
      gdPoint p[4] = {{x, y - r - 1}, {x + r + 1, y}, {x, y + r + 1}, {x - r - 1, y}};
      gdImageFilledPolygon(im, p, 4, colour);
      break;
    }
  }
}

// The plot area in pixels.
struct Frame {
  int left, top, right, bottom;
};

struct Styled {
  int colour, marker;
};

Styled style_of(const Series& s, int index) {
  const int c = s.colour >= 0 ? s.colour : index;
  return {gd_colour(series_colour(c)), s.marker >= 0 ? s.marker : index};
}

void draw_grid_and_ticks(gdImagePtr im, const Frame& f, const LogAxis& ax, const LogAxis& ay) {
  const int grid = gd_colour(0xdddddd), black = gd_colour(0x000000);
  gdFontPtr font = gdFontGetSmall();
  for (const Tick& t : ax.ticks(60)) {
    const int x = ax.pixel(t.value), length = t.major ? 7 : 3;
    if (t.major) gdImageLine(im, x, f.top + 1, x, f.bottom - 1, grid);
    gdImageLine(im, x, f.bottom, x, f.bottom - length, black);
    gdImageLine(im, x, f.top, x, f.top + length, black);
    if (!t.labelled) continue;
    const std::string label = tick_label(t.value);
    gdImageString(im, font, x - text_width(font, label) / 2, f.bottom + 6, text(label), black);
  }
  for (const Tick& t : ay.ticks(2 * font->h)) {
    const int y = ay.pixel(t.value), length = t.major ? 7 : 3;
    if (t.major) gdImageLine(im, f.left + 1, y, f.right - 1, y, grid);
    gdImageLine(im, f.left, y, f.left + length, y, black);
    gdImageLine(im, f.right, y, f.right - length, y, black);
    if (!t.labelled) continue;
    const std::string label = tick_label(t.value);
    gdImageString(im, font, f.left - 6 - text_width(font, label), y - font->h / 2, text(label),
                  black);
  }
  gdImageRectangle(im, f.left, f.top, f.right, f.bottom, black);
}

void draw_titles(gdImagePtr im, const LogLogChart& chart, const Frame& f) {
  const int black = gd_colour(0x000000);
  gdFontPtr bold = gdFontGetMediumBold(), font = gdFontGetSmall();
  gdImageString(im, bold, (f.left + f.right - text_width(bold, chart.title)) / 2,
                (f.top - bold->h) / 2, text(chart.title), black);
  gdImageString(im, font, (f.left + f.right - text_width(font, chart.x_label)) / 2,
                f.bottom + 10 + 2 * font->h, text(chart.x_label), black);
  gdImageStringUp(im, font, 8, (f.top + f.bottom + text_width(font, chart.y_label)) / 2,
                  text(chart.y_label), black);
}

// Dashed lines y = y0 (x / x0)^p over the data's x range, clipped to the plot area.
void draw_reference_slopes(gdImagePtr im, const LogLogChart& chart, const Frame& f,
                           const LogAxis& ax, const LogAxis& ay, Point anchor, double x_min,
                           double x_max) {
  const int grey = gd_colour(0x555555), white = gd_colour(0xffffff);
  int dash[10];
  std::fill(dash, dash + 6, grey);
  std::fill(dash + 6, dash + 10, gdTransparent);
  gdImageSetStyle(im, dash, 10);
  gdFontPtr font = gdFontGetSmall();
  for (double p : chart.reference_slopes) {
    const auto y_at = [&](double x) { return anchor.y * std::pow(x / anchor.x, p); };
    gdImageSetClip(im, f.left + 1, f.top + 1, f.right - 1, f.bottom - 1);
    gdImageLine(im, ax.pixel(x_min), ay.pixel(y_at(x_min)), ax.pixel(x_max),
                ay.pixel(y_at(x_max)), gdStyled);
    gdImageSetClip(im, 0, 0, gdImageSX(im) - 1, gdImageSY(im) - 1);
    // Label at the small-h end, kept inside the plot area.
    std::ostringstream label;
    label << "slope " << p;
    const int w = text_width(font, label.str());
    const int x = std::clamp(ax.pixel(x_min) + 4, f.left + 2, f.right - w - 2);
    const int y = std::clamp(ay.pixel(y_at(x_min)) + 2, f.top + 2, f.bottom - font->h - 2);
    gdImageFilledRectangle(im, x - 1, y, x + w, y + font->h - 1, white);
    gdImageString(im, font, x, y, text(label.str()), grey);
  }
}

void draw_series(gdImagePtr im, const std::vector<Point>& points, Styled style,
                 const LogAxis& ax, const LogAxis& ay) {
  gdImageSetThickness(im, 2);
  for (std::size_t i = 1; i < points.size(); ++i)
    gdImageLine(im, ax.pixel(points[i - 1].x), ay.pixel(points[i - 1].y), ax.pixel(points[i].x),
                ay.pixel(points[i].y), style.colour);
  gdImageSetThickness(im, 1);
  for (const Point& p : points) draw_marker(im, style.marker, ax.pixel(p.x), ay.pixel(p.y), style.colour);
}

struct Rect {
  int x0, y0, x1, y1;
  bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

// The corner of the plot area whose legend box covers the fewest samples of the drawn lines
// (ties: top left, bottom right, top right, bottom left).
Rect legend_box(const Frame& f, int width, int height,
                const std::vector<std::vector<Point>>& points, const LogAxis& ax,
                const LogAxis& ay) {
  const std::array<Rect, 4> corners{
      Rect{f.left + 10, f.top + 10, f.left + 10 + width, f.top + 10 + height},
      Rect{f.right - 10 - width, f.bottom - 10 - height, f.right - 10, f.bottom - 10},
      Rect{f.right - 10 - width, f.top + 10, f.right - 10, f.top + 10 + height},
      Rect{f.left + 10, f.bottom - 10 - height, f.left + 10 + width, f.bottom - 10}};
  std::array<int, 4> covered{};
  constexpr int kSamples = 64;
  for (const std::vector<Point>& series : points)
    for (std::size_t i = 0; i < series.size(); ++i) {
      const Point& b = series[i];
      const Point& a = i > 0 ? series[i - 1] : b;
      for (int k = 0; k <= kSamples; ++k) {
        const double t = static_cast<double>(k) / kSamples;
        const int x = static_cast<int>(std::lround((1 - t) * ax.pixel(a.x) + t * ax.pixel(b.x)));
        const int y = static_cast<int>(std::lround((1 - t) * ay.pixel(a.y) + t * ay.pixel(b.y)));
        for (std::size_t c = 0; c < corners.size(); ++c) covered[c] += corners[c].contains(x, y);
      }
    }
  return corners[static_cast<std::size_t>(std::min_element(covered.begin(), covered.end()) -
                                          covered.begin())];
}

void draw_legend(gdImagePtr im, const LogLogChart& chart, const Frame& f,
                 const std::vector<std::vector<Point>>& points, const LogAxis& ax,
                 const LogAxis& ay) {
  gdFontPtr font = gdFontGetSmall();
  int width = 0;
  for (const Series& s : chart.series) width = std::max(width, text_width(font, s.label));
  const int row = font->h + 4, n = static_cast<int>(chart.series.size());
  const Rect box = legend_box(f, width + 44, n * row + 6, points, ax, ay);
  gdImageFilledRectangle(im, box.x0, box.y0, box.x1, box.y1, gd_colour(0xffffff));
  gdImageRectangle(im, box.x0, box.y0, box.x1, box.y1, gd_colour(0x000000));
  for (int i = 0; i < n; ++i) {
    const Styled style = style_of(chart.series[i], i);
    const int x = box.x0, cy = box.y0 + 4 + i * row + row / 2;
    gdImageSetThickness(im, 2);
    gdImageLine(im, x + 6, cy, x + 30, cy, style.colour);
    gdImageSetThickness(im, 1);
    draw_marker(im, style.marker, x + 18, cy, style.colour);
    gdImageString(im, font, x + 38, cy - font->h / 2, text(chart.series[i].label),
                  gd_colour(0x000000));
  }
}

}  // namespace

std::uint32_t series_colour(int i) {
  const int n = static_cast<int>(kPalette.size());
  return kPalette[static_cast<std::size_t>(((i % n) + n) % n)];
}

std::vector<std::uint8_t> render_loglog_png(const LogLogChart& chart) {
  if (chart.width < 320 || chart.height < 240)
    throw InputError("plot '" + chart.title + "': " + std::to_string(chart.width) + " x " +
                     std::to_string(chart.height) + " pixels is too small (at least 320 x 240)");
  std::vector<std::vector<Point>> points;
  double x_min = std::numeric_limits<double>::infinity(), x_max = 0.0;
  double y_min = std::numeric_limits<double>::infinity(), y_max = 0.0;
  for (const Series& s : chart.series) {
    points.push_back(drawable_points(s));
    for (const Point& p : points.back()) {
      x_min = std::min(x_min, p.x), x_max = std::max(x_max, p.x);
      y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
    }
  }
  const auto first = std::find_if(points.begin(), points.end(),
                                  [](const auto& p) { return !p.empty(); });
  if (first == points.end())
    throw InputError("plot '" + chart.title + "': no series has a positive, finite point");
  const Point anchor = first->front();
  for (double p : chart.reference_slopes) {  // the reference lines fit in the y range too
    y_min = std::min({y_min, anchor.y * std::pow(x_min / anchor.x, p)});
    y_max = std::max({y_max, anchor.y * std::pow(x_max / anchor.x, p)});
  }

  const Frame f{80, 36, chart.width - 24, chart.height - 58};
  const LogAxis ax = LogAxis::covering(x_min, x_max, f.left, f.right);
  const LogAxis ay = LogAxis::covering(y_min, y_max, f.bottom, f.top);

  Image image(gdImageCreateTrueColor(chart.width, chart.height), gdImageDestroy);
  if (!image) throw std::bad_alloc();
  gdImagePtr im = image.get();
  gdImageFilledRectangle(im, 0, 0, chart.width - 1, chart.height - 1, gd_colour(0xffffff));
  draw_grid_and_ticks(im, f, ax, ay);
  draw_titles(im, chart, f);
  for (std::size_t i = 0; i < points.size(); ++i)
    draw_series(im, points[i], style_of(chart.series[i], static_cast<int>(i)), ax, ay);
  // After the series: a series of exactly a reference slope must not hide the line.
  draw_reference_slopes(im, chart, f, ax, ay, anchor, x_min, x_max);
  draw_legend(im, chart, f, points, ax, ay);

  int size = 0;
  void* png = gdImagePngPtr(im, &size);
  if (!png) throw std::bad_alloc();
  std::vector<std::uint8_t> bytes(static_cast<const std::uint8_t*>(png),
                                  static_cast<const std::uint8_t*>(png) + size);
  gdFree(png);
  return bytes;
}

}  // namespace volmesh::plot
