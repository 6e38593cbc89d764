#include "loop_triangulation.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace volmesh::cutcell {
namespace {

// A point this near a diagonal's plane, relative to the loop's size, lies on it: positions
// computed along different routes agree to rounding.
constexpr double kOnLine = 1e-9;

bool may_join(const LoopPoints& points, int a, int b) { return (points.faces[a] & points.faces[b]) == 0; }

// Area-weighted mean of the unit normals of the triangles (mass point, p_i, p_i+1) — (1) of
// the paper — and the mass point.
struct MeanPlane {
  Vec3 centre, normal;
};
MeanPlane mean_plane(const LoopPoints& points, std::span<const int> loop) {
  Vec3 centre = Vec3::Zero();
  for (int v : loop) centre += points.position[v];
  centre /= static_cast<double>(loop.size());
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3& p = points.position[loop[i]];
    const Vec3& q = points.position[loop[(i + 1) % loop.size()]];
    sum += 0.5 * (p - centre).cross(q - centre);  // = mes_i * n_i
  }
  return {centre, sum};
}

// Whether the diagonal from loop point i to loop point j lies inside the loop seen along
// `normal` (the loop turns counterclockwise about it): it leaves i into the loop and
// crosses no side, no other point within tolerance of it.
bool diagonal_inside(const LoopPoints& points, const std::vector<int>& loop, const Vec3& normal, int i, int j,
                     double tolerance) {
  const int n = static_cast<int>(loop.size());
  const Vec3 unit = normal.normalized();
  const auto at = [&](int k) -> const Vec3& { return points.position[loop[(k % n + n) % n]]; };
  // Twice the area of (a, b, c) seen along the normal, over the length of a -> b: the
  // distance of c to the left of that line.
  const auto left = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    const double l = (b - a).norm();
    return l > 0.0 ? (b - a).cross(c - a).dot(unit) / l : 0.0;
  };
  const Vec3 &a = at(i), &b = at(j), &prev = at(i - 1), &next = at(i + 1);
  const bool inside = left(prev, a, next) >= 0.0 ? left(a, b, prev) > tolerance && left(b, a, next) > tolerance
                                                  : !(left(a, b, next) <= tolerance && left(b, a, prev) <= tolerance);
  if (!inside) return false;
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    if (k != i && k != j && std::abs(left(a, b, at(k))) <= tolerance) {
      const double t = (at(k) - a).dot(b - a) / (b - a).squaredNorm();
      if (t > 0.0 && t < 1.0) return false;
    }
    if (k == i || k == j || k1 == i || k1 == j) continue;
    const Vec3 &c = at(k), &d = at(k1);
    if (left(a, b, c) * left(a, b, d) < 0.0 && left(c, d, a) * left(c, d, b) < 0.0) return false;
  }
  return true;
}

// The shortest diagonal (i, j), i < j, whose ends may be joined and that `fits`; (-1, -1) when
// there is none.
template <class Fits>
std::pair<int, int> shortest_diagonal(const LoopPoints& points, const std::vector<int>& loop, const Fits& fits) {
  const int n = static_cast<int>(loop.size());
  std::pair<int, int> out{-1, -1};
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i + 2 < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours around the loop
      if (!may_join(points, loop[i], loop[j])) continue;
      const double length = (points.position[loop[j]] - points.position[loop[i]]).norm();
      if (length >= best || !fits(i, j)) continue;
      best = length;
      out = {i, j};
    }
  return out;
}

bool divide(const LoopPoints& points, std::vector<int> loop, std::vector<Triangle>& out) {
  const int n = static_cast<int>(loop.size());
  if (n < 3) return false;
  if (n == 3) {
    out.push_back({loop[0], loop[1], loop[2]});
    return true;
  }
  const MeanPlane plane = mean_plane(points, loop);
  double scale = 0.0;
  for (int v : loop) scale = std::max(scale, (points.position[v] - plane.centre).norm());
  const double tolerance = kOnLine * scale;
  // Points strictly between i and j on one side of the diagonal, the others on the other.
  const auto separates = [&](int i, int j) {
    const Vec3& a = points.position[loop[i]];
    const Vec3 split = (points.position[loop[j]] - a).cross(plane.normal);
    const double split_norm = split.norm();
    if (!(split_norm > 0.0)) return false;
    int side = 0;
    for (int k = 0; k < n; ++k) {
      if (k == i || k == j) continue;
      const double s = split.dot(points.position[loop[k]] - a) / split_norm;
      if (std::abs(s) <= tolerance) return false;
      const int got = (s > 0 ? 1 : -1) * ((k > i && k < j) ? 1 : -1);
      if (side == 0) side = got;
      if (got != side) return false;
    }
    return true;
  };
  auto [best_i, best_j] = shortest_diagonal(points, loop, separates);
  // No diagonal separates the points (a loop that is not convex in its mean plane, a contour
  // on a face nearly tangent to the interface): any diagonal inside the loop seen along the
  // mean normal, which keeps the triangles from folding.
  if (best_i < 0)
    std::tie(best_i, best_j) = shortest_diagonal(
        points, loop, [&](int i, int j) { return diagonal_inside(points, loop, plane.normal, i, j, tolerance); });
  if (best_i < 0) return false;
  std::vector<int> first(loop.begin() + best_i, loop.begin() + best_j + 1);
  std::vector<int> second(loop.begin() + best_j, loop.end());
  second.insert(second.end(), loop.begin(), loop.begin() + best_i + 1);
  return divide(points, std::move(first), out) && divide(points, std::move(second), out);
}

