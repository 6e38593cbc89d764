// Golden regression outputs: each case's summary (golden_summary.hpp) recomputed and
// compared with the one stored in tests/golden/expected/<case>.json, so that a change of any
// mesher's or the solver's output fails `make test` naming every field that moved. With
// VOLMESH_GOLDEN_REGENERATE=1 (tests/golden/regenerate.sh) the summaries are written instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "golden_cases.hpp"
#include "golden_summary.hpp"

namespace volmesh::golden {

// Test names and failure messages show a case by its name.
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }

namespace {

namespace fs = std::filesystem;

fs::path stored_path(const GoldenCase& c) {
  return fs::path(VOLMESH_TEST_SOURCE) / "golden" / "expected" / (c.name + ".json");
}

bool regenerating() {
  const char* v = std::getenv("VOLMESH_GOLDEN_REGENERATE");
  return v != nullptr && std::string(v) == "1";
}

class Golden : public testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, SummaryMatchesTheStoredOne) {
  const GoldenCase& c = GetParam();
  if (!fs::exists(case_domain_spec(c)) && c.domain.starts_with("cgal:"))
    GTEST_SKIP() << case_domain_spec(c) << " is missing (make test installs libcgal-demo)";
  const auto domain = open_case_domain(c);
  const PolyMesh mesh = mesh_case(c, *domain);
  std::optional<fem::ScalarSolution> solution;
  if (!c.problem.empty()) solution = solve_case(c, *domain, mesh);
  const nlohmann::json now = case_summary(c, mesh, solution ? &*solution : nullptr);

  const fs::path path = stored_path(c);
  if (regenerating()) {
    std::ofstream out(path);
    out << now.dump(2) << "\n";
    ASSERT_TRUE(out.good()) << "could not write " << path;
    std::cout << "wrote " << path.string() << "\n";
    return;
  }
  std::ifstream in(path);
  ASSERT_TRUE(in) << path << " is missing: run tests/golden/regenerate.sh BUILD_DIR";
  const nlohmann::json stored = nlohmann::json::parse(in);
  const std::vector<std::string> moved = moved_fields(stored, now);
  std::string report;
  for (const std::string& line : moved) report += "\n  " + line;
  EXPECT_TRUE(moved.empty()) << c.name << ": " << moved.size() << " field(s) moved (figures beyond a relative "
                             << std::setprecision(1) << kRelativeTolerance << "; if the change is intended, run "
                             << "tests/golden/regenerate.sh BUILD_DIR and commit the new summaries):"
                             << report;
}

INSTANTIATE_TEST_SUITE_P(Cases, Golden, testing::ValuesIn(golden_cases()), [](const auto& info) {
  std::string name = info.param.name;
  std::replace(name.begin(), name.end(), '-', '_');
  std::replace(name.begin(), name.end(), '.', '_');  // a size's decimal point
  return name;
});

// Every stored summary belongs to a case: a case renamed or dropped leaves none behind (when
// regenerating, its summary is removed).
TEST(GoldenFiles, EveryStoredSummaryHasItsCase) {
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(fs::path(VOLMESH_TEST_SOURCE) / "golden" / "expected"))
    if (std::none_of(golden_cases().begin(), golden_cases().end(),
                     [&](const GoldenCase& c) { return stored_path(c) == entry.path(); }))
      stale.push_back(entry.path());
  for (const fs::path& p : stale) {
    if (regenerating()) {
      fs::remove(p);
      std::cout << "removed " << p.string() << "\n";
    } else {
      ADD_FAILURE() << p << " has no case in golden_cases()";
    }
  }
}

// The hash covers every array: changing one entry of any of them changes it.
TEST(GoldenHash, EveryArrayOfTheMeshCounts) {
  PolyMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Index tag = m.tag_index("wall");
  for (const std::array<Index, 3>& t : {std::array<Index, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}})
    m.add_face(t, 0, kNoIndex, tag);
  m.cell_region = {1};
  const std::string base = canonical_hash(m);
  EXPECT_EQ(canonical_hash(m), base);
  std::vector<PolyMesh> changed(8, m);
  changed[0].points[3].z() = std::nextafter(1.0, 2.0);
  changed[1].face_offsets[1] = 2;
  changed[2].face_vertices[0] = 1;
  changed[3].owner[0] = 1;
  changed[4].neighbour[0] = 0;
  changed[5].face_tag[0] = 1;
  changed[6].cell_region[0] = 2;
  changed[7].tag_names[0] = "walls";
  for (std::size_t k = 0; k < changed.size(); ++k) EXPECT_NE(canonical_hash(changed[k]), base) << "change " << k;
}

// moved_fields names each change: a count, a figure beyond the tolerance, a new and a gone
// field; figures within it pass.
TEST(GoldenCompare, NamesEveryMovedField) {
  const nlohmann::json stored = {{"mesh", {{"cells", 10}, {"total_volume", 1.0}, {"hash", "0x1"}}}, {"old", 1}};
  nlohmann::json now = stored;
  now["mesh"]["total_volume"] = 1.0 + 0.5 * kRelativeTolerance;
  EXPECT_TRUE(moved_fields(stored, now).empty());
  now["mesh"]["cells"] = 11;
  now["mesh"]["total_volume"] = 1.0 + 3.0 * kRelativeTolerance;
  now["mesh"]["hash"] = "0x2";
  now.erase("old");
  now["new"] = true;
  const std::vector<std::string> moved = moved_fields(stored, now);
  ASSERT_EQ(moved.size(), 5u);
  const auto names = [&](const std::string& prefix) {
    return std::any_of(moved.begin(), moved.end(), [&](const std::string& l) { return l.starts_with(prefix); });
  };
  EXPECT_TRUE(names("mesh.cells: 10 -> 11"));
  EXPECT_TRUE(names("mesh.total_volume: 1 -> 1.000000003"));
  EXPECT_TRUE(names("mesh.hash: \"0x1\" -> \"0x2\""));
  EXPECT_TRUE(names("old: 1 -> (gone)"));
  EXPECT_TRUE(names("new: (new) -> true"));
}

}  // namespace
}  // namespace volmesh::golden
