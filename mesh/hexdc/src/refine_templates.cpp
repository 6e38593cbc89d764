#include "refine_templates.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh::hexdc_detail {

namespace {

constexpr unsigned kAllCorners = 0xFF;
// Corner masks of the canonical templates: corner 0, edge 0-1, face 0-1-2-3 (z = 0).
constexpr unsigned kNodeMask = 0x01, kEdgeMask = 0x03, kFaceMask = 0x0F;
constexpr int kThirds = 3;

// VTK corner c's position in the unit cube, one bit per axis.
constexpr std::array<std::array<int, 3>, 8> kCornerBits{
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};

// A point given in thirds of the cube (a half third allowed) as a lattice point.
LatticePoint thirds(double x, double y, double z) {
  const auto step = [](double v) {
    return static_cast<int>(std::lround(v * kLatticeSteps / kThirds));
  };
  return {step(x), step(y), step(z)};
}

// The hex between two quads given as matching loops (corner k of `bottom` below corner k of `top`).
TemplateHex between(const std::array<LatticePoint, 4>& bottom, const std::array<LatticePoint, 4>& top) {
  return {bottom[0], bottom[1], bottom[2], bottom[3], top[0], top[1], top[2], top[3]};
}

// The axis-aligned box [x, x+1] x [y, y+1] x [z, z+1] in thirds.
TemplateHex unit_box(int x, int y, int z) {
  return between({thirds(x, y, z), thirds(x + 1, y, z), thirds(x + 1, y + 1, z), thirds(x, y + 1, z)},
                 {thirds(x, y, z + 1), thirds(x + 1, y, z + 1), thirds(x + 1, y + 1, z + 1),
                  thirds(x, y + 1, z + 1)});
}

bool on_cube_side(int v) { return v == 0 || v == kThirds; }

// Corner 0 marked: the small cube at it and one hex from each of its three inner faces to the
// far face on that axis.
std::vector<TemplateHex> node_template() {
  const auto p = thirds;
  return {unit_box(0, 0, 0),
          between({p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)},
                  {p(3, 0, 0), p(3, 3, 0), p(3, 3, 3), p(3, 0, 3)}),
          between({p(0, 1, 0), p(1, 1, 0), p(1, 1, 1), p(0, 1, 1)},
                  {p(0, 3, 0), p(3, 3, 0), p(3, 3, 3), p(0, 3, 3)}),
          between({p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)},
                  {p(0, 0, 3), p(3, 0, 3), p(3, 3, 3), p(0, 3, 3)})};
}

// Corners 0 and 1 marked (the edge along x at y = z = 0): three small cubes along the edge, one
// hex above (+z) and one beside (+y) each, and slabs to the far faces z = 1 and y = 1. The inner
// nodes sit at two thirds, the ends of the far faces' lines at the cube's corners.
std::vector<TemplateHex> edge_template() {
  const auto p = thirds;
  // Images of the small cubes' top edge (y = 0 or 1, z = 1) and back edge (y = 1, z = 0).
  const auto up = [&](int x, int y) {
    if (on_cube_side(x)) return y == 0 ? p(x, 0, 3) : p(x, 3, 3);
    return y == 0 ? p(x, 0, 2) : p(x, 2, 2);
  };
  const auto back = [&](int x) { return on_cube_side(x) ? p(x, 3, 0) : p(x, 2, 0); };
  std::vector<TemplateHex> hexes;
  for (int i = 0; i < kThirds; ++i) {
    hexes.push_back(unit_box(i, 0, 0));
    hexes.push_back(between({p(i, 0, 1), p(i + 1, 0, 1), p(i + 1, 1, 1), p(i, 1, 1)},
                            {up(i, 0), up(i + 1, 0), up(i + 1, 1), up(i, 1)}));
    hexes.push_back(between({p(i, 1, 0), p(i + 1, 1, 0), p(i + 1, 1, 1), p(i, 1, 1)},
                            {back(i), back(i + 1), up(i + 1, 1), up(i, 1)}));
  }
  hexes.push_back(between({p(0, 0, 3), p(3, 0, 3), p(3, 3, 3), p(0, 3, 3)},
                          {p(1, 0, 2), p(2, 0, 2), p(2, 2, 2), p(1, 2, 2)}));
  hexes.push_back(between({p(0, 3, 0), p(3, 3, 0), p(3, 3, 3), p(0, 3, 3)},
                          {p(1, 2, 0), p(2, 2, 0), p(2, 2, 2), p(1, 2, 2)}));
  return hexes;
}

