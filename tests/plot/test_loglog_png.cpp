// Log-log PNG charts: a real PNG that libgd decodes back, with the series drawn in their
// colours where their data lie, the reference slopes dashed, the same bytes every time.
#include <gd.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>

#include "volmesh/core/errors.hpp"
#include "volmesh/plot/loglog_png.hpp"

namespace volmesh::plot {
namespace {

using Image = std::unique_ptr<gdImage, decltype(&gdImageDestroy)>;

Image decode(std::vector<std::uint8_t>& png) {
  return Image(gdImageCreateFromPngPtr(static_cast<int>(png.size()), png.data()), gdImageDestroy);
}

int rgb_at(gdImagePtr im, int x, int y) {
  const int c = gdImageGetTrueColorPixel(im, x, y);
  return gdTrueColorGetRed(c) << 16 | gdTrueColorGetGreen(c) << 8 | gdTrueColorGetBlue(c);
}

// Pixels of one colour, in the right half of the image (away from the legend, top left).
std::vector<std::pair<int, int>> pixels_of(gdImagePtr im, std::uint32_t rgb, int x_from) {
  std::vector<std::pair<int, int>> found;
  for (int y = 0; y < gdImageSY(im); ++y)
    for (int x = x_from; x < gdImageSX(im); ++x)
      if (rgb_at(im, x, y) == static_cast<int>(rgb)) found.emplace_back(x, y);
  return found;
}

LogLogChart convergence_chart() {
  LogLogChart c;
  c.title = "sine on builtin:ball";
  c.x_label = "h";
  c.y_label = "error";
  const std::vector<double> h{0.5, 0.25, 0.125, 0.0625};
  Series first{"first order", h, {}}, second{"second order", h, {}};
  for (double x : h) {
    first.y.push_back(0.3 * x);
    second.y.push_back(0.2 * x * x);
  }
  c.series = {first, second};
  c.reference_slopes = {1.0, 2.0};
  return c;
}

TEST(LogLogPng, IsAPngOfTheRequestedSize) {
  LogLogChart chart = convergence_chart();
  chart.width = 640;
  chart.height = 480;
  std::vector<std::uint8_t> png = render_loglog_png(chart);
  const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(std::memcmp(png.data(), signature, 8), 0);
  const Image im = decode(png);
  ASSERT_NE(im, nullptr);
  EXPECT_EQ(gdImageSX(im.get()), 640);
  EXPECT_EQ(gdImageSY(im.get()), 480);
}

TEST(LogLogPng, SeriesAreDrawnInTheirColoursAlongTheirData) {
  LogLogChart chart = convergence_chart();
  std::vector<std::uint8_t> png = render_loglog_png(chart);
  const Image im = decode(png);
  ASSERT_NE(im, nullptr);
  const int half = chart.width / 2;
  for (int s = 0; s < 2; ++s) {
    const auto pixels = pixels_of(im.get(), series_colour(s), half);
    // A 2-pixel line across a fair part of the plot, not just a legend swatch.
    ASSERT_GT(pixels.size(), 300u) << "series " << s;
    // Error grows with h: the line rises (smaller pixel y) to the right.
    const auto [left, right] = std::minmax_element(pixels.begin(), pixels.end());
    EXPECT_GT(left->second, right->second) << "series " << s;
  }
  // The second-order series lies below the first-order one at the finest h (left end).
  auto lowest_left = [&](int s) {
    auto pixels = pixels_of(im.get(), series_colour(s), 0);
    std::erase_if(pixels, [&](auto p) { return p.second < chart.height / 2; });  // no legend
    return *std::min_element(pixels.begin(), pixels.end());
  };
  EXPECT_GT(lowest_left(1).second, lowest_left(0).second);
  // Dashed reference lines in grey.
  EXPECT_GT(pixels_of(im.get(), 0x555555, 0).size(), 200u);
}

TEST(LogLogPng, AnUnusedColourIsAbsentAndNonPositivePointsAreLeftOut) {
  LogLogChart chart = convergence_chart();
  chart.series[1].y = {0.0, -1.0, std::nan(""), 0.0};  // nothing drawable
  chart.series[1].label = "";
  std::vector<std::uint8_t> png = render_loglog_png(chart);
  const Image im = decode(png);
  ASSERT_NE(im, nullptr);
  EXPECT_GT(pixels_of(im.get(), series_colour(0), 0).size(), 300u);
  // Only the legend swatch shows series 1's colour: no line through the plot.
  EXPECT_LT(pixels_of(im.get(), series_colour(1), chart.width / 2).size(), 5u);
}

TEST(LogLogPng, SameChartSameBytes) {
  const LogLogChart chart = convergence_chart();
  EXPECT_EQ(render_loglog_png(chart), render_loglog_png(chart));
  LogLogChart other = chart;
  other.series[0].y[2] *= 2.0;
  EXPECT_NE(render_loglog_png(chart), render_loglog_png(other));
}

TEST(LogLogPng, RefusesAChartWithNothingToDraw) {
  LogLogChart chart;
  chart.title = "empty";
  chart.series = {Series{"zeros", {1.0, 0.5}, {0.0, 0.0}}};
  EXPECT_THROW(render_loglog_png(chart), InputError);
  chart = convergence_chart();
  chart.width = 100;
  EXPECT_THROW(render_loglog_png(chart), InputError);
}

}  // namespace
}  // namespace volmesh::plot
