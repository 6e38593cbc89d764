// volmesh study convergence end to end: the table, CSV, PNG and JSON agree with each other
// and show P1's second order; bad inputs give exit 1, one line, and no output directory.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "run_volmesh.hpp"
#include "stage_seconds.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  return fields;
}

std::uint32_t big_endian(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

TEST(CliStudy, GridP1StudyWritesConsistentCsvPngAndJson) {
  const fs::path dir = test::scratch_dir("study-grid");
  const fs::path out = dir / "p1";
  const auto r = run_volmesh(
      "study convergence --problem sine --method grid --tets --levels 1..3 -o " + out.string(),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("grid tets (p1)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("least-squares slope"), std::string::npos) << r.out;

  const auto csv = lines_of(test::slurp(out / "convergence.csv"));
  ASSERT_EQ(csv.size(), 4u);
  EXPECT_EQ(csv[0], "series,level,h,cells,dofs,l2,linf,h1,rate_l2,rate_linf,rate_h1");
  const auto last = csv_fields(csv[3]);
  ASSERT_EQ(last.size(), 11u) << csv[3];
  EXPECT_EQ(last[1], "3");
  EXPECT_EQ(std::stod(last[2]), 0.125);
  EXPECT_EQ(last[3], std::to_string(6 * 8 * 8 * 8));
  EXPECT_EQ(last[4], std::to_string(9 * 9 * 9));
  EXPECT_NEAR(std::stod(last[8]), 2.0, 0.15);  // L2 rate between levels 2 and 3

  const auto summary = nlohmann::json::parse(test::slurp(out / "summary.json"));
  ASSERT_EQ(summary["series"].size(), 1u);
  const auto& series = summary["series"][0];
  EXPECT_EQ(series["space"], "p1");
  EXPECT_EQ(series["levels"].size(), 3u);
  EXPECT_NEAR(series["slope"]["L2"].get<double>(), 2.0, 0.25);
  EXPECT_NEAR(series["slope"]["H1"].get<double>(), 1.0, 0.15);
  const double l2 = series["levels"][2]["l2"];
  EXPECT_NEAR(std::stod(last[5]), l2, 1e-9 * l2);  // the CSV keeps 10 digits

  const std::string png = test::slurp(out / "convergence.png");
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  EXPECT_EQ(big_endian(png, 16), 800u);
  EXPECT_EQ(big_endian(png, 20), 600u);

  // --json: the summary on stdout, the same figures as the file apart from the timings.
  const auto again = run_volmesh("study convergence --problem sine --method grid --tets "
                                 "--levels 1..3 --json -o " + (dir / "again").string(), dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const auto j = nlohmann::json::parse(again.out);
  EXPECT_EQ(j["series"][0]["slope"], series["slope"]);
  for (const auto& level : j["series"][0]["levels"])
    test::expect_stages_add_up(level["seconds"], {"mesh", "setup", "assembly", "preconditioner",
                                                  "solve", "errors"});
  EXPECT_EQ(test::slurp(dir / "again" / "convergence.csv"), test::slurp(out / "convergence.csv"));
  EXPECT_EQ(test::slurp(dir / "again" / "convergence.png"), png);
}

TEST(CliStudy, StaircaseSeriesOnTheBall) {
  const fs::path dir = test::scratch_dir("study-staircase");
  const auto r = run_volmesh("study convergence --problem sine --methods staircase --levels 2..3 "
                             "--json -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["domain"], "builtin:ball");
  const auto& s = j["series"][0];
  EXPECT_EQ(s["method"], "staircase");
  EXPECT_EQ(s["space"], "polyhedral");
  // Halving h multiplies the cells of a ball's octree by about 8.
  const double ratio = s["levels"][1]["cells"].get<double>() / s["levels"][0]["cells"].get<double>();
  EXPECT_GT(ratio, 4.0);
  EXPECT_LT(ratio, 12.0);
  EXPECT_LT(s["levels"][1]["l2"].get<double>(), s["levels"][0]["l2"].get<double>());
}

// Q1 on hexdc meshes of the ball, their boundary nodes projected onto the true sphere: second
// order in L2 (at least 1.8).
TEST(CliStudy, HexdcIsSecondOrderOnTheBall) {
#ifdef __SANITIZE_ADDRESS__
  // Three levels of hexdc's global optimisation take over the 600 s limit under the
  // sanitizers; hexdc's own unit tests run there, and this slope in the Release suite.
  GTEST_SKIP() << "a convergence study of hexdc: Release suite only";
#endif
  const fs::path dir = test::scratch_dir("study-hexdc");
  const auto r = run_volmesh("study convergence --problem sine --method hexdc --levels 3..5 "
                             "--json -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& s = j["series"][0];
  EXPECT_EQ(s["space"], "q1");
  EXPECT_GE(s["slope"]["L2"].get<double>(), 1.8);
  EXPECT_GE(s["slope"]["H1"].get<double>(), 0.9);
}

TEST(CliStudy, MethodsAreComparedInOneTable) {
  const fs::path dir = test::scratch_dir("study-compare");
  const fs::path out = dir / "out";
  const auto r = run_volmesh("study convergence --problem sine --methods staircase,cutcell "
                             "--levels 2..3 --json -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["series"].size(), 2u);
  EXPECT_EQ(j["series"][0]["method"], "staircase");
  EXPECT_EQ(j["series"][1]["method"], "cutcell");
  // The same h per level; the cut cells follow the sphere and err less.
  for (int i = 0; i < 2; ++i)
    EXPECT_EQ(j["series"][0]["levels"][i]["h"], j["series"][1]["levels"][i]["h"]);
  EXPECT_LT(j["series"][1]["levels"][1]["l2"].get<double>(),
            j["series"][0]["levels"][1]["l2"].get<double>());
  const auto csv = lines_of(test::slurp(out / "convergence.csv"));
  ASSERT_EQ(csv.size(), 5u);
  EXPECT_EQ(csv[1].rfind("staircase (polyhedral),2,", 0), 0u) << csv[1];
  EXPECT_EQ(csv[4].rfind("cutcell (polyhedral),3,", 0), 0u) << csv[4];
}

TEST(CliStudy, BadInputsGiveOneLineAndNoOutput) {
  const fs::path dir = test::scratch_dir("study-bad");
  const fs::path out = dir / "out";
  for (const auto& [args, what] : std::vector<std::pair<std::string, std::string>>{
           {"--problem sine --method grid --levels 5..3", "5..3"},
           {"--problem sine --method grid --levels two", "two"},
           {"--problem no-such --method grid --levels 1..2", "no-such"},
           {"--problem multi-material --method grid --levels 1..2", "no exact solution"},
           {"--source 1 --method grid --levels 1..2", "--exact"},
           {"--problem sine --method grid --domain builtin:ball --levels 1..2", "builtin:ball"}}) {
    const auto r = run_volmesh("study convergence " + args + " -o " + out.string(), dir);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  // Usage: no method, no levels, an unknown method.
  for (const std::string& args :
       std::vector<std::string>{"--problem sine --levels 1..2", "--problem sine --method grid",
                                "--problem sine --method fem --levels 1..2"}) {
    const auto r = run_volmesh("study convergence " + args + " -o " + out.string(), dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

}  // namespace
}  // namespace volmesh