// Corners 0-3 marked (the face z = 0): a 3 x 3 layer on it; a second layer from the first one's
// top to a lifted grid (inner nodes at half height, side nodes at two thirds, corners at the far
// face); a slab under the far face, the hex under it in the middle and one on either side.
std::vector<TemplateHex> face_template() {
  const auto p = thirds;
  const auto lifted = [&](int x, int y) {
    const int sides = static_cast<int>(on_cube_side(x)) + static_cast<int>(on_cube_side(y));
    constexpr std::array<double, 3> kHeight{1.5, 2.0, 3.0};  // by sides touched
    return p(x, y, kHeight[static_cast<std::size_t>(sides)]);
  };
  std::vector<TemplateHex> hexes;
  for (int j = 0; j < kThirds; ++j)
    for (int i = 0; i < kThirds; ++i) hexes.push_back(unit_box(i, j, 0));
  for (int j = 0; j < kThirds; ++j)
    for (int i = 0; i < kThirds; ++i)
      hexes.push_back(between({p(i, j, 1), p(i + 1, j, 1), p(i + 1, j + 1, 1), p(i, j + 1, 1)},
                              {lifted(i, j), lifted(i + 1, j), lifted(i + 1, j + 1), lifted(i, j + 1)}));
  const std::array<LatticePoint, 4> middle{p(1, 0, 2), p(2, 0, 2), p(2, 3, 2), p(1, 3, 2)};
  hexes.push_back(between({p(0, 0, 3), p(3, 0, 3), p(3, 3, 3), p(0, 3, 3)}, middle));
  hexes.push_back(between({lifted(1, 1), lifted(2, 1), lifted(2, 2), lifted(1, 2)}, middle));
  hexes.push_back(between({p(0, 0, 3), p(1, 0, 2), p(1, 3, 2), p(0, 3, 3)},
                          {lifted(0, 1), lifted(1, 1), lifted(1, 2), lifted(0, 2)}));
  hexes.push_back(between({p(3, 0, 3), p(2, 0, 2), p(2, 3, 2), p(3, 3, 3)},
                          {lifted(3, 1), lifted(2, 1), lifted(2, 2), lifted(3, 2)}));
  return hexes;
}

std::vector<TemplateHex> full_template() {
  std::vector<TemplateHex> hexes;
  for (int k = 0; k < kThirds; ++k)
    for (int j = 0; j < kThirds; ++j)
      for (int i = 0; i < kThirds; ++i) hexes.push_back(unit_box(i, j, k));
  return hexes;
}

// A symmetry of the cube: axis i of the image is axis perm[i] of the source, mirrored if flip[i].
struct Symmetry {
  std::array<int, 3> perm;
  std::array<bool, 3> flip;

  LatticePoint apply(const LatticePoint& q) const {
    LatticePoint r;
    for (std::size_t i = 0; i < 3; ++i) {
      const int v = q[static_cast<std::size_t>(perm[i])];
      r[i] = flip[i] ? kLatticeSteps - v : v;
    }
    return r;
  }
  unsigned apply_mask(unsigned mask) const {
    unsigned image = 0;
    for (int c = 0; c < 8; ++c)
      if ((mask >> c) & 1u) {
        const LatticePoint q = apply(corner_point(c));
        for (int d = 0; d < 8; ++d)
          if (corner_point(d) == q) image |= 1u << d;
      }
    return image;
  }
};

