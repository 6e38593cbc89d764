#pragma once
// Surfaces, fixture paths and helpers shared by the surface I/O and surface check tests.
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <utility>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/tri_surface.hpp"

namespace volmesh::test {

inline std::filesystem::path surface_fixture(const std::string& name) {
  return std::filesystem::path(VOLMESH_TEST_DATA) / "surfaces" / name;
}
inline std::filesystem::path bad_fixture(const std::string& name) {
  return std::filesystem::path(VOLMESH_TEST_DATA) / "bad" / name;
}

// The message of the InputError that f throws, or "no error".
template <class F>
std::string input_error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// [0,1]^3, outward, in the same numbering as tests/data/surfaces/cube_quads.off: each quad
// (a, b, c, d) split into (a, b, c) and (a, c, d).
inline TriSurface unit_cube() {
  TriSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::array<std::array<Index, 4>, 6> quads = {
      {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}}};
  for (const auto& q : quads) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  return s;
}

// The corner tetrahedron (0,0,0), e1, e2, e3, outward; volume 1/6.
inline TriSurface corner_tetrahedron() {
  TriSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return s;
}

// The icosahedron subdivided `level` times, vertices on the unit sphere, outward:
// 20·4^level triangles, 10·4^level + 2 vertices.
inline TriSurface icosphere(int level) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriSurface s;
  s.points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
              {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& p : s.points) p.normalize();
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<Index, Index>, Index> midpoint;
    auto middle = [&](Index a, Index b) {
      auto [it, inserted] = midpoint.try_emplace(std::minmax(a, b), s.num_points());
      if (inserted) s.points.push_back((s.points[a] + s.points[b]).normalized());
      return it->second;
    };
    std::vector<std::array<Index, 3>> finer;
    for (const auto& [a, b, c] : s.triangles) {
      const Index ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    s.triangles = std::move(finer);
  }
  return s;
}

}  // namespace volmesh::test
