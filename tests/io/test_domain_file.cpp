// Domain files: the examples in tests/data/domains (layers, a fault, nested surfaces, CSG
// solids, multi-material primitives with priorities) and the one-line errors naming the file
// and the JSON path.
#include <gtest/gtest.h>

#include "../support/images.hpp"
#include "volmesh/domain/layered.hpp"
#include "volmesh/io/domain_file.hpp"

namespace volmesh {
namespace {

using image_test::expect_input_error;
using image_test::TempDir;
using image_test::write_bytes;

const std::filesystem::path kData = std::filesystem::path(VOLMESH_TEST_DATA) / "domains";

TEST(DomainFile, LayersBetweenASurfaceFileAndAFlatHorizon) {
  const auto d = read_domain_file(kData / "layers.json");
  ASSERT_NE(dynamic_cast<const LayeredDomain*>(d.get()), nullptr);
  EXPECT_EQ(d->regions(), (std::vector<Index>{1, 2, 3}));
  // wavy.off has the vertex (0.25, 0, 0.35): a vertical line through it crosses there.
  EXPECT_EQ(d->region({0.25, 0.0, 0.35}), 2);
  EXPECT_EQ(d->region({0.25, 0.0, std::nextafter(0.35, 0.0)}), 1);
  EXPECT_EQ(d->region({0.25, 0.0, 0.6}), 3);
  EXPECT_EQ(d->region({0.7, 0.3, 0.9}), 3);
  EXPECT_EQ(d->region({0.7, 0.3, 1.1}), 0);
  const std::vector<Crossing> c = d->crossings({0.25, 0.0, -1.0}, {0.25, 0.0, 2.0});
  ASSERT_EQ(c.size(), 4u);
  EXPECT_NEAR(c[1].point.z(), 0.35, 1e-15);
  EXPECT_NEAR(c[2].point.z(), 0.6, 1e-15);
  EXPECT_EQ(c[3].after, 0);
  EXPECT_EQ(d->surface_name({0.5, 0.5, 0.59}), "flat top");
  EXPECT_EQ(d->surface_name({0.5, 0.5, 0.31}), "wavy.off");
}

TEST(DomainFile, AFaultWithTwoBlocksAndPriorities) {
  const auto d = read_domain_file(kData / "faulted.json");
  // The fault x = 0.375 + 0.25 z; on its upper side the horizons are z = 0.45 and 0.75.
  EXPECT_EQ(d->region({0.1, 0.5, 0.5}), 2);
  EXPECT_EQ(d->region({0.1, 0.5, 0.7}), 3);
  EXPECT_EQ(d->region({0.9, 0.5, 0.5}), 2);
  EXPECT_EQ(d->region({0.9, 0.5, 0.7}), 2);
  EXPECT_EQ(d->region({0.9, 0.5, 0.8}), 3);
  EXPECT_EQ(d->region({0.9, 0.5, 0.4}), 1);
  // Priority 2 > 3 > 1: on the flat top (2 below, 3 above) 2 wins; on the fault at z = 0.5
  // (2 on both sides) 2; at z = 0.4 on the fault x = 0.475, 2 (lower side) beats 1.
  EXPECT_EQ(d->region({0.1, 0.5, 0.6}), 2);
  EXPECT_EQ(d->region({0.5, 0.5, 0.5}), 2);
  EXPECT_EQ(d->region({0.9, 0.5, 0.75}), 2);
  EXPECT_EQ(d->region({0.9, 0.5, 0.45}), 2);
  EXPECT_EQ(d->regions(), (std::vector<Index>{1, 2, 3}));
  const std::vector<Crossing> c = d->crossings({0.9, 0.5, 0.3}, {0.9, 0.5, 0.5});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].before, 1);
  EXPECT_EQ(c[0].after, 2);
}

