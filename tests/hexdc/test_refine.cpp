// Schneiders' 3-refinement templates: each case on a lone box hex and inside a block whose
// unrefined hexes must conform, the closure of unsupported marks, and the marking helpers.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <map>
#include <set>
#include <string>

#include "hex_checks.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/hexdc/hex_quality.hpp"
#include "volmesh/hexdc/refine.hpp"

namespace volmesh {
namespace {

using test_hexdc::corners_of;
using test_hexdc::invalid_hexes;
using test_hexdc::mesh_volume;

constexpr double kTol = 1e-12;
constexpr std::size_t kNodeHexes = 4, kEdgeHexes = 11, kFaceHexes = 22, kFullHexes = 27;

// Corners marked in each template.
const std::map<RefineCase, int> kMarksOf{{RefineCase::none, 0},
                                         {RefineCase::node, 1},
                                         {RefineCase::edge, 2},
                                         {RefineCase::face, 4},
                                         {RefineCase::full, 8}};

using Quad = std::array<Index, 4>;

Quad sorted(Quad q) {
  std::sort(q.begin(), q.end());
  return q;
}

std::map<Quad, int> face_uses(const HexMesh& mesh) {
  std::map<Quad, int> uses;
  for (const auto& cell : mesh.cells)
    for (const auto& f : kHexFaces) ++uses[sorted({cell[f[0]], cell[f[1]], cell[f[2]], cell[f[3]]})];
  return uses;
}

// The side of the box [lo, hi] holding all four points of q, as structured_hex_mesh's tag name;
// "" when they are not on one side.
std::string box_side(const HexMesh& mesh, const Quad& q, const Vec3& lo, const Vec3& hi) {
  static const std::array<std::array<const char*, 2>, 3> kNames{
      {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}}};
  for (int axis = 0; axis < 3; ++axis)
    for (int end = 0; end < 2; ++end) {
      const double plane = end == 0 ? lo[axis] : hi[axis];
      if (std::all_of(q.begin(), q.end(), [&](Index v) {
            return std::abs(mesh.points[static_cast<std::size_t>(v)][axis] - plane) < kTol;
          }))
        return kNames[static_cast<std::size_t>(axis)][static_cast<std::size_t>(end)];
    }
  return "";
}

// A conforming refinement of the box [lo, hi]: no two nodes at one point, every node used,
// every quad in one or two hexes, the quads in one hex exactly the boundary quads and each on the
// box side its tag names (so no hanging node inside), every hex valid, and the box's volume.
void expect_conforming_box(const HexMesh& mesh, const Vec3& lo, const Vec3& hi) {
  std::vector<Vec3> points = mesh.points;
  std::sort(points.begin(), points.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  for (std::size_t i = 1; i < points.size(); ++i)
    ASSERT_GT((points[i] - points[i - 1]).norm(), 1e-9) << "duplicate point";
  std::vector<char> used(mesh.points.size(), 0);
  for (const auto& cell : mesh.cells)
    for (const Index v : cell) used[static_cast<std::size_t>(v)] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);

  std::set<Quad> once;
  for (const auto& [quad, uses] : face_uses(mesh)) {
    ASSERT_LE(uses, 2);
    if (uses == 1) once.insert(quad);
  }
  ASSERT_EQ(mesh.boundary_faces.size(), mesh.boundary_tag.size());
  std::set<Quad> tagged;
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    const Quad& q = mesh.boundary_faces[f];
    tagged.insert(sorted(q));
    const auto tag = static_cast<std::size_t>(mesh.boundary_tag[f]);
    ASSERT_LT(tag, mesh.tag_names.size());
    EXPECT_EQ(box_side(mesh, q, lo, hi), mesh.tag_names[tag]) << f;
  }
  EXPECT_EQ(tagged.size(), mesh.boundary_faces.size());
  EXPECT_EQ(tagged, once);

  EXPECT_EQ(invalid_hexes(mesh), 0);
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    EXPECT_GT(hex_quality(corners_of(mesh, h)).scaled_jacobian, 0.0) << h;
  const Vec3 size = hi - lo;
  const double volume = size.prod();
  EXPECT_NEAR(mesh_volume(mesh), volume, kTol * volume);
}

Index node_at(const HexMesh& mesh, const Vec3& p) {
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if ((mesh.points[v] - p).norm() < kTol) return static_cast<Index>(v);
  return -1;
}

