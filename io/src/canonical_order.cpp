#include "canonical_order.hpp"

#include <algorithm>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh {

namespace {

using Perm4 = std::array<int, 4>;
using Perm8 = std::array<int, 8>;

std::vector<Perm4> even_permutations() {
  std::vector<Perm4> out;
  Perm4 p{0, 1, 2, 3};
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += p[i] > p[j];
    if (inversions % 2 == 0) out.push_back(p);
  } while (std::next_permutation(p.begin(), p.end()));
  return out;
}

// A rotation puts any face at the bottom with any of its corners first: the bottom corners
// are the face's outward loop reversed, each top corner the bottom corner's edge partner.
std::vector<Perm8> hex_rotations() {
  std::vector<Perm8> out;
  for (const auto& face : kHexFaces)
    for (int start = 0; start < 4; ++start) {
      Perm8 p{};
      for (int i = 0; i < 4; ++i) p[i] = face[(start + 4 - i) % 4];
      for (int i = 0; i < 4; ++i)
        for (const auto& e : kHexEdges)
          for (int end = 0; end < 2; ++end)
            if (e[end] == p[i] && std::find(face.begin(), face.end(), e[1 - end]) == face.end())
              p[4 + i] = e[1 - end];
      out.push_back(p);
    }
  return out;
}

template <std::size_t N, typename Perms>
std::array<Index, N> smallest(const std::array<Index, 8>& corners, const Perms& perms) {
  std::array<Index, N> best{}, candidate{};
  bool first = true;
  for (const auto& p : perms) {
    for (std::size_t i = 0; i < N; ++i) candidate[i] = corners[p[i]];
    if (first || candidate < best) best = candidate;
    first = false;
  }
  return best;
}

}  // namespace

std::array<Index, 4> canonical_tet(const std::array<Index, 8>& corners) {
  static const std::vector<Perm4> perms = even_permutations();
  return smallest<4>(corners, perms);
}

std::array<Index, 8> canonical_hex(const std::array<Index, 8>& corners) {
  static const std::vector<Perm8> perms = hex_rotations();
  return smallest<8>(corners, perms);
}

void rotate_to_smallest(std::span<Index> loop) {
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
}

std::vector<std::vector<Index>> canonical_faces(const PolyMesh& mesh, std::span<const Index> faces,
                                                Index c) {
  std::vector<std::vector<Index>> loops;
  for (Index f : faces) {
    auto& loop = loops.emplace_back(mesh.face(f).begin(), mesh.face(f).end());
    if (face_sign(mesh, f, c) < 0) std::reverse(loop.begin(), loop.end());
    rotate_to_smallest(loop);
  }
  std::sort(loops.begin(), loops.end());
  return loops;
}

}  // namespace volmesh
