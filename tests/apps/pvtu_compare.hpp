#pragma once
// A serial VTU against a PVTU of the same solution, through VTK's readers (the serial one and
// vtkXMLPUnstructuredGridReader, external/pvtu_compare.py): cells and points matched by the
// pieces' "global_cell" and "global_point".
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "run_volmesh.hpp"

namespace volmesh::test {

// The relative tolerance of the solves (LinearSolverOptions::tolerance 1e-10) leaves the
// solutions of two solvers this close, relative to the solution's size.
inline constexpr double kSolutionAgreement = 1e-7;

// pvtu_compare.py's report (a JSON object) on the two files.
inline nlohmann::json compare_files(const std::filesystem::path& serial,
                                    const std::filesystem::path& parallel) {
  const std::string cmd = "/usr/bin/python3 '" + std::string(VOLMESH_TEST_SOURCE) +
                          "/apps/external/pvtu_compare.py' " + serial.string() + " " +
                          parallel.string() + " > " + (serial.parent_path() / "cmp.json").string();
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd << " (`make test` installs python3-vtk9)";
  return nlohmann::json::parse(test::slurp(serial.parent_path() / "cmp.json"));
}

// Every array of the serial file is in the parallel one, equal to the solver tolerance.
inline void expect_same_solution(const nlohmann::json& cmp) {
  EXPECT_EQ(cmp["serial_cells"], cmp["parallel_cells"]) << cmp;
  EXPECT_TRUE(cmp["cells_once"].get<bool>()) << cmp;
  for (const auto& [name, a] : cmp["arrays"].items()) {
    ASSERT_FALSE(a.is_null()) << name << " missing: " << cmp;
    EXPECT_LE(a["diff"].get<double>(), kSolutionAgreement * std::max(1.0, a["max"].get<double>()))
        << name << ": " << cmp;
  }
}

}  // namespace volmesh::test
