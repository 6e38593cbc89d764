// The mesher registry: every method meshes its default domain into a valid mesh whose
// summary counts match it, unknown names and misapplied options are refused, and the option
// declarations agree wherever a name recurs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/meshers/registry.hpp"

namespace volmesh::meshers {
namespace {

constexpr int kSmallLevel = 3;

MeshRequest at_level(int level, const std::string& domain_name) {
  MeshRequest r;
  r.domain_name = domain_name;
  r.level = level;
  return r;
}

// A value of the option's type inside its range or choices.
OptionValue valid_value(const OptionSpec& spec) {
  switch (spec.type) {
    case OptionSpec::Type::flag:
      return true;
    case OptionSpec::Type::integer:
      return static_cast<std::int64_t>(spec.min);
    case OptionSpec::Type::real:
      return spec.max;
    case OptionSpec::Type::choice:
      return spec.choices.back();
    case OptionSpec::Type::text:
      return std::string("text");
  }
  return false;
}

TEST(MesherRegistry, HoldsTheMethodsSortedAndUniquelyNamed) {
  const std::vector<MesherInfo>& all = meshers();
  ASSERT_GE(all.size(), 3u);
  for (const char* name : {"cutcell", "grid", "staircase"}) EXPECT_EQ(find_mesher(name).name, name);
  for (std::size_t i = 1; i < all.size(); ++i) EXPECT_LT(all[i - 1].name, all[i].name);
  for (const MesherInfo& m : all) {
    EXPECT_FALSE(m.description.empty()) << m.name;
    EXPECT_NE(m.run, nullptr) << m.name;
  }
}

constexpr double kSizeDivisions = 4.0;

TEST(MesherRegistry, EveryMethodMeshesItsDefaultDomainAndCountsMatch) {
  for (const MesherInfo& m : meshers()) {
    SCOPED_TRACE(m.name);
    const bool by_level = m.resolution == Resolution::level;
    const std::unique_ptr<Domain> domain = open_domain(m.default_domain);
    std::vector<double> fractions;
    MeshRequest request = at_level(kSmallLevel, m.default_domain);
    if (!by_level) request.level.reset();
    // A size method: a few edges across the domain.
    if (m.resolution == Resolution::size)
      request.size = domain->bounds().size().maxCoeff() / kSizeDivisions;
    request.progress = [&](const std::string& stage, double f) {
      EXPECT_FALSE(stage.empty());
      fractions.push_back(f);
    };
    const MeshResult r = mesh(m, *domain, request);
    const ValidityReport v = check_validity(r.mesh);
    EXPECT_TRUE(v.valid()) << (v.problems.empty() ? "" : v.problems.front());
    EXPECT_GT(r.mesh.num_cells(), 0);
    EXPECT_EQ(r.summary.at("cells").get<Index>(), r.mesh.num_cells());
    EXPECT_EQ(r.summary.at("faces").get<Index>(), r.mesh.num_faces());
    EXPECT_EQ(r.summary.at("vertices").get<Index>(), r.mesh.num_points());
    // h: the edge at the boundary, 2^-level of the domain's extent or a little more (the
    // octree root has a margin; hexdc's grid has at most a node and a little on each side,
    // so that 2^level - 2 nodes span the extent).
    // A surface method meshes the surface as it is: h is its longest edge.
    const double extent = domain->bounds().size().maxCoeff();
    EXPECT_GE(r.h, by_level ? std::ldexp(extent, -kSmallLevel) * (1.0 - 1e-12) : 0.0);
    EXPECT_LE(r.h, by_level ? extent / static_cast<double>((1 << kSmallLevel) - 2) * 1.01
                            : extent * std::sqrt(3.0));
    for (double f : fractions) EXPECT_TRUE(f >= 0.0 && f <= 1.0) << f;
    if (m.octree) {
      EXPECT_FALSE(fractions.empty());
    }
  }
}

TEST(MesherRegistry, MethodFiguresAgreeWithTheMesh) {
  const auto ball = open_domain("builtin:ball"), box = open_domain("builtin:box");
  MeshRequest request = at_level(2, "builtin:box");
  request.options["tets"] = true;
  const MeshResult grid = mesh(find_mesher("grid"), *box, request);
  EXPECT_EQ(grid.summary.at("cells_per_axis").get<Index>(), 4);
  EXPECT_EQ(grid.summary.at("element"), "tet");
  EXPECT_EQ(grid.mesh.num_cells(), 6 * 4 * 4 * 4);
  const MeshResult stairs =
      mesh(find_mesher("staircase"), *ball, at_level(kSmallLevel, "builtin:ball"));
  EXPECT_GE(stairs.summary.at("leaves").get<Index>(), stairs.mesh.num_cells());
  const MeshResult cut = mesh(find_mesher("cutcell"), *ball, at_level(kSmallLevel, "builtin:ball"));
  EXPECT_GT(cut.summary.at("cut_cells").get<Index>(), 0);
  EXPECT_LE(cut.summary.at("cut_cells").get<Index>(), cut.mesh.num_cells());
  EXPECT_EQ(cut.summary.at("interface_points"), "exact");
}

// Uniform: the octree's depth is the level everywhere, so every staircase cell has edge h.
TEST(MesherRegistry, UniformRequestsMeshAtOneDepth) {
  const auto ball = open_domain("builtin:ball");
  MeshRequest request = at_level(4, "builtin:ball");
  const MeshResult graded = mesh(find_mesher("staircase"), *ball, request);
  request.uniform = true;
  const MeshResult uniform = mesh(find_mesher("staircase"), *ball, request);
  EXPECT_EQ(uniform.h, graded.h);
  EXPECT_GT(uniform.mesh.num_cells(), graded.mesh.num_cells());
  const ValidityReport v = check_validity(uniform.mesh);
  EXPECT_NEAR(v.min_cell_volume, std::pow(uniform.h, 3), 1e-12);
  request.options["base-level"] = std::int64_t{2};
  EXPECT_THROW(mesh(find_mesher("staircase"), *ball, request), InputError);
}

TEST(MesherRegistry, UnknownNameListsTheKnownOnes) {
  try {
    find_mesher("no-such");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no-such"), std::string::npos) << what;
    for (const MesherInfo& m : meshers()) EXPECT_NE(what.find(m.name), std::string::npos) << what;
  }
}

TEST(MesherRegistry, ARequestWithoutItsResolutionIsRefused) {
  const auto box = open_domain("builtin:box");
  MeshRequest request;
  request.domain_name = "builtin:box";
  EXPECT_THROW(mesh(find_mesher("grid"), *box, request), InputError);
  request.level = 1;
  request.size = 0.5;
  EXPECT_THROW(mesh(find_mesher("grid"), *box, request), InputError);
}

// Options recur only with one meaning, and each method refuses the options it does not
// declare, naming the methods that take them.
TEST(MesherRegistry, OptionDeclarationsAreConsistent) {
  std::map<std::string, OptionSpec> by_name;
  for (const MesherInfo& m : meshers()) {
    std::set<std::string> names;
    for (const OptionSpec& s : options_of(m)) {
      SCOPED_TRACE(m.name + " --" + s.name);
      EXPECT_TRUE(names.insert(s.name).second) << "declared twice";
      EXPECT_FALSE(s.help.empty());
      if (s.type == OptionSpec::Type::choice) {
        EXPECT_FALSE(s.choices.empty());
      }
      if (s.type == OptionSpec::Type::integer || s.type == OptionSpec::Type::real) {
        EXPECT_LE(s.min, s.max);
      }
      EXPECT_NO_THROW(check_option(s, valid_value(s)));
      const auto [first, inserted] = by_name.emplace(s.name, s);
      if (!inserted) {
        EXPECT_EQ(first->second.type, s.type);
        EXPECT_EQ(first->second.min, s.min);
        EXPECT_EQ(first->second.max, s.max);
        EXPECT_EQ(first->second.choices, s.choices);
      }
    }
    if (!m.octree) {
      for (const OptionSpec& s : octree_options()) EXPECT_FALSE(names.contains(s.name)) << m.name;
    }
  }
  for (const MesherInfo& m : meshers())
    for (const auto& [name, spec] : by_name) {
      const MethodOptions given{{name, valid_value(spec)}};
      const std::vector<OptionSpec> taken = options_of(m);
      const bool declared = std::any_of(taken.begin(), taken.end(),
                                        [&](const OptionSpec& s) { return s.name == name; });
      if (declared) {
        EXPECT_NO_THROW(check_options(m, given)) << m.name << " --" << name;
        continue;
      }
      try {
        check_options(m, given);
        ADD_FAILURE() << m.name << " took --" << name;
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--" + name + " applies to the "), std::string::npos)
            << e.what();
      }
      const auto domain = open_domain(m.default_domain);
      MeshRequest request = at_level(1, m.default_domain);
      request.options = given;
      EXPECT_THROW(mesh(m, *domain, request), InputError) << m.name << " --" << name;
    }
}

TEST(MesherRegistry, OptionValuesAreCheckedAgainstTheirDeclaration) {
  const MesherInfo& cutcell = find_mesher("cutcell");
  for (const MethodOptions& bad :
       {MethodOptions{{"feature-angle", 95.0}}, MethodOptions{{"feature-angle", std::int64_t{20}}},
        MethodOptions{{"interface-points", std::string("nearest")}},
        MethodOptions{{"crossing-levels", std::int64_t{-1}}},
        MethodOptions{{"cells-between-levels", std::int64_t{0}}},
        MethodOptions{{"no-such-option", true}}})
    EXPECT_THROW(check_options(cutcell, bad), InputError) << bad.begin()->first;
  EXPECT_NO_THROW(check_options(cutcell, {{"feature-angle", 20.0},
                                          {"interface-points", std::string("midpoint")},
                                          {"base-level", std::int64_t{2}}}));
  EXPECT_EQ(option_text("tets", true), "--tets");
  EXPECT_EQ(option_text("feature-angle", 20.0), "--feature-angle 20");
}

TEST(MesherRegistry, GridRefusesADomainThatDoesNotFillItsBox) {
  const auto ball = open_domain("builtin:ball");
  try {
    mesh(find_mesher("grid"), *ball, at_level(2, "builtin:ball"));
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("builtin:ball"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volmesh::meshers
