// builtin:twisted-prism:K:DEG and builtin:schoenhardt, its case K = 3, DEG = 30 (builtin.hpp
// describes them): surface domains whose triangulated boundaries are their definition.
//
// Vertices: b_i = (cos a_i, sin a_i, 0) and t_i = (cos(a_i + w), sin(a_i + w), 1), with
// a_i = 2 pi i / K and the twist w > 0. The side quad b_i b_{i+1} t_{i+1} t_i is split along
// b_i t_{i+1}, the diagonal spanning the larger angle (2 pi / K + w) around the axis: it runs
// inside the convex hull, so the edge is reflex, as in Schönhardt's polyhedron. The caps are
// fanned from b_0 and t_0 (no Steiner points).
//
// The twist limit: the section at height z is the polygon through the points
// (1 - z) b_i + z t_i and (1 - z) b_i + z t_{i+1} in turn, and the surface is free of
// self-intersections exactly while every section is a simple polygon. That holds for every z
// in (0, 1) while 2 pi / K + w < pi, i.e. w < pi (K - 2) / K, the K-gon's interior angle: at
// that twist every reflex diagonal passes through the axis at z = 1/2, where they meet, and
// past it they cross. Twists must lie in (0, 180 (K - 2) / K)
// degrees: 60 for K = 3, 90 for K = 4, 120 for K = 6.
//
// The enclosed volume, as the sum of the signed volumes of the tetrahedra joining the origin
// to the triangles: none for the bottom cap, (K/6) sin(2 pi / K) for the top cap (its area
// over 3) and (sin(2 pi / K) + sin(2 pi / K + w) - sin w) / 6 for each side quad:
//   V = K/6 (2 sin(2 pi / K) + sin(2 pi / K + w) - sin w),
// the prism's (K/2) sin(2 pi / K) at w = 0; sqrt(3)/2 for Schönhardt's.
#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string_view>

#include "builtin_entries.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {
namespace {

constexpr std::string_view kPattern = "twisted-prism:K:DEG";
constexpr std::string_view kStem = kPattern.substr(0, kPattern.find(':') + 1);
constexpr int kMinSides = 3, kMaxSides = 64;
constexpr double kPi = std::numbers::pi;
constexpr Index kLabel = 1;

struct TwistedPrism {
  int sides;
  double twist_degrees;
};

double twist_limit_degrees(int sides) { return 180.0 * (sides - 2) / sides; }

TriSurface twisted_prism_surface(const TwistedPrism& p) {
  const int k = p.sides;
  const double twist = p.twist_degrees * kPi / 180.0;
  TriSurface s;
  for (int level = 0; level < 2; ++level)  // b_i = i, then t_i = k + i
    for (int i = 0; i < k; ++i) {
      const double angle = 2.0 * kPi * i / k + level * twist;
      s.points.emplace_back(std::cos(angle), std::sin(angle), level);
    }
  const auto b = [k](int i) { return Index(i % k); };
  const auto t = [k](int i) { return Index(k + i % k); };
  for (int i = 1; i + 1 < k; ++i) {
    s.triangles.push_back({b(0), b(i + 1), b(i)});
    s.triangles.push_back({t(0), t(i), t(i + 1)});
  }
  for (int i = 0; i < k; ++i) {
    s.triangles.push_back({b(i), b(i + 1), t(i + 1)});
    s.triangles.push_back({b(i), t(i + 1), t(i)});
  }
  return s;
}

double twisted_prism_volume(const TwistedPrism& p) {
  const double sector = 2.0 * kPi / p.sides, twist = p.twist_degrees * kPi / 180.0;
  return p.sides / 6.0 * (2.0 * std::sin(sector) + std::sin(sector + twist) - std::sin(twist));
}

BuiltinDomain twisted_prism_builtin(const std::string& name, const TwistedPrism& p) {
  const auto surfaces = [name, p] {
    return std::vector<LabelledSurface>{{twisted_prism_surface(p), kLabel, "builtin:" + name}};
  };
  return {name, [surfaces] { return std::make_unique<SurfaceDomain>(surfaces()); },
          [p] { return std::map<Index, double>{{kLabel, twisted_prism_volume(p)}}; }, surfaces};
}

template <class T>
bool parse_whole(std::string_view text, T& value) {
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && stop == end;
}

std::string shortest(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// "twisted-prism:K:DEG" -> its parameters; throws InputError naming the built-in.
TwistedPrism parse_twisted_prism(const std::string& name) {
  const std::string where = "builtin:" + name + ": ";
  const std::string_view params = std::string_view(name).substr(kStem.size());
  const std::size_t colon = params.find(':');
  TwistedPrism p{};
  if (colon == std::string_view::npos || !parse_whole(params.substr(0, colon), p.sides) ||
      !parse_whole(params.substr(colon + 1), p.twist_degrees) || !std::isfinite(p.twist_degrees))
    throw InputError(where + "expected " + std::string(kPattern) + ", K sides (" +
                     std::to_string(kMinSides) + " to " + std::to_string(kMaxSides) +
                     ") and a twist of DEG degrees");
  if (p.sides < kMinSides || p.sides > kMaxSides)
    throw InputError(where + std::to_string(p.sides) + " sides; K must lie in " +
                     std::to_string(kMinSides) + " to " + std::to_string(kMaxSides));
  const std::string twist(params.substr(colon + 1));
  const std::string range = "twists must lie in (0, " + shortest(twist_limit_degrees(p.sides)) + ")";
  if (p.twist_degrees <= 0.0)
    throw InputError(where + "a twist of " + twist +
                     " degrees leaves the side diagonals convex or flat; " + range);
  if (p.twist_degrees >= twist_limit_degrees(p.sides))
    throw InputError(where + "a twist of " + twist +
                     " degrees makes the surface self-intersect; " + range);
  return p;
}

}  // namespace

std::vector<BuiltinDomain> polyhedral_builtin_domains() {
  return {twisted_prism_builtin("schoenhardt", {3, 30.0})};
}

std::vector<BuiltinFamily> polyhedral_builtin_families() {
  return {{std::string(kPattern),
           [](const std::string& name) { return twisted_prism_builtin(name, parse_twisted_prism(name)); }}};
}

}  // namespace volmesh
