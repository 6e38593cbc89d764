#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "volmesh/quality/histogram.hpp"

namespace volmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(Histogram, BinsAreHalfOpenWithTheLastClosed) {
  Histogram h = make_histogram(0, 180, 18);
  ASSERT_EQ(h.counts.size(), 18u);
  for (double v : {0.0, 9.999, 10.0, 179.0, 180.0}) add_to_histogram(h, v);
  EXPECT_EQ(h.counts[0], 2);
  EXPECT_EQ(h.counts[1], 1);
  EXPECT_EQ(h.counts[17], 2);
}

TEST(Histogram, OutliersAndInfinitiesGoToTheEndBinsAndNaNNowhere) {
  Histogram h = make_histogram(-1, 1, 20);
  for (double v : {-5.0, -kInf, 7.0, kInf, kNaN}) add_to_histogram(h, v);
  EXPECT_EQ(h.counts.front(), 2);
  EXPECT_EQ(h.counts.back(), 2);
  Index total = 0;
  for (Index c : h.counts) total += c;
  EXPECT_EQ(total, 4);
}

TEST(Histogram, ZeroWidthRangeCountsInTheFirstBin) {
  Histogram h = make_histogram(2, 2, 5);
  add_to_histogram(h, 2.0);
  add_to_histogram(h, 3.0);
  EXPECT_EQ(h.counts[0], 2);
}

TEST(Histogram, RejectsBadRanges) {
  EXPECT_THROW(make_histogram(0, 1, 0), std::invalid_argument);
  EXPECT_THROW(make_histogram(1, 0, 4), std::invalid_argument);
}

TEST(Summary, SkipsNotApplicableValues) {
  const std::vector<double> v{kNaN, 3.0, 1.0, kNaN, 2.0};
  const MetricSummary s = summarize("x", v, make_histogram(0, 4, 4));
  EXPECT_EQ(s.name, "x");
  EXPECT_EQ(s.count, 3);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 3.0);
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_EQ(s.histogram.counts, (std::vector<Index>{0, 1, 1, 1}));
}

TEST(Summary, EmptyHasNaNExtremes) {
  const MetricSummary s = summarize("x", std::vector<double>{kNaN}, make_histogram(0, 1, 2));
  EXPECT_EQ(s.count, 0);
  EXPECT_TRUE(std::isnan(s.min) && std::isnan(s.max) && std::isnan(s.mean));
}

}  // namespace
}  // namespace volmesh