std::vector<char> corner_marks(const HexMesh& mesh, Index hex, unsigned mask) {
  std::vector<char> marks(mesh.points.size(), 0);
  for (std::size_t c = 0; c < 8; ++c)
    if ((mask >> c) & 1u) marks[static_cast<std::size_t>(mesh.cells[static_cast<std::size_t>(hex)][c])] = 1;
  return marks;
}

// One lone box hex with every supported mask: the template's hex count, conforming.
TEST(RefineHexes, EveryTemplateOnALoneHexIsConformingAndKeepsTheVolume) {
  const Vec3 lo(0.0, 0.0, 0.0), hi(1.0, 2.0, 3.0);
  int supported = 0;
  for (unsigned mask = 1; mask < 256; ++mask) {
    const RefineCase kind = refine_case(mask);
    if (std::popcount(mask) != kMarksOf.at(kind)) continue;  // not a template's own marks
    ++supported;
    SCOPED_TRACE(mask);
    HexMesh mesh = structured_hex_mesh(lo, hi, {1, 1, 1});
    const RefineStats stats = refine_hexes(mesh, corner_marks(mesh, 0, mask));
    const std::map<RefineCase, std::size_t> hexes{{RefineCase::node, kNodeHexes},
                                                  {RefineCase::edge, kEdgeHexes},
                                                  {RefineCase::face, kFaceHexes},
                                                  {RefineCase::full, kFullHexes}};
    EXPECT_EQ(mesh.cells.size(), hexes.at(kind));
    EXPECT_EQ(stats.hexes_by_case[static_cast<std::size_t>(kind)], 1);
    EXPECT_EQ(stats.marked_after_closure, stats.marked_given);
    expect_conforming_box(mesh, lo, hi);
  }
  EXPECT_EQ(supported, 8 + 12 + 6 + 1);  // corners, edges, faces, the whole hex
}

// The centre hex of a 3x3x3 block with each case's marks: its neighbours take the matching
// transitions and the block stays conforming.
TEST(RefineHexes, EachCaseInsideABlockConformsWithItsNeighbours) {
  const Vec3 lo = Vec3::Zero(), hi(3.0, 3.0, 3.0);
  constexpr Index kCentre = 13;  // (1, 1, 1) of the 3x3x3 block in x-fastest order
  for (const unsigned mask : {0x01u, 0x03u, 0x0Fu, 0xFFu}) {
    SCOPED_TRACE(mask);
    HexMesh mesh = structured_hex_mesh(lo, hi, {3, 3, 3});
    ASSERT_LT((corners_of(mesh, kCentre)[0] - Vec3::Ones()).norm(), kTol);
    const RefineStats stats = refine_hexes(mesh, corner_marks(mesh, kCentre, mask));
    EXPECT_EQ(stats.marked_after_closure, stats.marked_given);
    EXPECT_EQ(stats.hexes_before, 27);
    EXPECT_EQ(stats.hexes_after, mesh.num_cells());
    Index sum = 0;
    for (const Index n : stats.hexes_by_case) sum += n;
    EXPECT_EQ(sum, 27);
    expect_conforming_box(mesh, lo, hi);
  }
}

// One marked node inside the block: the eight hexes around it each take the node template.
TEST(RefineHexes, OneInteriorNodeGivesEightNodeTemplates) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Constant(3.0), {3, 3, 3});
  std::vector<char> marks(mesh.points.size(), 0);
  marks[static_cast<std::size_t>(node_at(mesh, Vec3::Ones()))] = 1;
  const RefineStats stats = refine_hexes(mesh, marks);
  EXPECT_EQ(stats.hexes_by_case[static_cast<std::size_t>(RefineCase::node)], 8);
  EXPECT_EQ(stats.hexes_by_case[static_cast<std::size_t>(RefineCase::none)], 19);
  EXPECT_EQ(stats.hexes_after, 19 + 8 * static_cast<Index>(kNodeHexes));
}

