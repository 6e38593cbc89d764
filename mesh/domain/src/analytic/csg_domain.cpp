// CSG solids and labelled layers compiled into region tables: the table entry of a bitmask
// is the label of the last layer whose solid contains such points.
#include <string>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/analytic_csg.hpp"

namespace volmesh {

AnalyticDomain layered_domain(const std::vector<Layer>& layers) {
  std::vector<Primitive> primitives;
  for (const Layer& layer : layers) {
    if (layer.label < 1)
      throw InputError("analytic domain: layer label " + std::to_string(layer.label) +
                       " must be >= 1");
    const auto& p = layer.solid.primitives();
    primitives.insert(primitives.end(), p.begin(), p.end());
  }
  // Too many primitives: an empty table, for the AnalyticDomain constructor to report.
  const std::size_t n = primitives.size();
  std::vector<Index> table(n <= AnalyticDomain::kMaxPrimitives ? std::size_t{1} << n : 0, 0);
  for (std::size_t m = 0; m < table.size(); ++m) {
    std::size_t offset = 0;
    for (const Layer& layer : layers) {
      const std::size_t k = layer.solid.primitives().size();
      if (layer.solid.contains(static_cast<std::uint32_t>(m >> offset & ((1u << k) - 1))))
        table[m] = layer.label;
      offset += k;
    }
  }
  return AnalyticDomain(std::move(primitives), std::move(table));
}

AnalyticDomain solid_domain(const Solid& solid) { return layered_domain({{solid, 1}}); }

}  // namespace volmesh