std::vector<Symmetry> cube_symmetries() {
  std::vector<Symmetry> all;
  std::array<int, 3> perm{0, 1, 2};
  do {
    for (int f = 0; f < 8; ++f)
      all.push_back({perm, {(f & 1) != 0, (f & 2) != 0, (f & 4) != 0}});
  } while (std::next_permutation(perm.begin(), perm.end()));
  return all;
}

double lattice_volume_sign(const TemplateHex& hex) {
  std::array<Vec3, 8> corners;
  for (std::size_t c = 0; c < 8; ++c)
    corners[c] = Vec3(hex[c][0], hex[c][1], hex[c][2]);
  double sum = 0.0;
  for (const double v : hex_corner_tet_volumes(corners)) sum += v;
  return sum;
}

// The template turned by `s`, each hex re-ordered (mirrored) where the symmetry reverses it.
std::vector<TemplateHex> turned(const std::vector<TemplateHex>& hexes, const Symmetry& s) {
  constexpr std::array<std::size_t, 8> kMirror{0, 3, 2, 1, 4, 7, 6, 5};
  std::vector<TemplateHex> out;
  for (const TemplateHex& hex : hexes) {
    TemplateHex image;
    for (std::size_t c = 0; c < 8; ++c) image[c] = s.apply(hex[c]);
    if (lattice_volume_sign(image) < 0.0) {
      const TemplateHex mirrored = image;
      for (std::size_t c = 0; c < 8; ++c) image[c] = mirrored[kMirror[c]];
    }
    out.push_back(image);
  }
  return out;
}

struct TemplateTable {
  std::array<std::vector<TemplateHex>, 256> by_mask;
  std::array<bool, 256> closed{};

  TemplateTable() {
    TemplateHex parent;
    for (int c = 0; c < 8; ++c) parent[static_cast<std::size_t>(c)] = corner_point(c);
    by_mask[0] = {parent};
    closed[0] = true;
    const std::array<std::pair<unsigned, std::vector<TemplateHex>>, 4> canonical{
        {{kNodeMask, node_template()},
         {kEdgeMask, edge_template()},
         {kFaceMask, face_template()},
         {kAllCorners, full_template()}}};
    for (const Symmetry& s : cube_symmetries())
      for (const auto& [mask, hexes] : canonical) {
        const unsigned image = s.apply_mask(mask);
        if (closed[image]) continue;
        closed[image] = true;
        by_mask[image] = turned(hexes, s);
      }
  }
};

const TemplateTable& table() {
  static const TemplateTable t;
  return t;
}

}  // namespace

LatticePoint corner_point(int c) {
  const auto& b = kCornerBits[static_cast<std::size_t>(c)];
  return {b[0] * kLatticeSteps, b[1] * kLatticeSteps, b[2] * kLatticeSteps};
}

unsigned corner_mask(const std::array<Index, 8>& cell, const std::vector<char>& marked) {
  unsigned mask = 0;
  for (std::size_t c = 0; c < 8; ++c)
    if (marked[static_cast<std::size_t>(cell[c])] != 0) mask |= 1u << c;
  return mask;
}

unsigned closed_mask(unsigned mask) {
  if (table().closed[mask & kAllCorners]) return mask & kAllCorners;
  // Not supported: the face holding every mark, if one does, else the whole hex.
  for (const auto& face : kHexFaces) {
    unsigned face_mask = 0;
    for (const int c : face) face_mask |= 1u << c;
    if ((mask & ~face_mask) == 0) return face_mask;
  }
  return kAllCorners;
}

const std::vector<TemplateHex>& template_hexes(unsigned mask) {
  if (mask > kAllCorners || !table().closed[mask])
    throw std::logic_error("refine: corner mask " + std::to_string(mask) + " is not closed");
  return table().by_mask[mask];
}

}  // namespace volmesh::hexdc_detail

namespace volmesh {

RefineCase refine_case(unsigned mask) {
  switch (std::popcount(hexdc_detail::closed_mask(mask))) {
    case 0:
      return RefineCase::none;
    case 1:
      return RefineCase::node;
    case 2:
      return RefineCase::edge;
    case 4:
      return RefineCase::face;
    default:
      return RefineCase::full;
  }
}

}  // namespace volmesh
