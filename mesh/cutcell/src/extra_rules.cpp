#include "extra_rules.hpp"

#include <algorithm>

namespace volmesh::cutcell {

std::uint8_t transversal_crossings(const std::vector<Crossing>& hits) {
  const auto n = std::count_if(hits.begin(), hits.end(), [](const Crossing& c) { return c.before != c.after; });
  return static_cast<std::uint8_t>(std::min<std::ptrdiff_t>(n, 255));
}

void RuleCandidates::add_leaf(Index leaf, int most_crossed_edge) {
  leaves.push_back(leaf);
  most_crossed.push_back(most_crossed_edge);
}

void RuleCandidates::add_transition_face(int face, const Vec3& centre, double size) {
  segment_leaf.push_back(leaves.size() - 1);
  from.push_back(centre);
  to.push_back(centre + (face & 1 ? -1.0 : 1.0) * size * Vec3::Unit(face / 2));
}

std::vector<Index> leaves_selected(const RuleCandidates& candidates, const Domain& domain, double clearance) {
  std::vector<std::uint8_t> flag(candidates.leaves.size(), 0);
  for (std::size_t k = 0; k < flag.size(); ++k) flag[k] = candidates.most_crossed[k] > 1;
  if (clearance > 0.0) {
    std::vector<std::vector<Crossing>> hits;
    domain.crossings(candidates.from, candidates.to, hits);
    for (std::size_t s = 0; s < hits.size(); ++s) {
      const auto first = std::find_if(hits[s].begin(), hits[s].end(), [](const Crossing& c) { return c.before != c.after; });
      if (first != hits[s].end() && first->t < clearance) flag[candidates.segment_leaf[s]] = 1;
    }
  }
  std::vector<Index> out;
  for (std::size_t k = 0; k < flag.size(); ++k)
    if (flag[k]) out.push_back(candidates.leaves[k]);
  return out;
}

}  // namespace volmesh::cutcell
