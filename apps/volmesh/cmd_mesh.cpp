// volmesh mesh <method> <domain> -o <out> [--level N] [--json] [--threads T]: the meshers
// behind one dispatch table (DESIGN.md §3). Every mesh is checked before it is written.
#include <CLI/CLI.hpp>
#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <numbers>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "reports.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/octree/staircase.hpp"

namespace volmesh::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct MeshOptions {
  std::string method, domain, output;
  std::string interface_points = "exact";
  int level = 5;
  int base_level = OctreeOptions{}.base_level;
  int cells_between_levels = OctreeOptions{}.cells_between_levels;
  double feature_angle = 0.0;  // degrees; 0: the paper's threshold
  int crossing_levels = -1;    // -1: CutcellOptions' default
  bool tets = false, json = false;
  int threads = 0;
};

// What a method returns: the mesh and its own figures for the report.
struct MethodResult {
  PolyMesh mesh;
  nlohmann::json details = nlohmann::json::object();
};

// Stage lines on stderr once a run has taken more than a second.
class StageLog {
 public:
  explicit StageLog(std::string what) : what_(std::move(what)), start_(Clock::now()) {}
  void operator()(const std::string& stage) const {
    const double t = seconds_since(start_);
    if (t > 1.0) std::cerr << what_ << ": " << stage << " (" << t << " s)\n";
  }

 private:
  std::string what_;
  Clock::time_point start_;
};

MethodResult mesh_grid(const Domain& domain, const MeshOptions& opt) {
  if (opt.level > 10)
    throw InputError("grid: --level " + std::to_string(opt.level) + " gives " +
                     std::to_string(std::int64_t{1} << (3 * opt.level)) +
                     " cells, beyond the index limit (at most --level 10)");
  if (opt.level < 0) throw InputError("grid: --level must be at least 0");
  const Box3 box = domain.bounds();
  if (!box.lo.allFinite() || !box.hi.allFinite() || !((box.hi - box.lo).minCoeff() > 0.0))
    throw InputError(opt.domain + ": empty or flat bounding box; no grid to build");
  const Index n = Index{1} << opt.level;
  MethodResult r;
  r.mesh = opt.tets ? to_poly_mesh(kuhn_tet_mesh(box.lo, box.hi, {n, n, n}))
                    : to_poly_mesh(structured_hex_mesh(box.lo, box.hi, {n, n, n}));
  r.details = {{"cells_per_axis", n}, {"element", opt.tets ? "tet" : "hex"}};
  return r;
}

OctreeOptions octree_options(const MeshOptions& opt) {
  OctreeOptions o;
  o.level = opt.level;
  o.base_level = opt.base_level;
  o.cells_between_levels = opt.cells_between_levels;
  return o;
}

MethodResult mesh_staircase(const Domain& domain, const MeshOptions& opt) {
  const StageLog log("staircase");
  StaircaseOptions options;
  options.octree = octree_options(opt);
  options.progress = [&log](const std::string& stage, double) { log(stage); };
  StaircaseStats stats;
  MethodResult r;
  r.mesh = staircase_mesh(domain, options, &stats);
  r.details = {{"leaves", stats.leaves},
               {"octree_seconds", stats.octree_seconds},
               {"mesh_seconds", stats.mesh_seconds}};
  return r;
}

