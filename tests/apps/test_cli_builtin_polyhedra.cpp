// The polyhedral built-ins on the command line: Schönhardt's polyhedron and the twisted
// prisms mesh as surface domains, and bad parameters are refused with one line.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <tuple>

#include "run_volmesh.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

// K/6 (2 sin(2 pi / K) + sin(2 pi / K + w) - sin w), w the twist (builtin.hpp).
double twisted_prism_volume(int sides, double degrees) {
  const double a = 2.0 * std::numbers::pi / sides, w = degrees * std::numbers::pi / 180.0;
  return sides / 6.0 * (2.0 * std::sin(a) + std::sin(a + w) - std::sin(w));
}

TEST(CliBuiltinPolyhedra, CutcellMeshesSchoenhardtAndTwistedPrisms) {
  const fs::path dir = test::scratch_dir("builtin-polyhedra");
  const fs::path out = dir / "prism.vtu";
  for (const auto& [name, sides, degrees] :
       {std::tuple{"schoenhardt", 3, 30.0}, std::tuple{"twisted-prism:6:110", 6, 110.0}}) {
    const auto r = run_volmesh(std::string("mesh cutcell builtin:") + name +
                                   " --level 4 --json -o " + out.string(),
                               dir);
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["validity"]["valid"].get<bool>()) << name;
    EXPECT_TRUE(check_validity(read_mesh(out)).valid()) << name;
    const double exact = twisted_prism_volume(sides, degrees);
    EXPECT_NEAR(j["regions"]["1"]["volume"].get<double>(), exact, 0.02 * exact) << name;
  }
}

TEST(CliBuiltinPolyhedra, BadTwistsAreRefusedWithOneLine) {
  const fs::path dir = test::scratch_dir("builtin-polyhedra-bad");
  const fs::path out = dir / "prism.vtu";
  const auto r = run_volmesh("mesh cutcell builtin:twisted-prism:3:75 --level 3 -o " + out.string(), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err,
            "volmesh: error: builtin:twisted-prism:3:75: a twist of 75 degrees makes the surface "
            "self-intersect; twists must lie in (0, 60)\n");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace volmesh
