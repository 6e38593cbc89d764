#pragma once
// Region priorities other than "the higher label wins".
#include <memory>
#include <vector>

#include "volmesh/domain/domain.hpp"

namespace volmesh {

// The domain with its labels reordered in priority: `order` lists the labels, highest
// priority first, and must hold every label of the domain once. The inner domain must be one
// where the higher label wins on interfaces (analytic, image and layered domains): it is
// built with label r for the r-th lowest priority, through `rank_of` below, and its regions
// are renamed back. `order` = {3, 1, 2}: on the 1-3 interface 3 wins, on 1-2 1 wins.
std::unique_ptr<Domain> prioritized(std::unique_ptr<Domain> ranked, std::vector<Index> order);
// The rank (1 = lowest priority) of `label` in `order`, 0 if absent.
Index rank_of(const std::vector<Index>& order, Index label);

}  // namespace volmesh
