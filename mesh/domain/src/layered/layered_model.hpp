#pragma once
// What a LayeredDomain holds (layered.hpp describes the model): its sheets as exact
// graphs, the blocks of horizons, and the trees for segment and nearest-point queries.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "surface/surface_closest.hpp"
#include "surface/surface_exact.hpp"
#include "surface/surface_geometry.hpp"
#include "volmesh/domain/layered.hpp"

namespace volmesh::layers {

// A sheet checked to be a graph w = f(u, v) over the box's rectangle across w, its triangles
// turned counter-clockwise in (u, v) so that their normals point to +w.
class GraphSheet {
 public:
  // Throws InputError "MODEL: sheet 'NAME': ..." if it is not such a graph (see Sheet).
  GraphSheet(const Sheet& sheet, const Box3& box, const std::string& model);

  // A triangle whose closed projection holds (p_u, p_v), or kNoIndex if that point lies
  // outside the rectangle. Exact.
  Index locate(const Vec3& p) const;
  // sign(p_w - f(p_u, p_v)) for p over the rectangle: +1 above, 0 on, -1 below. Exact.
  int side(const Vec3& p) const;
  // Whether p lies over the closed rectangle.
  bool over(const Vec3& p) const;
  // The triangles whose boxes meet the box of lo and hi, increasing, or false (and nothing)
  // when that box spans more than max_buckets buckets: a tree is faster for long segments.
  bool triangles_near(const Vec3& lo, const Vec3& hi, std::size_t max_buckets,
                      std::vector<Index>& out) const;
  // Calls f(t) for the triangles t that may meet the (u, v) box of lo and hi (some twice).
  template <class F>
  void for_each_near(const Vec3& lo, const Vec3& hi, F&& f) const {
    const auto a = bucket(lo[u], lo[v]), b = bucket(hi[u], hi[v]);
    for (Index j = a[1]; j <= b[1]; ++j)
      for (Index i = a[0]; i <= b[0]; ++i)
        for (Index k = first_[i + nu_ * j]; k < first_[i + nu_ * j + 1]; ++k) f(members_[k]);
  }

  int axis, u, v;  // w and the two axes it is a graph over
  std::string name;
  std::vector<Vec3> points;
  std::vector<std::array<Index, 3>> triangles;  // counter-clockwise in (u, v)
  std::vector<std::array<Index, 3>> across;     // the triangle across side k (k to k + 1)

 private:
  void build_buckets();
  std::array<Index, 2> bucket(double pu, double pv) const;
  // locate() for a point over the rectangle, in its bucket cell = i + nu_ j.
  Index locate_in(const Vec3& p, Index cell) const;

  double u0_, v0_, u1_, v1_;            // the rectangle
  double w0_, w1_;                      // the least and greatest w of the sheet
  double scale_u_, scale_v_;            // buckets per unit length
  Index nu_, nv_;                       // buckets along u and v
  std::vector<Index> first_, members_;  // triangles of bucket (i, j): first_[i + nu_ j] ...
  std::vector<std::array<double, 2>> w_range_;  // per bucket: its triangles' least and greatest w
};

// Appends a sheet to a geometry for the exact and closest-point trees: face normals, edge
// normals (the sum of the faces' on each side), angle-weighted vertex normals.
void add_sheet(surface::SurfaceGeometry& geometry, const GraphSheet& sheet);

// Throws InputError "MODEL: horizons 'A' and 'B' cross (...) near (x, y, z)" unless `lower`
// lies nowhere above `upper` over the rectangle (layered_order.cpp).
void check_order(const GraphSheet& lower, const GraphSheet& upper, const std::string& model);

// The side of a point towards a sheet, or kUnknown for a sheet whose rectangle the point is
// not over.
inline constexpr int kUnknown = 2;

struct Block {
  Index first_horizon;        // sheet index of its lowest horizon
  Index horizons;             // how many
  std::vector<Index> labels;  // horizons + 1, bottom to top
};

// The sheets nearest to points of one block: the box faces, the faults and its horizons.
struct Nearest {
  explicit Nearest(surface::SurfaceGeometry g) : geometry(std::move(g)), tree(geometry) {}
  surface::SurfaceGeometry geometry;
  surface::ClosestTree tree;
  std::vector<Index> sheet;  // per surface of the geometry: the model's sheet
};

struct Model {
  explicit Model(LayeredModel input);