MethodResult mesh_cutcell(const Domain& domain, const MeshOptions& opt) {
  const StageLog log("cutcell");
  CutcellOptions options;
  options.octree = octree_options(opt);
  options.interface_points =
      opt.interface_points == "midpoint" ? InterfacePoints::midpoint : InterfacePoints::exact;
  if (opt.feature_angle > 0.0) options.feature_theta = std::cos(opt.feature_angle * std::numbers::pi / 180.0);
  if (opt.crossing_levels >= 0) options.crossing_levels = opt.crossing_levels;
  options.progress = [&log](const std::string& stage, double) { log(stage); };
  CutcellStats stats;
  MethodResult r;
  r.mesh = cutcell_mesh(domain, options, &stats);
  r.details = {{"leaves", stats.leaves},
               {"cut_cells", stats.cut_cells},
               {"max_leaf_level", stats.max_leaf_level},
               {"interface_points", opt.interface_points},
               {"feature_angle", std::acos(options.feature_theta) * 180.0 / std::numbers::pi},
               {"crossing_levels", options.crossing_levels},
               {"moved_vertices", stats.moved_vertices},
               {"split_edges", stats.split_edges},
               {"feature_points", stats.feature_points},
               {"min_cell_volume_ratio", stats.min_cell_volume_ratio},
               {"max_skewness", stats.max_skewness},
               {"max_non_orthogonality", stats.max_non_orthogonality},
               {"split_cells", stats.split_cells},
               {"merged_cells", stats.merged_cells},
               {"joined_faces", stats.joined_faces},
               {"bad_faces", stats.bad_faces},
               {"octree_seconds", stats.octree_seconds},
               {"cut_seconds", stats.cut_seconds}};
  return r;
}

using Mesher = MethodResult (*)(const Domain&, const MeshOptions&);

// Adding a method is one line here.
const std::map<std::string, Mesher>& methods() {
  static const std::map<std::string, Mesher> table{
      {"cutcell", mesh_cutcell},
      {"grid", mesh_grid},
      {"staircase", mesh_staircase},
  };
  return table;
}

nlohmann::json region_summary(const PolyMesh& mesh, const ValidityReport& validity) {
  std::map<Index, Index> cells;
  for (const Index r : mesh.cell_region) ++cells[r];
  nlohmann::json regions = nlohmann::json::object();
  for (const auto& [region, count] : cells) {
    const auto volume = validity.region_volume.find(region);
    regions[std::to_string(region)] = {
        {"cells", count},
        {"volume", volume == validity.region_volume.end() ? 0.0 : volume->second}};
  }
  return regions;
}

int run_mesh(const MeshOptions& opt) {
  if (opt.tets && opt.method != "grid") {
    std::cerr << "volmesh mesh: --tets applies to the grid method only\n";
    return 2;
  }
  if (opt.interface_points != "exact" && opt.method != "cutcell") {
    std::cerr << "volmesh mesh: --interface-points applies to the cutcell method only\n";
    return 2;
  }
  if (opt.cells_between_levels != 1 && opt.method == "grid") {
    std::cerr << "volmesh mesh: --cells-between-levels applies to the octree methods only\n";
    return 2;
  }
  if (opt.feature_angle > 0.0 && opt.method != "cutcell") {
    std::cerr << "volmesh mesh: --feature-angle applies to the cutcell method only\n";
    return 2;
  }
  if (opt.crossing_levels >= 0 && opt.method != "cutcell") {
    std::cerr << "volmesh mesh: --crossing-levels applies to the cutcell method only\n";
    return 2;
  }
  std::unique_ptr<tbb::global_control> threads;
  if (opt.threads > 0)
    threads = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(opt.threads));
  require_writable_mesh_path(opt.output);

  const Clock::time_point start = Clock::now();
  const std::unique_ptr<Domain> domain = open_domain(opt.domain);
  const Clock::time_point meshing = Clock::now();
  MethodResult result = methods().at(opt.method)(*domain, opt);
  const double mesh_seconds = seconds_since(meshing);

  // An invalid mesh is a bug in the mesher: say so, and write nothing.
  const ValidityReport validity = check_validity(result.mesh);
  if (!validity.valid())
    throw std::runtime_error(opt.method + " produced an invalid mesh of " + opt.domain + " (" +
                             (validity.problems.empty() ? std::string("see volmesh check")
                                                        : validity.problems.front()) +
                             "); nothing written");
  write_mesh(result.mesh, opt.output);

  const PolyMesh& mesh = result.mesh;
  if (opt.json) {
    nlohmann::json j{{"method", opt.method},
                     {"domain", domain_display_name(opt.domain)},
                     {"output", opt.output},
                     {"level", opt.level},
                     {"base_level", opt.base_level},
                     {"cells_between_levels", opt.cells_between_levels},
                     {"time_seconds", mesh_seconds},
                     {"total_seconds", seconds_since(start)},
                     {"cells", mesh.num_cells()},
                     {"faces", mesh.num_faces()},
                     {"vertices", mesh.num_points()},
                     {"regions", region_summary(mesh, validity)},
                     {"validity", to_json(validity)}};
    j.update(result.details);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << opt.output << ": " << opt.method << " mesh of " << domain_display_name(opt.domain)
              << " at level " << opt.level << ": " << mesh.num_cells() << " cells, "
              << mesh.num_faces() << " faces, " << mesh.num_points() << " vertices, volume "
              << validity.total_volume << ", " << mesh_seconds << " s\n";
  }
  return 0;
}

}  // namespace

