// builtin:layers6 (builtin.hpp describes it) and its exact region volumes, integrated over
// the very triangles of its sheets.
#include <array>
#include <cmath>
#include <numbers>

#include "builtin_entries.hpp"
#include "volmesh/domain/layered.hpp"

namespace volmesh {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr Index kGrid = 129;    // vertices along x and y of every horizon
constexpr double kThrow = 0.1;  // the fault lifts the layers on its upper side by this
const Box3 kBox{Vec3::Zero(), Vec3::Ones()};
// The fault: the plane x = 0.4 + 0.3 z (dipping 73 degrees), a graph across x.
const Vec3 kFaultPoint(0.4, 0.0, 0.0), kFaultNormal(1.0, 0.0, -0.3);

// Horizon k = 1..5 before the pinch-out: around z = k/6, undulating by up to 0.045.
double undulating(int k, double x, double y) {
  return k / 6.0 +
         0.03 * std::sin(kTwoPi * (1.5 * x + 0.2 * k)) * std::cos(kTwoPi * (y + 0.1 * k)) +
         0.015 * std::sin(kTwoPi * (3.0 * y + 0.7 * x));
}

// Layer 3 (between horizons 2 and 3) pinches out where y < 0.35 - 0.1 sin(4 pi x): horizon
// 3 rests on horizon 2 there, with the very same vertex heights.
double horizon(int k, double x, double y) {
  if (k != 3) return undulating(k, x, y);
  const double thickness = 0.3 * (y - 0.35) + 0.03 * std::sin(2.0 * kTwoPi * x);
  return undulating(2, x, y) + std::max(0.0, thickness);
}

LayeredModel layers6_model() {
  LayeredModel model;
  model.box = kBox;
  model.name = "builtin:layers6";
  model.faults.push_back(plane_sheet(kBox, 0, kFaultPoint, kFaultNormal, "fault"));
  for (int block = 0; block < 2; ++block) {
    LayerBlock b;
    const double lift = block == 1 ? kThrow : 0.0;
    for (int k = 1; k <= 5; ++k) {
      std::string name(1, 'h');
      name += std::to_string(k);
      if (block == 1) name += " (lifted)";
      b.horizons.push_back(graph_sheet(
          kBox, 2, kGrid, kGrid, [&](double x, double y) { return horizon(k, x, y) + lift; },
          std::move(name)));
    }
    b.labels = {1, 2, 3, 4, 5, 6};
    model.blocks.push_back(std::move(b));
  }
  return model;
}

// The integral of max(0, min_i upper_i - max_j lower_j) over a triangle, the functions being
// linear: the triangle is cut into the polygons where one difference is the least, and
// the positive part of that difference is integrated on each exactly.
struct Corner {
  double x, y;
  std::array<double, 6> f;  // the functions' values: upper ones, then lower ones
};
using Polygon = std::vector<Corner>;

// The part of the polygon where g(corner) <= 0, g linear in the values.
template <class G>
Polygon clip(const Polygon& p, G g) {
  Polygon out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Corner &a = p[i], &b = p[(i + 1) % p.size()];
    const double ga = g(a), gb = g(b);
    if (ga <= 0.0) out.push_back(a);
    if ((ga < 0.0 && gb > 0.0) || (ga > 0.0 && gb < 0.0)) {
      const double s = ga / (ga - gb);
      Corner c{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), {}};
      for (std::size_t k = 0; k < c.f.size(); ++k) c.f[k] = a.f[k] + s * (b.f[k] - a.f[k]);
      out.push_back(c);
    }
  }
  return out;
}

// The integral of a linear function (value h(corner)) over a convex polygon.
template <class H>
double integral(const Polygon& p, H h) {
  double sum = 0.0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const double area = 0.5 * ((p[i].x - p[0].x) * (p[i + 1].y - p[0].y) -
                               (p[i + 1].x - p[0].x) * (p[i].y - p[0].y));
    sum += area * (h(p[0]) + h(p[i]) + h(p[i + 1])) / 3.0;
  }
  return sum;
}

