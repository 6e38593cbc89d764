// classify_leaves without a table of every corner: the leaves go in runs along the Morton
// curve, each run a compact block (neighbours along the curve are neighbours in space) whose
// corners index a dense grid at the run's finest spacing, so that a corner shared by leaves
// of the run is asked of the domain once.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "refine_stages.hpp"

namespace volmesh::octree_dist {
namespace {

// Grid points per run at most: a uniform level's 4096 leaves straddling two blocks of 16^3
// fit (33^3), and the grid stays within the cache.
constexpr std::uint64_t kMaxRunPoints = 40 * 40 * 40;

class Run {
 public:
  Run(const Octree& frame, const Domain& domain) : frame_(frame), domain_(domain) {}

  // Adds the leaf, classifying the run before when its grid would outgrow kMaxRunPoints.
  void add(p8est_quadrant_t& q) {
    const OctreeLeaf leaf = to_leaf(q);
    if (!leaves_.empty() && !fits(leaf)) classify();
    if (leaves_.empty()) {
      lo_ = leaf.anchor;
      hi_ = leaf.corner(7);
      spacing_ = leaf.size();
    } else {
      for (int a = 0; a < 3; ++a) {
        lo_[a] = std::min(lo_[a], leaf.anchor[a]);
        hi_[a] = std::max(hi_[a], leaf.anchor[a] + leaf.size());
      }
      spacing_ = std::min(spacing_, leaf.size());
    }
    leaves_.push_back(&q);
  }

  void classify() {
    if (leaves_.empty()) return;
    for (int a = 0; a < 3; ++a) points_[a] = (hi_[a] - lo_[a]) / spacing_ + 1;
    regions_.assign(points_[0] * points_[1] * points_[2], kNoIndex);
    for (p8est_quadrant_t* q : leaves_) {
      const OctreeLeaf leaf = to_leaf(*q);
      const Index first = region(leaf.corner(0));
      bool differ = false;
      for (int k = 1; k < 8 && !differ; ++k) differ = region(leaf.corner(k)) != first;
      leaf_data(*q).state = differ ? LeafState::cut : LeafState::uncut;
    }
    leaves_.clear();
  }

 private:
  bool fits(const OctreeLeaf& leaf) const {
    const std::uint32_t spacing = std::min(spacing_, leaf.size());
    std::uint64_t points = 1;
    for (int a = 0; a < 3; ++a)
      points *= (std::max(hi_[a], leaf.anchor[a] + leaf.size()) - std::min(lo_[a], leaf.anchor[a])) / spacing + 1;
    return points <= kMaxRunPoints;
  }

  Index region(const GridPoint& p) {
    const std::uint64_t i =
        ((p[2] - lo_[2]) / spacing_ * points_[1] + (p[1] - lo_[1]) / spacing_) * points_[0] + (p[0] - lo_[0]) / spacing_;
    if (regions_[i] == kNoIndex) regions_[i] = domain_.region(frame_.world(p));
    return regions_[i];
  }

  const Octree& frame_;
  const Domain& domain_;
  std::vector<p8est_quadrant_t*> leaves_;
  GridPoint lo_{}, hi_{};  // the run's box
  std::uint32_t spacing_ = 0;  // its finest leaf's edge
  std::array<std::uint64_t, 3> points_{};
  std::vector<Index> regions_;  // per grid point, kNoIndex until asked
};

}  // namespace

void classify_leaves(p8est_t* forest, const Octree& frame, const Domain& domain) {
  Run run(frame, domain);
  for_each_leaf(forest, [&run](p8est_quadrant_t& q) {
    if (leaf_data(q).state == LeafState::unknown) run.add(q);
  });
  run.classify();
}

}  // namespace volmesh::octree_dist
