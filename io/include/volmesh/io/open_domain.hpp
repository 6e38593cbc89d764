#pragma once
// Opening the <domain> argument of the command line (docs/architecture.md) as a Domain.
//
// Accepted, by prefix or extension (case-insensitive):
//   builtin:NAME             a built-in domain (builtin.hpp)
//   .stl .off .obj .ply      one closed triangulated surface, region 1 inside (SurfaceDomain)
//   .inr .inr.gz             a labelled image, region = label (ImageDomain)
//   .nrrd                    by the header's sample type: an integer type is a labelled image,
//                            float or double a signed-distance grid
//   .rawiv .vti              a signed-distance grid, region 1 where f >= 0 (SdfGridDomain)
//   .json                    a domain file (domain_file.hpp): several surfaces, layers, or
//                            analytic solids
// Throws InputError naming the file (or the built-in name) for a missing file, an unknown
// extension, or anything wrong inside the file.
#include <memory>
#include <string>

#include "volmesh/domain/domain.hpp"

namespace volmesh {

std::unique_ptr<Domain> open_domain(const std::string& spec);

// A short name for reports: "builtin:ball", or the file name without its directory.
std::string domain_display_name(const std::string& spec);

}  // namespace volmesh
