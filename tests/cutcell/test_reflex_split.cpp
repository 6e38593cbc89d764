// split_reflex_cells on cells written by hand: an L-shaped cell whose centre lies behind the
// faces at its reflex edge is cut in two by the plane of one of them; a U-shaped cell, which
// no such plane leaves as checkMesh wants it, is left as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "hand_meshes.hpp"
#include "reflex_split.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh {
namespace {

using test::Xy;

// The arms' width: thin enough that the L's centre lies behind both faces at its reflex
// edge (it lies at x = y = 0.32).
constexpr double kArm = 0.2;

// The L [0,1] x [0,arm] + [0,arm] x [0,1] (in z, [0,1]).
std::vector<Xy> l_profile(double x0) {
  return {{x0, 0}, {x0 + 1, 0}, {x0 + 1, kArm}, {x0 + kArm, kArm}, {x0 + kArm, 1}, {x0, 1}};
}

// The outward loops of cell c, as positions, in a form independent of the face numbering.
std::vector<std::vector<Vec3>> cell_loops(const PolyMesh& m, Index c) {
  const CellFaces cf = build_cell_faces(m);
  std::vector<std::vector<Vec3>> out;
  for (Index f : cf.of(c)) {
    std::vector<Vec3> loop;
    for (Index v : m.face(f)) loop.push_back(m.points[v]);
    if (m.owner[f] != c) std::reverse(loop.begin(), loop.end());
    out.push_back(std::move(loop));
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), [](const Vec3& p, const Vec3& q) {
      return std::lexicographical_compare(p.begin(), p.end(), q.begin(), q.end());
    });
  });
  return out;
}

std::vector<Vec3> cell_points(const PolyMesh& m, Index c) {
  std::vector<Vec3> out;
  for (const auto& loop : cell_loops(m, c)) out.insert(out.end(), loop.begin(), loop.end());
  return out;
}

double cell_volume(const PolyMesh& m, Index c) {
  return mesh_geometry(m, build_cell_faces(m)).cells[c].volume;
}

// The L with a box beside each of its outer faces x = 0 (region 1) and y = 0 (region 2),
// so that the cut puts its new points into a neighbour's faces whichever plane it takes;
// with `filled`, a box of region 3 in its notch, whose faces are then the reflex edge's.
class ReflexSplitL : public testing::TestWithParam<bool> {};

TEST_P(ReflexSplitL, CutsTheCellInTwoBoxesAtItsReflexEdge) {
  test::HandMesh hand;
  const Index l = hand.prism(l_profile(0.0), 0.0, 1.0, 1);
  hand.box({-1, 0, 0}, {0, 1, 1}, 1);
  hand.box({0, -1, 0}, {1, 0, 1}, 2);
  if (GetParam()) hand.box({kArm, kArm, 0}, {1, 1, 1}, 3);
  PolyMesh mesh = hand.build();
  const ValidityReport before = check_validity(mesh);
  ASSERT_TRUE(before.valid());
  ASSERT_GT(test::checkmesh_failures(mesh), 0) << "the L's centre must lie behind its reflex faces";
  const Index cells = mesh.num_cells();
  std::vector<double> size(cells, 1.0);

  EXPECT_EQ(cutcell::split_reflex_cells(mesh, size, CheckMeshLimits{}), 1);

  ASSERT_EQ(mesh.num_cells(), cells + 1);
  EXPECT_EQ(size.size(), static_cast<std::size_t>(cells + 1));
  test::expect_valid_with_volumes(mesh, before);
  EXPECT_EQ(test::checkmesh_failures(mesh), 0);
  // The parts are the L's two arms, the boxes [0,1] x [0,arm] and [0,arm] x [arm,1] (or the
  // other way round, by the other plane), on either side of the plane x = arm or y = arm.
  const Index part = cells;
  EXPECT_EQ(mesh.cell_region[part], mesh.cell_region[l]);
  std::vector<double> volumes{cell_volume(mesh, l), cell_volume(mesh, part)};
  std::sort(volumes.begin(), volumes.end());
  EXPECT_NEAR(volumes[0], kArm * (1.0 - kArm), 1e-12);
  EXPECT_NEAR(volumes[1], kArm, 1e-12);
  const auto sides = [&](int axis) {
    const auto behind = [&](Index c) {
      const std::vector<Vec3> p = cell_points(mesh, c);
      return std::all_of(p.begin(), p.end(), [&](const Vec3& x) { return x[axis] <= kArm + 1e-12; });
    };
    const auto beyond = [&](Index c) {
      const std::vector<Vec3> p = cell_points(mesh, c);
      return std::all_of(p.begin(), p.end(), [&](const Vec3& x) { return x[axis] >= kArm - 1e-12; });
    };
    return (behind(l) && beyond(part)) || (behind(part) && beyond(l));
  };
  EXPECT_TRUE(sides(0) || sides(1));
}

INSTANTIATE_TEST_SUITE_P(NotchEmptyOrFilled, ReflexSplitL, testing::Bool(),
                         [](const auto& info) { return info.param ? "filled" : "empty"; });

// The U [0,3] x [0,arm] + [0,arm] x [arm,1] + [3-arm,3] x [arm,1]: its centre lies behind its
// inner floor. The plane of the floor would cut it into three; that of an arm's inner face
// leaves an L still rejected. So it is left as it was (its tentative cuts undone), while the
// L beside it is split.
TEST(ReflexSplit, LeavesACellNoPlaneFixes) {
  const double a = kArm;
  test::HandMesh hand;
  const Index u = hand.prism({{0, 0}, {3, 0}, {3, 1}, {3 - a, 1}, {3 - a, a}, {a, a}, {a, 1}, {0, 1}}, 0.0, 1.0, 1);
  const Index l = hand.prism(l_profile(5.0), 0.0, 1.0, 1);
  PolyMesh mesh = hand.build();
  const ValidityReport before = check_validity(mesh);
  ASSERT_TRUE(before.valid());
  const auto u_loops = cell_loops(mesh, u);
  const double u_volume = cell_volume(mesh, u);
  std::vector<double> size(mesh.num_cells(), 1.0);

  EXPECT_EQ(cutcell::split_reflex_cells(mesh, size, CheckMeshLimits{}), 1);

  ASSERT_EQ(mesh.num_cells(), 3);
  test::expect_valid_with_volumes(mesh, before);
  EXPECT_EQ(cell_loops(mesh, u), u_loops);
  EXPECT_EQ(cell_volume(mesh, u), u_volume);
  EXPECT_NEAR(cell_volume(mesh, l) + cell_volume(mesh, 2), 2 * kArm - kArm * kArm, 1e-12);
}

}  // namespace
}  // namespace volmesh