  // Sheets: the box faces xmin, xmax, ymin, ymax, zmin, zmax (0..5), the faults, then each
  // block's horizons, bottom to top.
  static constexpr Index kFirstFault = 6;
  Box3 box;
  std::string name;
  std::vector<GraphSheet> sheets;
  Index faults = 0;
  std::vector<Block> blocks;
  surface::SurfaceGeometry geometry;  // every sheet; surface index = sheet index
  // Two trees for the segment queries: the box faces and the faults (few triangles, as large
  // as the box), and the horizons. Large triangles in the horizons' tree would grow the
  // boxes of every node above them and slow down every query.
  std::unique_ptr<surface::ExactTree> exact_planes, exact_horizons;
  Index first_horizon_triangle = 0;
  // Every triangle the closed segment meets, by increasing triangle index of `geometry`.
  std::vector<surface::SegmentHit> hits(const Vec3& a, const Vec3& b) const;
  std::vector<Index> regions;

  // The nearest-sheet tree of a block, built on first use (only normal() and surface_name()
  // need it, and it costs as much as the rest of the model).
  const Nearest& nearest(Index block) const;

 private:
  mutable std::unique_ptr<std::once_flag[]> nearest_built_;
  mutable std::vector<std::unique_ptr<Nearest>> nearest_;

 public:
  // The side of p towards sheet s: exact comparisons for the box faces, the located
  // triangle's plane for the others (kUnknown where p is not over their rectangle).
  int side(Index s, const Vec3& p) const {
    if (s < kFirstFault) {
      const double c = s % 2 ? box.hi[s / 2] : box.lo[s / 2];
      return (p[s / 2] > c) - (p[s / 2] < c);
    }
    return sheets[s].over(p) ? sheets[s].side(p) : kUnknown;
  }

  // Whether block b's closure holds a point on the given sides of the faults.
  template <class Side>
  bool in_block(std::size_t b, const Side& side) const {
    for (Index j = 0; j < faults; ++j) {
      const int f = side(kFirstFault + j);
      if (f != 0 && (f > 0) != static_cast<bool>((b >> j) & 1)) return false;
    }
    return true;
  }

  // The region at a point whose side towards sheet s is side(s): 0 outside the closed box;
  // else the highest label among the layers around the point in every block it is in.
  template <class Side>
  Index region(const Side& side) const {
    for (Index k = 0; k < 3; ++k)
      if (side(2 * k) < 0 || side(2 * k + 1) > 0) return 0;
    Index best = 0;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      if (!in_block(b, side)) continue;
      const Block& block = blocks[b];
      // Sides are non-increasing from the lowest horizon up: the layers around the point
      // run from the number of horizons strictly below it to the number below or through it.
      const auto count = [&](auto pred) {
        Index lo = 0, hi = block.horizons;
        while (lo < hi) {
          const Index mid = (lo + hi) / 2;
          if (pred(side(block.first_horizon + mid)))
            lo = mid + 1;
          else
            hi = mid;
        }
        return lo;
      };
      const Index above = count([](int s) { return s > 0; });
      const Index touching = count([](int s) { return s >= 0; });
      for (Index layer = above; layer <= touching; ++layer)
        best = std::max(best, block.labels[layer]);
    }
    return best;
  }

  // Side of p towards each sheet, computed once on demand (kept on the stack for models of
  // up to kSmall sheets: one is made per query).
  class State {
   public:
    State(const Model& m, const Vec3& p) : m_(&m), p_(p) {
      if (m.sheets.size() > kSmall) large_.assign(m.sheets.size(), kNotYet);
      small_.fill(kNotYet);
    }
    int operator()(Index s) const {
      std::int8_t& side = large_.empty() ? small_[s] : large_[s];
      if (side == kNotYet) side = static_cast<std::int8_t>(m_->side(s, p_));
      return side;
    }
    const Vec3& point() const { return p_; }

   private:
    static constexpr std::size_t kSmall = 32;
    static constexpr std::int8_t kNotYet = 3;
    const Model* m_;
    Vec3 p_;
    mutable std::array<std::int8_t, kSmall> small_;
    mutable std::vector<std::int8_t> large_;
  };
  Index region(const Vec3& p) const { return region(State(*this, p)); }
  // The first block whose closure holds a point of the box.
  template <class Side>
  Index block(const Side& side) const {
    for (std::size_t b = 0; b < blocks.size(); ++b)
      if (in_block(b, side)) return static_cast<Index>(b);
    return 0;
  }
};

// Every crossing of segment [a, b] (layered_crossings.cpp).
std::vector<Crossing> crossings(const Model& model, const Vec3& a, const Vec3& b);

}  // namespace volmesh::layers