// The face shared by consecutive loop points a -> b (the lowest common bit), -1 if none.
int segment_face(const LoopPoints& points, int a, int b) {
  const unsigned common = points.faces[a] & points.faces[b];
  return common ? std::countr_zero(common) : -1;
}

// Strip between chains p[0..] and q[0..] that share their first and last points; the
// degenerate triangles at the shared ends are skipped.
void strip(const LoopPoints& points, std::span<const int> p, std::span<const int> q,
           std::vector<Triangle>& out) {
  const auto add = [&out](int a, int b, int c) {
    if (a != b && b != c && c != a) out.push_back({a, b, c});
  };
  std::size_t i = 0, j = 0;
  while (i + 1 < p.size() || j + 1 < q.size()) {
    const bool advance_p =
        j + 1 >= q.size() ||
        (i + 1 < p.size() &&
         (points.position[p[i + 1]] - points.position[q[j]]).squaredNorm() <=
             (points.position[q[j + 1]] - points.position[p[i]]).squaredNorm());
    if (advance_p) {
      add(p[i], p[i + 1], q[j]);
      ++i;
    } else {
      add(p[i], q[j + 1], q[j]);
      ++j;
    }
  }
}

}  // namespace

std::optional<std::vector<Triangle>> triangulate_divide_and_conquer(const LoopPoints& points,
                                                                   std::span<const int> loop) {
  std::vector<Triangle> out;
  if (!divide(points, std::vector<int>(loop.begin(), loop.end()), out)) return std::nullopt;
  return out;
}

std::vector<Triangle> triangulate_fan(std::span<const int> loop, int centre) {
  std::vector<Triangle> out;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const int a = loop[i], b = loop[(i + 1) % n];
    if (a != centre && b != centre) out.push_back({a, b, centre});
  }
  return out;
}

std::optional<std::vector<Triangle>> triangulate_across_faces(const LoopPoints& points,
                                                             std::span<const int> loop) {
  const int n = static_cast<int>(loop.size());
  if (n < 3) return std::nullopt;
  std::vector<int> face(n);
  for (int i = 0; i < n; ++i) {
    face[i] = segment_face(points, loop[i], loop[(i + 1) % n]);
    if (face[i] < 0) return std::nullopt;
  }
  // Chains: maximal runs of segments on one face, starting where the face changes.
  int start = -1;
  for (int i = 0; i < n; ++i)
    if (face[i] != face[(i + n - 1) % n]) {
      start = i;
      break;
    }
  if (start < 0) return std::nullopt;
  std::vector<std::vector<int>> chains;  // points of each chain, its last = next chain's first
  std::vector<int> chain_face;
  for (int k = 0; k < n; ++k) {
    const int i = (start + k) % n;
    if (k == 0 || face[i] != face[(i + n - 1) % n]) {
      chains.push_back({loop[i]});
      chain_face.push_back(face[i]);
    }
    chains.back().push_back(loop[(i + 1) % n]);
  }
  // Faces k and k^1 are opposite: the chains' faces must be distinct and pairwise adjacent.
  for (std::size_t c = 0; c < chain_face.size(); ++c)
    for (std::size_t d = c + 1; d < chain_face.size(); ++d)
      if (chain_face[c] / 2 == chain_face[d] / 2) return std::nullopt;
  std::vector<Triangle> out;
  if (chains.size() == 2) {
    std::vector<int> back(chains[1].rbegin(), chains[1].rend());
    strip(points, chains[0], back, out);
    return out;
  }
  if (chains.size() != 3) return std::nullopt;
  // Rotate so that the first chain has an inner point A2.
  int first = -1;
  for (int c = 0; c < 3; ++c)
    if (chains[c].size() > 2) {
      first = c;
      break;
    }
  if (first < 0) {
    out.push_back({chains[0][0], chains[1][0], chains[2][0]});
    return out;
  }
  const std::vector<int>& A = chains[first];
  const std::vector<int>& B = chains[(first + 1) % 3];
  const std::vector<int>& C = chains[(first + 2) % 3];
  const int a2 = A[1], b2 = B[1];  // B[1] may be C's first point (B has no inner point)
  // Fan from B2 over A2 .. An, B1; then fan from A2 over B2 .. Bm, C1 .. Ck, A1.
  for (std::size_t i = 1; i + 1 < A.size(); ++i) out.push_back({A[i], A[i + 1], b2});
  std::vector<int> rest(B.begin() + 1, B.end());
  rest.insert(rest.end(), C.begin() + 1, C.end());  // ends with A1
  for (std::size_t i = 0; i + 1 < rest.size(); ++i) out.push_back({rest[i], rest[i + 1], a2});
  return out;
}

}  // namespace volmesh::cutcell
