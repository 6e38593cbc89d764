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
//                   (pi/4, pi/6, 0) (region 2, surface "inclusion"); triangulated
//                   (builtin_surfaces), the outer faces in squares of side 2 and the
//                   inclusion's in squares of side 1.5, each split in two
//   layers6         the octree paper's Table 2 case (layered.hpp): six layers,
//                   labels 1 to 6 from the bottom, in the unit cube, between five horizons
//                   z = k/6 + undulations of up to 0.045 (sums of sines, 129 x 129 vertices
//                   each); layer 3 pinches out where y < 0.35 - 0.1 sin(4 pi x) (horizon 3
//                   rests on horizon 2 there, vertex for vertex); the fault x = 0.4 + 0.3 z (dipping 73
//                   degrees) lifts every horizon by 0.1 on its side x > 0.4 + 0.3 z. Exact
//                   volumes of the triangulated model (builtin_region_volumes):
//                     1: 0.220185  2: 0.161633  3: 0.061861  4: 0.261482  5: 0.161674
//                     6: 0.133166
//   twisted-prism:K:DEG
//                   a surface domain, one region: the prism over the regular K-gon of
//                   circumradius 1 (vertices at angles 2 pi i / K in z = 0), height 1, its
//                   top turned by DEG degrees counter-clockwise; each side quad split along
//                   its reflex diagonal (from bottom vertex i to top vertex i + 1), the caps
//                   fanned from vertex 0 (no Steiner points): 2K vertices, 4K - 4
//                   triangles. K = 3..64; DEG in (0, 180 (K - 2) / K), the K-gon's interior
//                   angle, at which the reflex diagonals meet on the axis (60 for K = 3, 90
//                   for K = 4). Volume K/6 (2 sin(2 pi / K) + sin(2 pi / K + w) - sin w),
//                   w the twist in radians.
//   schoenhardt     Schönhardt's polyhedron, which no tetrahedralization without Steiner
//                   points fills: twisted-prism:3:30 (6 vertices, 8 triangles, volume
//                   sqrt(3)/2)
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "volmesh/domain/domain.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh {

// Sorted; a family with parameters appears as its pattern ("twisted-prism:K:DEG").
std::vector<std::string> builtin_domain_names();
// Each throws InputError naming the valid names for an unknown name, or naming the built-in
// and the range for a family's parameters out of range.
std::unique_ptr<Domain> make_builtin_domain(const std::string& name);
// Exact volume of each region (label -> volume) where it has a closed form; empty otherwise.
std::map<Index, double> builtin_region_volumes(const std::string& name);
// The triangulated boundary of a built-in bounded by polyhedra, labelled as its regions
// (box, cube-inclusion, schoenhardt, twisted-prism:K:DEG): closed, manifold, outward, free
// of degenerate triangles and self-intersections. Empty for the others, whose boundaries
// are curved (ball, primitives, thick-sphere) or open sheets (layers6).
std::vector<LabelledSurface> builtin_surfaces(const std::string& name);

}  // namespace volmesh
