#pragma once
// The --json `seconds` objects name every stage of a run: each present and non-negative,
// together the reported total up to a remainder (argument checks, the JSON itself).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace volmesh::test {

// A small share of the total, or a few milliseconds on a run that takes hardly any.
inline constexpr double kStageRemainderShare = 0.05;
inline constexpr double kStageRemainderSeconds = 0.01;

inline void expect_stages_add_up(const nlohmann::json& seconds,
                                 const std::vector<std::string>& stages) {
  ASSERT_TRUE(seconds.is_object()) << seconds;
  ASSERT_TRUE(seconds.contains("total")) << seconds;
  const double total = seconds["total"];
  double sum = 0.0;
  for (const std::string& stage : stages) {
    ASSERT_TRUE(seconds.contains(stage) && seconds[stage].is_number()) << stage << " " << seconds;
    EXPECT_GE(seconds[stage].get<double>(), 0.0) << stage;
    sum += seconds[stage].get<double>();
  }
  EXPECT_EQ(seconds.size(), stages.size() + 1) << "a stage not checked: " << seconds;
  EXPECT_LE(sum, total) << seconds;
  EXPECT_GE(sum, total * (1.0 - kStageRemainderShare) - kStageRemainderSeconds) << seconds;
}

}  // namespace volmesh::test