// Marks that are no template's: two diagonal corners of a face, or three corners of one face,
// close to the face; corners on a body diagonal, or three not in one face, to the whole hex.
TEST(RefineHexes, ClosureTurnsDiagonalMarksIntoAFaceOrTheWholeHex) {
  const Vec3 lo = Vec3::Zero(), hi = Vec3::Constant(3.0);
  for (const auto& [mask, kind, closed_marks] :
       std::vector<std::tuple<unsigned, RefineCase, Index>>{{0x05u, RefineCase::face, 4},
                                                            {0x41u, RefineCase::full, 8},
                                                            {0x07u, RefineCase::face, 4},
                                                            {0x13u, RefineCase::face, 4},
                                                            {0x25u, RefineCase::full, 8}}) {
    SCOPED_TRACE(mask);
    EXPECT_EQ(refine_case(mask), kind);
    HexMesh lone = structured_hex_mesh(lo, hi, {1, 1, 1});
    const RefineStats stats = refine_hexes(lone, corner_marks(lone, 0, mask));
    EXPECT_EQ(stats.marked_given, std::popcount(mask));
    EXPECT_EQ(stats.marked_after_closure, closed_marks);
    expect_conforming_box(lone, lo, hi);

    // In the block the added marks spread to the neighbours until every hex has a template.
    HexMesh block = structured_hex_mesh(lo, hi, {3, 3, 3});
    std::vector<char> marks = corner_marks(block, 13, mask);
    const Index passes = close_refinement_marks(block, marks);
    EXPECT_GE(passes, 2);
    for (const auto& cell : block.cells) {
      unsigned m = 0;
      for (std::size_t c = 0; c < 8; ++c) m |= marks[static_cast<std::size_t>(cell[c])] != 0 ? 1u << c : 0u;
      EXPECT_EQ(std::popcount(m), kMarksOf.at(refine_case(m)));
    }
    refine_hexes(block, corner_marks(block, 13, mask));
    expect_conforming_box(block, lo, hi);
  }
}

// Hex layers of a 6x6x6 block: the nodes whose index is within `layers` of a side on some axis.
TEST(RefineHexes, BoundaryLayersMarkTheNodesOfTheOuterHexLayers) {
  constexpr Index kCells = 6;
  const HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Constant(kCells), {kCells, kCells, kCells});
  const std::vector<char> none = mark_boundary_layers(mesh, 0);
  EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
  for (const int layers : {1, 2, 3}) {
    const std::vector<char> marks = mark_boundary_layers(mesh, layers);
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
      const Vec3& p = mesh.points[v];
      const double depth = std::min({p.x(), p.y(), p.z(), kCells - p.x(), kCells - p.y(), kCells - p.z()});
      EXPECT_EQ(marks[v] != 0, depth <= layers) << layers << " " << p.transpose();
    }
  }
}

// On a 4x4x4 block one layer marks every node but the centre; the inner hexes then have seven
// marks, which the closure completes, so every hex splits into 27.
TEST(RefineHexes, OneBoundaryLayerOfASmallBlockClosesToTheWholeBlock) {
  const Vec3 lo = Vec3::Zero(), hi = Vec3::Constant(4.0);
  HexMesh mesh = structured_hex_mesh(lo, hi, {4, 4, 4});
  const RefineStats stats = refine_hexes(mesh, mark_boundary_layers(mesh, 1));
  EXPECT_EQ(stats.marked_given, 124);
  EXPECT_EQ(stats.marked_after_closure, 125);
  EXPECT_EQ(stats.hexes_by_case[static_cast<std::size_t>(RefineCase::full)], 64);
  EXPECT_EQ(stats.hexes_after, 64 * static_cast<Index>(kFullHexes));
  expect_conforming_box(mesh, lo, hi);
}

TEST(RefineHexes, BoxMarksTheNodesInsideIt) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Constant(4.0), {4, 4, 4});
  const std::vector<char> marks = mark_box(mesh, Eigen::AlignedBox3d(Vec3::Constant(0.5), Vec3::Constant(2.0)));
  EXPECT_EQ(std::count(marks.begin(), marks.end(), 1), 8);  // (1..2)^3
  refine_hexes(mesh, marks);
  expect_conforming_box(mesh, Vec3::Zero(), Vec3::Constant(4.0));
}

TEST(RefineHexes, NoMarksLeaveTheMeshAndWrongSizesAreRefused) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2});
  const HexMesh before = mesh;
  const RefineStats stats = refine_hexes(mesh, std::vector<char>(mesh.points.size(), 0));
  EXPECT_EQ(stats.hexes_after, stats.hexes_before);
  EXPECT_EQ(mesh.cells, before.cells);
  EXPECT_THROW(refine_hexes(mesh, std::vector<char>(3, 1)), InputError);
}

}  // namespace
}  // namespace volmesh