double positive_gap(const Polygon& triangle, int uppers, int lowers) {
  const auto gap = [&](int i, int j) {
    return [=](const Corner& c) { return c.f[i] - c.f[uppers + j]; };
  };
  // Mostly one difference is the least at every corner, hence everywhere.
  std::array<std::array<double, 9>, 3> d;  // per corner, per pair (i, j)
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < uppers; ++i)
      for (int j = 0; j < lowers; ++j) d[c][i * lowers + j] = gap(i, j)(triangle[c]);
  const int pairs = uppers * lowers;
  for (int q = 0; q < pairs; ++q) {
    bool least = true;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < pairs; ++r) least &= d[c][q] <= d[c][r];
    if (!least) continue;
    const auto g = gap(q / lowers, q % lowers);
    if (d[0][q] >= 0.0 && d[1][q] >= 0.0 && d[2][q] >= 0.0) return integral(triangle, g);
    if (d[0][q] <= 0.0 && d[1][q] <= 0.0 && d[2][q] <= 0.0) return 0.0;
    const Polygon p = clip(triangle, [&](const Corner& c) { return -g(c); });
    return p.size() >= 3 ? integral(p, g) : 0.0;
  }
  double sum = 0.0;
  for (int i = 0; i < uppers; ++i)
    for (int j = 0; j < lowers; ++j) {
      Polygon p = triangle;
      for (int k = 0; k < uppers && !p.empty(); ++k)
        for (int l = 0; l < lowers && !p.empty(); ++l)
          if (k != i || l != j)
            p = clip(p, [&](const Corner& c) { return gap(i, j)(c) - gap(k, l)(c); });
      if (p.empty()) continue;
      p = clip(p, [&](const Corner& c) { return -gap(i, j)(c); });
      if (p.size() >= 3) sum += integral(p, gap(i, j));
    }
  return sum;
}

std::map<Index, double> layers6_volumes() {
  const LayeredModel model = layers6_model();
  const TriSurface& fault = model.faults[0].surface;
  // The fault's plane as z = zf(x) (it is a graph across x, linear in z only).
  double x_at_z0 = 0.0, x_at_z1 = 0.0;
  for (const Vec3& p : fault.points) (p.z() == 0.0 ? x_at_z0 : x_at_z1) = p.x();
  const auto fault_z = [&](double x) { return (x - x_at_z0) / (x_at_z1 - x_at_z0); };
  std::map<Index, double> volumes;
  for (int block = 0; block < 2; ++block) {
    const std::vector<Sheet>& h = model.blocks[block].horizons;
    const TriSurface& grid = h[0].surface;  // every horizon has the same triangles
    for (int layer = 0; layer <= 5; ++layer) {
      double sum = 0.0;
      for (const auto& t : grid.triangles) {
        Polygon triangle;
        for (Index c : t) {
          const Vec3& p = grid.points[c];
          Corner corner{p.x(), p.y(), {}};
          // Upper bounds: the horizon above, the box top, and (block 1, below the fault
          // plane) the fault; lower bounds: the horizon below, the box bottom, and (block
          // 0) the fault.
          int n = 0;
          if (layer < 5) corner.f[n++] = h[layer].surface.points[c].z();
          corner.f[n++] = kBox.hi.z();
          if (block == 1) corner.f[n++] = fault_z(p.x());
          if (layer > 0) corner.f[n++] = h[layer - 1].surface.points[c].z();
          corner.f[n++] = kBox.lo.z();
          if (block == 0) corner.f[n++] = fault_z(p.x());
          triangle.push_back(corner);
        }
        const int uppers = (layer < 5) + 1 + (block == 1);
        const int lowers = (layer > 0) + 1 + (block == 0);
        sum += positive_gap(triangle, uppers, lowers);
      }
      volumes[layer + 1] += sum;
    }
  }
  return volumes;
}

std::unique_ptr<Domain> make_layers6() { return std::make_unique<LayeredDomain>(layers6_model()); }

}  // namespace

std::vector<BuiltinDomain> layered_builtin_domains() {
  return {{"layers6", make_layers6, layers6_volumes}};
}

}  // namespace volmesh