TEST(DomainFile, NestedSurfaces) {
  const auto d = read_domain_file(kData / "nested.json");
  EXPECT_EQ(d->region({0.5, 0.5, 0.5}), 2);
  EXPECT_EQ(d->region({0.1, 0.5, 0.5}), 1);
  EXPECT_EQ(d->region({1.1, 0.5, 0.5}), 0);
  EXPECT_EQ(d->regions(), (std::vector<Index>{1, 2}));
}

TEST(DomainFile, CsgSolidsWithRigidMotions) {
  const auto d = read_domain_file(kData / "solids.json");
  EXPECT_EQ(d->region({0.0, 0.0, 0.0}), 0);  // in the hole
  EXPECT_EQ(d->region({0.7, 0.0, 0.0}), 1);
  EXPECT_EQ(d->region({0.75, 0.9, 0.0}), 2);  // the ellipsoid turned to lie along y
  EXPECT_EQ(d->region({0.9, 0.75, 0.0}), 1);
  EXPECT_EQ(d->region({0.75, 0.75, 0.095}), 2);
  EXPECT_EQ(d->regions(), (std::vector<Index>{1, 2}));
}

TEST(DomainFile, MultiMaterialPrimitivesWithPriorities) {
  const auto d = read_domain_file(kData / "materials.json");
  EXPECT_EQ(d->regions(), (std::vector<Index>{1, 2, 3}));
  EXPECT_EQ(d->region({-0.5, 0, 0}), 1);  // the ball only
  EXPECT_EQ(d->region({0.5, 0, 0}), 3);   // both
  EXPECT_EQ(d->region({1.5, 0, 0}), 2);   // the box only
  // Priority 1 > 2 > 3 instead of the higher label: on the ball's surface inside the box 2
  // wins over 3, on the box's face inside the ball 1 wins over 3.
  EXPECT_EQ(d->region({1, 0, 0}), 2);
  EXPECT_EQ(d->region({0, 0.5, 0}), 1);
  const std::vector<Crossing> c = d->crossings({-3, 0.5, 0}, {3, 0.5, 0});
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[1].before, 1);
  EXPECT_EQ(c[1].after, 3);
  EXPECT_NEAR(c[1].t, 0.5, 1e-12);
  EXPECT_LT((c[1].normal - Vec3(1, 0, 0)).norm(), 1e-12);
}

// Each bad file, written next to a copy of wavy.off, and the start of its message.
struct BadFile {
  const char* json;
  const char* message;
};

class DomainFileErrors : public testing::TestWithParam<BadFile> {};

TEST_P(DomainFileErrors, NameTheFileAndThePath) {
  TempDir dir;
  std::filesystem::copy_file(kData / "wavy.off", dir / "wavy.off");
  write_bytes(dir / "bad.json", GetParam().json);
  const std::string path = (dir / "bad.json").string();
  try {
    read_domain_file(path);
    ADD_FAILURE() << "no InputError for " << GetParam().json;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos);
    EXPECT_EQ(what.substr(0, path.size() + 2), path + ": ") << what;
    EXPECT_EQ(what.substr(path.size() + 2, std::string(GetParam().message).size()),
              GetParam().message)
        << what;
  }
}

constexpr const char* kBox = R"("box": {"min": [0, 0, 0], "max": [1, 1, 1]})";

std::string layers(const std::string& inside) {
  return std::string("{") + kBox + R"(, "layers": {)" + inside + "}}";
}

