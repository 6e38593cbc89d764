#pragma once
// Built-in domains, named as on the command line without the "builtin:" prefix
// (docs/methods.md, "Domains"):
//   box             the unit cube [0, 1]^3
//   ball            the unit ball
//   primitives      the octree paper's §5.2 scene: ball, box and cylinder overlapping, each
//                   overlap its own region (multi-material labels, analytic.hpp):
//                     ball      centre 0, radius 1                        bit 1
//                     box       [0, 1.2] x [-1.2, 1.2] x [-0.6, 1.2]      bit 2
//                     cylinder  axis z through 0, radius 1/2, |z| <= 1.4  bit 4
//                   all seven regions occur; exact volumes (builtin_region_volumes)
//                     1: 1.446763  2: 3.203206  3: 1.273936  4: 0.626808
//                     5: 0.865449  6: 0.104216  7: 0.602642
//   thick-sphere    the hollow ball 1/2 <= |x| <= 1 for the Lamé problem, one region;
//                   surfaces named "inner" and "outer" (AnalyticDomain::surface_name)
//   cube-inclusion  the cube [0, 8]^3 (region 1, surface "outer") with a 3 x 3 x 3 cube
//                   centred at (4, 4, 4) and rotated by the z-x-z Euler angles
//                   (pi/4, pi/6, 0) (region 2, surface "inclusion")
//   layers6         the octree paper's Table 2 case (layered.hpp): six layers,
//                   labels 1 to 6 from the bottom, in the unit cube, between five horizons
//                   z = k/6 + undulations of up to 0.045 (sums of sines, 129 x 129 vertices
//                   each); layer 3 pinches out where y < 0.35 - 0.1 sin(4 pi x) (horizon 3
//                   rests on horizon 2 there, vertex for vertex); the fault x = 0.4 + 0.3 z (dipping 73
//                   degrees) lifts every horizon by 0.1 on its side x > 0.4 + 0.3 z. Exact
//                   volumes of the triangulated model (builtin_region_volumes):
//                     1: 0.220185  2: 0.161633  3: 0.061861  4: 0.261482  5: 0.161674
//                     6: 0.133166
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "volmesh/domain/domain.hpp"

namespace volmesh {

std::vector<std::string> builtin_domain_names();  // sorted
// Throws InputError naming the valid names for an unknown one.
std::unique_ptr<Domain> make_builtin_domain(const std::string& name);
// Exact volume of each region (label -> volume) where it has a closed form; empty otherwise.
std::map<Index, double> builtin_region_volumes(const std::string& name);

}  // namespace volmesh
