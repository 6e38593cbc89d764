// The geometric claims (docs/verification.md, "Geometric convergence") on real runs of the
// meshers, at low levels (the full study is validation/geometry/run.sh): cut cells converge to
// second order in volume and in the two-sided Hausdorff distance to the TRUE surface; staircase
// and midpoint M3C to first order. If cutting degraded to first order (crossings snapped,
// interface points at midpoints), the cut-cell slopes here would fall to about 1 and these
// tests would fail.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "volmesh/core/validity.hpp"
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/fem/study.hpp"
#include "volmesh/io/domain_file.hpp"
#include "volmesh/octree/staircase.hpp"
#include "volmesh/quality/analytic_surfaces.hpp"

namespace volmesh {
namespace {

using fem::least_squares_slope;

enum class Method { cutcell, midpoint, staircase };

PolyMesh mesh_of(const Domain& domain, Method method, int level) {
  OctreeOptions octree;
  octree.level = level;
  if (method == Method::staircase) return staircase_mesh(domain, StaircaseOptions{octree, {}});
  CutcellOptions options;
  options.octree = octree;
  options.interface_points =
      method == Method::midpoint ? InterfacePoints::midpoint : InterfacePoints::exact;
  return cutcell_mesh(domain, options);
}

double cell_size(const Domain& domain, int level) {
  return std::ldexp(octree_root(domain, OctreeOptions{}).side, -level);
}

struct Series {
  std::vector<double> h, volume_error, hausdorff;
};

// The two-sided Hausdorff distance to the true surfaces, samples h/4 apart.
double hausdorff(const PolyMesh& mesh, const AnalyticDomain& domain, double h) {
  return surface_distance(mesh, AnalyticSurfaces(domain), {.tolerance = h / 4.0}).all.hausdorff();
}

// Per level: |mesh volume - exact| and the two-sided Hausdorff distance.
Series study(const AnalyticDomain& domain, double exact_volume, Method method, int first,
             int last) {
  Series s;
  for (int level = first; level <= last; ++level) {
    const PolyMesh mesh = mesh_of(domain, method, level);
    const double h = cell_size(domain, level);
    s.h.push_back(h);
    s.volume_error.push_back(std::abs(check_validity(mesh).total_volume - exact_volume));
    s.hausdorff.push_back(hausdorff(mesh, domain, h));
  }
  return s;
}

const AnalyticDomain& ball() {
  static const std::unique_ptr<Domain> domain = make_builtin_domain("ball");
  return dynamic_cast<const AnalyticDomain&>(*domain);
}
const double kBallVolume = 4.0 / 3.0 * std::numbers::pi;

std::string table(const Series& s) {
  std::string out;
  for (std::size_t i = 0; i < s.h.size(); ++i)
    out += "h " + std::to_string(s.h[i]) + "  volume error " + std::to_string(s.volume_error[i]) +
           "  hausdorff " + std::to_string(s.hausdorff[i]) + "\n";
  return out;
}

TEST(GeometricConvergence, CutcellBallIsSecondOrder) {
  const Series s = study(ball(), kBallVolume, Method::cutcell, 3, 6);
  EXPECT_GE(least_squares_slope(s.h, s.hausdorff), 1.8) << table(s);
  EXPECT_GE(least_squares_slope(s.h, s.volume_error), 1.8) << table(s);
  // Per level, at least 3x (second order: 4x; first order: 2x).
  for (std::size_t i = 1; i < s.h.size(); ++i)
    EXPECT_GE(s.hausdorff[i - 1] / s.hausdorff[i], 3.0) << table(s);
}

TEST(GeometricConvergence, CutcellTorusIsSecondOrder) {
  const std::unique_ptr<Domain> domain =
      read_domain_file(VOLMESH_TEST_DATA "/domains/torus.json");
  const auto& torus = dynamic_cast<const AnalyticDomain&>(*domain);
  const Series s = study(torus, solid_volume(torus.primitives()[0]), Method::cutcell, 3, 6);
  EXPECT_GE(least_squares_slope(s.h, s.hausdorff), 1.8) << table(s);
}

// The staircase's volume error cancels irregularly; its first order shows in the distance.
TEST(GeometricConvergence, StaircaseBallIsFirstOrder) {
  const Series s = study(ball(), kBallVolume, Method::staircase, 3, 6);
  const double slope = least_squares_slope(s.h, s.hausdorff);
  EXPECT_GE(slope, 0.6) << table(s);
  EXPECT_LE(slope, 1.4) << table(s);
}

TEST(GeometricConvergence, MidpointM3CBallIsFirstOrder) {
  const Series s = study(ball(), kBallVolume, Method::midpoint, 3, 6);
  const double slope = least_squares_slope(s.h, s.hausdorff);
  EXPECT_GE(slope, 0.6) << table(s);
  EXPECT_LE(slope, 1.4) << table(s);
}

// builtin:layers6: the regions' volumes converge to the exact volumes of the triangulated
// model at second order; the cut mesh is valid with closed region boundaries (no gaps).
TEST(GeometricConvergence, Layers6RegionVolumesAreSecondOrder) {
  const std::unique_ptr<Domain> domain = make_builtin_domain("layers6");
  const std::map<Index, double> exact = builtin_region_volumes("layers6");
  std::vector<double> h, region_error, total_error;
  for (int level = 3; level <= 5; ++level) {
    const ValidityReport validity = check_validity(mesh_of(*domain, Method::cutcell, level));
    if (level == 3) {
      EXPECT_TRUE(validity.valid());
    }
    const std::map<Index, double>& volumes = validity.region_volume;
    double worst = 0.0, total = 0.0;
    for (const auto& [region, v] : exact) {
      worst = std::max(worst, std::abs(volumes.at(region) - v));
      total += volumes.at(region);
    }
    h.push_back(cell_size(*domain, level));
    region_error.push_back(worst);
    total_error.push_back(std::abs(total - 1.0));
  }
  EXPECT_GE(least_squares_slope(h, region_error), 1.8);
  // The unit box is the octree's root and its faces stay the root's: the regions fill the
  // box to rounding at every level.
  for (const double e : total_error) EXPECT_LE(e, 1e-10);
}

// builtin:primitives: the seven regions' volumes against their closed forms. From level 4
// the worst error falls about 3x per level (validation/geometry follows it to level 8). At
// level 3, 2.6 cells across the ball's radius, a cell point takes its Newton step only where
// the step converges: one that does not costs region 1 2.7e-2 of its volume, beyond the
// 1e-2 checked here.
TEST(GeometricConvergence, PrimitivesRegionVolumesConverge) {
  const std::unique_ptr<Domain> domain = make_builtin_domain("primitives");
  const std::map<Index, double> exact = builtin_region_volumes("primitives");
  std::vector<double> worst;
  for (int level = 3; level <= 6; ++level) {
    const std::map<Index, double> volumes =
        check_validity(mesh_of(*domain, Method::cutcell, level)).region_volume;
    double w = 0.0;
    for (const auto& [region, v] : exact) w = std::max(w, std::abs(volumes.at(region) - v));
    worst.push_back(w);
  }
  EXPECT_LE(worst[0], 1e-2);
  EXPECT_GE(worst[1] / worst[2], 2.8);
  EXPECT_GE(worst[2] / worst[3], 2.8);
}

// The largest distance from a vertex of a boundary or interface face to the surfaces.
double farthest_interface_vertex(const PolyMesh& mesh, const AnalyticDomain& domain) {
  const AnalyticSurfaces surfaces(domain);
  double worst = 0.0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Index n = mesh.neighbour[f];
    if (n != kNoIndex && mesh.cell_region[n] == mesh.cell_region[mesh.owner[f]]) continue;
    for (const Index v : mesh.face(f)) worst = std::max(worst, surfaces.distance(mesh.points[v]));
  }
  return worst;
}

// Where two surfaces cross (the ball through the box's bottom face, the cylinder through
// the ball) or meet at a sharp edge (the cylinder's rims, whose caps lie 0.09 h from a grid
// plane at level 6), leaf edges beside the junction are crossed twice at the deepest level:
// both crossings are kept, a rim's feature point is taken next to a side the vertex moves
// warped, and junction and corner points take a Newton step onto the true surfaces. Should
// one crossing stand for both, the rims would be chamfered (Hausdorff about a third of h);
// should points be fitted to tangent planes a cell away, they would lie 0.04-0.08 h off.
TEST(GeometricConvergence, PrimitivesJunctionsAndRimsStayOnTheSurfaces) {
  const std::unique_ptr<Domain> domain = make_builtin_domain("primitives");
  const auto& primitives = dynamic_cast<const AnalyticDomain&>(*domain);
  for (const int level : {5, 6}) {
    const PolyMesh mesh = mesh_of(primitives, Method::cutcell, level);
    const double h = cell_size(primitives, level);
    EXPECT_LE(hausdorff(mesh, primitives, h), 0.04 * h) << "level " << level;
    EXPECT_LE(farthest_interface_vertex(mesh, primitives), 0.032 * h) << "level " << level;
  }
}

// At level 7 junction lines pass beside deepest leaf edges crossed twice: crossings are kept
// apart down to the split gap (0.05 of the edge), and a face's junction point next to a
// crossing that stands for two is that crossing (not the meeting point of nearly parallel
// tangent lines). Every vertex of a boundary or interface face then lies within 0.02 h of
// the true surfaces; a crossing standing for two lies off either by up to the gap, so a
// larger gap moves the vertices beside such edges farther off.
TEST(GeometricConvergence, PrimitivesJunctionLinesKeepCloseCrossings) {
  const std::unique_ptr<Domain> domain = make_builtin_domain("primitives");
  const auto& primitives = dynamic_cast<const AnalyticDomain&>(*domain);
  const PolyMesh mesh = mesh_of(primitives, Method::cutcell, 7);
  EXPECT_LE(farthest_interface_vertex(mesh, primitives), 0.02 * cell_size(primitives, 7));
}

}  // namespace
}  // namespace volmesh