Command add_mesh_command(CLI::App& root) {
  auto opt = std::make_shared<MeshOptions>();
  CLI::App* app = root.add_subcommand("mesh", "Mesh a domain (octree cut cells, octree staircase, Cartesian grid)");
  std::vector<std::string> names;
  for (const auto& entry : methods()) names.push_back(entry.first);
  app->add_option("method", opt->method, "meshing method")
      ->required()
      ->check(CLI::IsMember(names));
  app->add_option("domain", opt->domain,
                  "builtin:NAME, a closed surface (.stl .off .obj .ply), an image (.inr .nrrd), "
                  "an SDF grid (.rawiv .vti) or a domain file (.json)")
      ->required();
  app->add_option("-o,--output", opt->output, "output mesh (.vtu .msh .mesh .inp DIR.foam/)")
      ->required();
  app->add_option("--level", opt->level,
                  "octree depth at boundaries and interfaces (grid: 2^level cells per axis)")
      ->capture_default_str();
  app->add_option("--base-level", opt->base_level,
                  "octree: uniform depth everywhere before refining toward the interfaces")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app->add_option("--cells-between-levels", opt->cells_between_levels,
                  "octree: cells of each level across before the next coarser one begins "
                  "(snappyHexMesh's nCellsBetweenLevels; 1: 2:1 balance only)")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  app->add_flag("--tets", opt->tets, "grid: split each hex into 6 Kuhn tetrahedra");
  app->add_option("--interface-points", opt->interface_points,
                  "cutcell: exact crossings (default) or edge midpoints (M3C as published)")
      ->check(CLI::IsMember({"exact", "midpoint"}));
  app->add_option("--feature-angle", opt->feature_angle,
                  "cutcell: keep a bend of the surface sharper than this many degrees as a sharp "
                  "edge (default 25.8, the paper's cosine 0.9)")
      ->check(CLI::Range(1.0, 90.0));
  app->add_option("--crossing-levels", opt->crossing_levels,
                  "cutcell: levels below --level to which a leaf with an edge crossed by the "
                  "interfaces more than once is still split (default " +
                      std::to_string(CutcellOptions{}.crossing_levels) +
                      "; 0: the paper's meshes, fewer cut cells, faster, thin features coarser)")
      ->check(CLI::Range(0, 8));
  app->add_flag("--json", opt->json, "print one JSON object on stdout");
  app->add_option("--threads", opt->threads, "at most this many threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  app->footer(R"(Examples:
  volmesh mesh cutcell builtin:primitives --level 5 -o primitives.vtu --json
  volmesh mesh cutcell fandisk.off --level 6 -o fandisk.foam/
  volmesh mesh staircase builtin:ball --level 6 -o ball.vtu
  volmesh mesh staircase part.stl --level 7 -o part.foam/ --json
  volmesh mesh grid builtin:box --level 4 --tets -o box.msh)");
  return {app, [opt] { return run_mesh(*opt); }};
}

}  // namespace volmesh::cli
