#include <gtest/gtest.h>

#include <vector>

#include "volmesh/core/progress.hpp"

namespace volmesh {
namespace {

TEST(Progress, PartOfMapsFractionsAndPrefixesStages) {
  std::vector<std::pair<std::string, double>> seen;
  const Progress whole = [&](const std::string& stage, double f) { seen.emplace_back(stage, f); };
  const Progress second_half = part_of(whole, 0.5, 1.0, "solve: ");
  report(second_half, "assembly", 0.0);
  report(part_of(second_half, 0.5, 1.0, "cg: "), "iterations", 0.5);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].first, "solve: assembly");
  EXPECT_DOUBLE_EQ(seen[0].second, 0.5);
  EXPECT_EQ(seen[1].first, "solve: cg: iterations");
  EXPECT_DOUBLE_EQ(seen[1].second, 0.875);
  EXPECT_FALSE(part_of(Progress{}, 0.0, 1.0));
  report(Progress{}, "nothing", 0.0);  // no reporter: nothing happens
}

}  // namespace
}  // namespace volmesh
