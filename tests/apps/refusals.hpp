#pragma once
// The refusal contract of a command (exit 1, one line on stderr naming what is wrong, nothing
// written), checked for a list of argument strings.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "run_volmesh.hpp"

namespace volmesh::test {

// Each case is (arguments, a part of the expected message); `-o out` is appended to each.
inline void expect_refusals(const std::vector<std::pair<std::string, std::string>>& cases,
                            const std::filesystem::path& out,
                            const std::filesystem::path& scratch) {
  for (const auto& [args, message] : cases) {
    const auto r = run_volmesh(args + " -o " + out.string(), scratch);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_EQ(count_lines(r.err), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  }
}

}  // namespace volmesh::test
