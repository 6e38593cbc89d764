// Progress on stderr: on a terminal (a pseudo-terminal here) every subcommand with long steps
// draws "label: stage [###   ]  NN%" in place and erases it when done; on a pipe or with
// --quiet nothing is drawn; an error is still one line.
#include <gtest/gtest.h>

#include <regex>

#include "run_volmesh.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;
using test::RunResult;

// As run_volmesh, with stderr on a pseudo-terminal (on_terminal.py).
RunResult run_on_terminal(const std::string& args, const fs::path& scratch) {
  const fs::path script = fs::path(VOLMESH_TEST_SOURCE) / "apps" / "on_terminal.py";
  const auto out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  const std::string cmd = "/usr/bin/python3 '" + script.string() + "' " + err.string() + " " +
                          VOLMESH_BINARY + " " + args + " >" + out.string() + " </dev/null";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = test::slurp(out);
  r.err = test::slurp(err);
  return r;
}

// One drawing of the progress line: back to the line's start, the text, erase the rest.
const std::regex kDrawing("\r[^\r\n]*\x1b\\[K");

// stderr without the progress drawings: what remains is what a pipe would get.
std::string without_progress(const std::string& err) {
  return std::regex_replace(err, kDrawing, "");
}

struct Case {
  std::string args;
  std::string stage;  // a drawing must show it
};

// A small case of every subcommand with long steps, each in its own scratch directory.
std::vector<Case> cases(const fs::path& dir) {
  const std::string d = dir.string(), cube = std::string(VOLMESH_TEST_DATA) + "/surfaces/cube.obj";
  return {
      {"mesh cutcell builtin:ball --level 3 -o " + d + "/ball.vtu", "cutcell: octree"},
      {"mesh tet-front builtin:ball --size 0.4 --interior delaunay -o " + d + "/front.vtu",
       "tet-front: sphere: building the Delaunay"},
      {"solve poisson --problem sine --method staircase --level 3 -o " + d + "/u.vtu",
       "solve: meshing: octree"},
      {"study convergence --problem sine --method grid --levels 1..2 -o " + d + "/study",
       "study: grid level 2: solving 64 cells: "},
      {"sdf " + cube + " --dim 9 -o " + d + "/cube.rawiv", "sdf: distances at 9^3 points"},
      {"check " + d + "/ball.vtu --surface " + cube, "check: distance to "},
      {"partition " + d + "/ball.vtu --parts 2 -o " + d + "/parts.pvtu", "partition: METIS"},
      {"demo -o " + d + "/demo --level 3 --study-levels 2..2", "demo: study: staircase level 2"},
  };
}

TEST(CliProgress, DrawnInPlaceOnATerminalAndErasedWhenDone) {
  const fs::path dir = test::scratch_dir("progress-terminal");
  for (const Case& c : cases(dir)) {
    const RunResult r = run_on_terminal(c.args, dir);
    ASSERT_EQ(r.exit_code, 0) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find("\r" + c.stage.substr(0, c.stage.find(':')) + ": "), std::string::npos)
        << c.args << "\n"
        << r.err;
    EXPECT_NE(r.err.find(c.stage), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find("%\x1b[K"), std::string::npos) << c.args << "\n" << r.err;
    // Every drawing is erased: the line ends empty, and the rest is what a pipe gets.
    const std::string rest = without_progress(r.err);
    EXPECT_EQ(rest.find('\r'), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_TRUE(rest.empty() || rest.rfind("wrote ", 0) == 0) << c.args << "\n" << r.err;
  }
}

TEST(CliProgress, NothingOnAPipeOrWithQuiet) {
  const fs::path dir = test::scratch_dir("progress-quiet");
  for (const Case& c : cases(dir)) {
    for (const bool terminal : {false, true}) {
      const RunResult r =
          terminal ? run_on_terminal(c.args + " --quiet", dir) : run_volmesh(c.args, dir);
      ASSERT_EQ(r.exit_code, 0) << c.args << "\n" << r.err;
      EXPECT_EQ(r.err.find('\r'), std::string::npos) << c.args << "\n" << r.err;
      EXPECT_EQ(r.err.find('%'), std::string::npos) << c.args << "\n" << r.err;
      // partition says what it wrote, once; the others say nothing.
      EXPECT_TRUE(r.err.empty() || (r.err.rfind("wrote ", 0) == 0 && test::count_lines(r.err) == 1))
          << c.args << "\n"
          << r.err;
    }
  }
}

// A failure part-way erases the line before the one error line.
TEST(CliProgress, AnErrorIsStillOneLine) {
  const fs::path dir = test::scratch_dir("progress-error");
  const RunResult r =
      run_on_terminal("mesh cutcell builtin:ball --level 0 -o " + (dir / "x.vtu").string(), dir);
  EXPECT_EQ(r.exit_code, 1);
  const std::string rest = without_progress(r.err);
  EXPECT_EQ(test::count_lines(rest), 1) << r.err;
  EXPECT_EQ(rest.rfind("volmesh: error: ", 0), 0u) << r.err;
  EXPECT_NE(rest.find("smaller than one cell"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.vtu"));
}

}  // namespace
}  // namespace volmesh
