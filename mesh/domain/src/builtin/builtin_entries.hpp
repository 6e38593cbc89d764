#pragma once
// One entry per built-in domain, and one per family of built-ins with parameters; each
// group of built-ins (analytic solids, layers, polyhedra) provides its lists, and
// builtin_registry.cpp joins them.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "volmesh/domain/analytic.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh {

struct BuiltinDomain {
  std::string name;
  std::function<std::unique_ptr<Domain>()> make;
  std::function<std::map<Index, double>()> region_volumes;  // exact, or empty
  // The triangulated boundary, labelled as the domain's regions; null where it is curved.
  std::function<std::vector<LabelledSurface>()> surfaces;
};

// A family such as "twisted-prism:K:DEG": a name belongs to it when it starts with the
// pattern's stem (up to its first ':') followed by ':'.
struct BuiltinFamily {
  std::string pattern;
  // The built-in of that name; throws InputError naming it if its parameters are malformed
  // or out of range.
  std::function<BuiltinDomain(const std::string& name)> instance;
};

std::vector<BuiltinDomain> analytic_builtin_domains();
std::vector<BuiltinDomain> layered_builtin_domains();
std::vector<BuiltinDomain> polyhedral_builtin_domains();
std::vector<BuiltinFamily> polyhedral_builtin_families();

// The surface of the box [lo, hi] moved by `frame`, oriented outward, with every face cut
// into squares x squares rectangles that share their corners across the box's edges. On the
// faces across axis a, with u = a + 1 and v = a + 2 (mod 3), every rectangle is split along
// its diagonal from least (u, v) to greatest (u, v).
TriSurface box_surface(const Vec3& lo, const Vec3& hi, int squares, const Rigid& frame = {});

}  // namespace volmesh
