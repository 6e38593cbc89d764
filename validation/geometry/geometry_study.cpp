// Geometric convergence of one mesher on one domain (docs/verification.md): per level, the
// mesh's region volumes against the exact ones and, for analytic domains, the two-sided
// Hausdorff distance between its boundaries/interfaces and the true surfaces, overall and
// within a band around the sharp edges. One JSON object per level on stdout.
//   geometry_study DOMAIN --method cutcell|midpoint|staircase --levels A..B
//                  [--spacing F] [--feature-band K] [--margin M] [--clearance C]
//                  [--split-gap G]
// DOMAIN: builtin:NAME or a domain file (.json). Samples are h/F apart (default F = 6); the
// feature band is K h (default 2); M is the octree's margin around the bounding box (default:
// OctreeOptions'; 0 puts a box-shaped domain's faces on the octree grid); C is
// CutcellOptions::vertex_clearance (0 moves no grid vertex off the interfaces); G is
// CutcellOptions::split_gap. Exact volumes: exact_region_volumes (built-in domains' closed
// forms, the solid's own volume for a file holding one analytic primitive). The distances are
// surface_distance's against AnalyticSurfaces, the volumes check_validity's.
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "volmesh/core/validity.hpp"
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/io/domain_file.hpp"
#include "volmesh/octree/staircase.hpp"
#include "volmesh/quality/analytic_surfaces.hpp"

namespace {

using namespace volmesh;
using Clock = std::chrono::steady_clock;

struct Arguments {
  std::string domain, method;
  int first = 0, last = 0;
  double spacing = 6.0, band = 2.0;
  std::optional<double> margin;  // unset: the octree's default
  double clearance = CutcellOptions{}.vertex_clearance;
  double split_gap = CutcellOptions{}.split_gap;
};

constexpr const char* kUsage =
    "usage: geometry_study DOMAIN --method cutcell|midpoint|staircase --levels A..B "
    "[--spacing F] [--feature-band K] [--margin M] [--clearance C] [--split-gap G]";

bool parse(int argc, char** argv, Arguments& a) {
  if (argc < 2) return false;
  a.domain = argv[1];
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--method") {
      a.method = value;
    } else if (key == "--levels") {
      if (std::sscanf(value.c_str(), "%d..%d", &a.first, &a.last) != 2) return false;
    } else if (key == "--spacing") {
      a.spacing = std::stod(value);
    } else if (key == "--feature-band") {
      a.band = std::stod(value);
    } else if (key == "--margin") {
      a.margin = std::stod(value);
    } else if (key == "--clearance") {
      a.clearance = std::stod(value);
    } else if (key == "--split-gap") {
      a.split_gap = std::stod(value);
    } else {
      return false;
    }
  }
  return argc % 2 == 0 && (a.method == "cutcell" || a.method == "midpoint" ||
                           a.method == "staircase") &&
         a.first >= 1 && a.last >= a.first && a.spacing > 0.0 && a.band >= 0.0 && a.margin.value_or(0.0) >= 0.0 &&
         a.clearance >= 0.0 && a.split_gap > 0.0 && a.split_gap <= 1.0;
}

std::unique_ptr<Domain> load(const std::string& name) {
  const std::string prefix = "builtin:";
  if (name.starts_with(prefix)) return make_builtin_domain(name.substr(prefix.size()));
  return read_domain_file(name);
}

double cell_size(const Domain& domain, const OctreeOptions& octree, int level) {
  return std::ldexp(octree_root(domain, octree).side, -level);
}

nlohmann::json two_sided(const TwoSidedDistance& d) {
  const auto at = [](const Vec3& p) { return nlohmann::json{p.x(), p.y(), p.z()}; };
  return {{"mesh_to_surface", d.mesh_to_surface.distance},
          {"surface_to_mesh", d.surface_to_mesh.distance},
          {"hausdorff", d.hausdorff()},
          {"mesh_samples", d.mesh_to_surface.points},
          {"surface_samples", d.surface_to_mesh.points},
          {"mesh_worst", at(d.mesh_to_surface.at)},
          {"surface_worst", at(d.surface_to_mesh.at)}};
}