const std::vector<std::string>& bad_files() {
  static const std::vector<std::string> files = {
      "{\"layers\": ",
      layers(R"("horizons": ["wavy.off"]}, "colour": 1, "x": {)"),
      R"({"box": {"min": [0, 0, "a"], "max": [1, 1, 1]}, "layers": {"horizons": []}})",
      layers(R"("horizons": ["wavy.off", "nope.off"])"),
      R"({"surfaces": [{"file": "wavy.off"}, {"file": "x.stl"}]})",
      layers(R"("horizons": [{"height": 0.32}, "wavy.off"])"),
      layers(R"("horizons": ["wavy.off"], "labels": [1, 2, 3])"),
      layers(R"("horizons": [{"height": 0.5, "colour": "red"}])"),
      layers(
          R"("faults": [{"plane": {"point": [0.5, 0, 0], "normal": [1, 0, 0]}}], "blocks": [{}])"),
      layers(R"("faults": [{"file": "wavy.off"}], "blocks": [{}, {}])"),
      R"({"solids": [{"label": 1, "solid": {"type": "sphere", "centre": [0, 0, 0], "radius": -1}}]})",
      R"({"solids": [{"label": 0, "solid": {"type": "sphere", "centre": [0, 0, 0], "radius": 1}}]})",
      R"({"materials": [{"type": "cone"}]})",
      R"({"solids": [{"label": 1, "solid": {"union": [{"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]}, 3]}}]})",
      R"({"materials": [{"type": "sphere", "centre": [0, 0, 0], "radius": 1}], "priority": [2]})",
      R"({"surfaces": [{"file": "wavy.off"}], "priority": [1]})",
      R"({"surfaces": [{"file": "wavy.off"}]})",
      R"({"solids": [], "materials": []})",
      R"({"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "solids": []})",
      std::string("{") + kBox + R"(, "layers": {"horizons": []}, "priority": [1, 1]})",
  };
  return files;
}

INSTANTIATE_TEST_SUITE_P(
    All, DomainFileErrors,
    testing::Values(
        BadFile{bad_files()[0].c_str(), "invalid JSON at line 1, column 12"},
        BadFile{bad_files()[1].c_str(),
                "colour: unknown key (expected box, surfaces, layers, solids, materials, "
                "priority)"},
        BadFile{bad_files()[2].c_str(), "box.min[2]: expected a number, got a string 'a'"},
        BadFile{bad_files()[3].c_str(), "layers.horizons[1]: cannot open 'nope.off'"},
        BadFile{bad_files()[4].c_str(), "surfaces[1].file: cannot open 'x.stl'"},
        BadFile{bad_files()[5].c_str(),
                "horizons 'layers.horizons[0]' and 'wavy.off' cross (the layer between them "
                "would have a negative thickness) near ("},
        BadFile{bad_files()[6].c_str(),
                "layers.labels: 3 labels for 1 horizons (expected one more)"},
        BadFile{bad_files()[7].c_str(),
                "layers.horizons[0].colour: unknown key (expected file, plane, height, name)"},
        BadFile{bad_files()[8].c_str(), "layers.blocks: 1 blocks for 1 faults (expected 2^faults)"},
        BadFile{bad_files()[9].c_str(), "layers.faults[0]: missing key 'axis'"},
        BadFile{bad_files()[10].c_str(), "solids[0].solid.radius: must be > 0"},
        BadFile{bad_files()[11].c_str(), "solids[0].label: label 0 is not in 1.."},
        BadFile{bad_files()[12].c_str(), "materials[0].type: unknown primitive 'cone'"},
        BadFile{bad_files()[13].c_str(),
                "solids[0].solid.union[1]: expected a primitive: an object with a 'type'"},
        BadFile{bad_files()[14].c_str(), "priority: label 1 is not listed"},
        BadFile{bad_files()[15].c_str(), "priority: surface domains take no priority"},
        BadFile{bad_files()[16].c_str(), "surfaces: wavy.off: edge"},
        BadFile{bad_files()[17].c_str(), "expected exactly one of \"surfaces\", \"layers\""},
        BadFile{bad_files()[18].c_str(), "box: only layered domains take a box"},
        BadFile{bad_files()[19].c_str(), "priority[1]: label 1 is listed twice"}));

TEST(DomainFile, AMissingFileIsNamed) {
  expect_input_error([] { read_domain_file("no/such/domain.json"); },
                     {"no/such/domain.json: cannot open"});
}

}  // namespace
}  // namespace volmesh