nlohmann::json run_level(const Arguments& a, const Domain& domain,
                         const std::map<Index, double>& exact, int level) {
  OctreeOptions octree;
  octree.level = level;
  octree.margin = a.margin;
  const auto start = Clock::now();
  PolyMesh mesh;
  Index cut_cells = 0, bad_faces = 0;
  if (a.method == "staircase") {
    mesh = staircase_mesh(domain, StaircaseOptions{octree, {}});
  } else {
    CutcellOptions options;
    options.octree = octree;
    options.vertex_clearance = a.clearance;
    options.split_gap = a.split_gap;
    options.interface_points =
        a.method == "midpoint" ? InterfacePoints::midpoint : InterfacePoints::exact;
    CutcellStats stats;
    mesh = cutcell_mesh(domain, options, &stats);
    cut_cells = stats.cut_cells;
    bad_faces = stats.bad_faces;
  }
  const double mesh_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const double h = cell_size(domain, octree, level);

  nlohmann::json row = {{"domain", a.domain}, {"method", a.method}, {"level", level},
                        {"h", h},             {"cells", mesh.num_cells()},
                        {"cut_cells", cut_cells}, {"bad_faces", bad_faces},
                        {"mesh_seconds", mesh_seconds}};
  const std::map<Index, double> volumes = check_validity(mesh).region_volume;
  double total = 0.0, exact_total = 0.0, max_region_error = 0.0;
  nlohmann::json regions = nlohmann::json::object();
  for (const auto& [label, volume] : volumes) total += volume;
  for (const auto& [label, volume] : exact) {
    const auto found = volumes.find(label);
    const double error = (found == volumes.end() ? 0.0 : found->second) - volume;
    regions[std::to_string(label)] = {{"exact", volume}, {"error", error}};
    exact_total += volume;
    max_region_error = std::max(max_region_error, std::abs(error));
  }
  row["volume"] = total;
  row["regions"] = regions;
  if (!exact.empty()) {
    row["exact_volume"] = exact_total;
    row["volume_error"] = std::abs(total - exact_total);
    row["max_region_error"] = max_region_error;
  }

  if (const auto* analytic = dynamic_cast<const AnalyticDomain*>(&domain)) {
    const auto measured = Clock::now();
    const AnalyticSurfaces surfaces(*analytic);
    const SurfaceDistance d =
        surface_distance(mesh, surfaces, {.tolerance = h / a.spacing, .feature_band = a.band * h});
    row["hausdorff"] = two_sided(d.all);
    nlohmann::json features = nlohmann::json::object();
    const std::vector<std::string> groups = surfaces.feature_groups();
    for (std::size_t g = 0; g < d.features.size(); ++g)
      if (d.features[g].surface_to_mesh.points > 0) features[groups[g]] = two_sided(d.features[g]);
    row["features"] = features;
    row["measure_seconds"] = std::chrono::duration<double>(Clock::now() - measured).count();
  }
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments a;
  bool usable = false;
  try {
    usable = parse(argc, argv, a);
  } catch (const std::exception&) {  // a number that is not one
  }
  if (!usable) {
    std::cerr << kUsage << "\n";
    return 2;
  }
  try {
    const std::unique_ptr<Domain> domain = load(a.domain);
    const std::map<Index, double> exact = exact_region_volumes(a.domain, *domain);
    for (int level = a.first; level <= a.last; ++level)
      std::cout << run_level(a, *domain, exact, level).dump() << std::endl;
  } catch (const std::exception& e) {
    // Domain errors name the domain already; the mesher's (e.g. the level) do not.
    const std::string what = e.what();
    std::cerr << (what.starts_with(a.domain) ? what : a.domain + ": " + what) << "\n";
    return 1;
  }
  return 0;
}
