// volmesh mesh <method> <domain> -o <out> [--level N] [--json] [--threads T]: the meshers of
// the registry (volmesh/meshers/registry.hpp). Every mesh is checked before it is written.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "mesher_cli.hpp"
#include "progress_line.hpp"
#include "volmesh/runs/thread_limit.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/geometry/tet_decomposition.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/meshers/registry.hpp"
#include "volmesh/runs/mesh_run.hpp"

namespace volmesh::cli {

namespace {

// The share of the progress bar the mesher's own stages take; checking, the decomposition
// into tetrahedra when asked, and writing follow.
constexpr double kMeshingShare = 0.9, kDecomposingAt = 0.93, kWritingAt = 0.96;

struct MeshOptions {
  std::string method, domain, output;
  int level = 5;
  bool level_given = false;  // --level on the command line, not its default
  std::optional<double> size;
  meshers::MethodOptions given;
  std::string decompose;  // "" or "tets"
  bool json = false, quiet = false;
  int threads = 0;
};

int run_mesh(const MeshOptions& opt) {
  const meshers::MesherInfo& info = meshers::find_mesher(opt.method);
  if (!options_apply("mesh", info, opt.given)) return 2;
  const auto threads = limit_threads(opt.threads);
  require_writable_mesh_path(opt.output);

  const Clock::time_point start = Clock::now();
  const std::unique_ptr<Domain> domain = open_domain(opt.domain);
  ProgressLine progress(opt.method, opt.quiet);
  meshers::MeshRequest request;
  request.domain_name = domain_display_name(opt.domain);
  if (info.resolution == meshers::Resolution::level || opt.level_given) request.level = opt.level;
  request.size = opt.size;
  request.options = opt.given;
  request.progress = part_of(progress.progress(), 0.0, kMeshingShare);
  const TimedMesh result = mesh_timed(info, *domain, request);

  // An invalid mesh is a bug in the mesher: say so, and write nothing.
  progress("checking", kMeshingShare);
  const ValidityReport validity = require_valid_output(result.result.mesh, opt.method, opt.domain);
  // The element formats take tetrahedra and hexahedra: --decompose tets writes any mesh to
  // them as conforming tetrahedra. The summary stays the mesher's own.
  std::optional<PolyMesh> tets;
  if (opt.decompose == "tets") {
    progress("decomposing into tetrahedra", kDecomposingAt);
    tets = decompose_into_tets(result.result.mesh, opt.output);
  }
  progress("writing " + opt.output, kWritingAt);
  write_mesh(tets ? *tets : result.result.mesh, opt.output);
  progress.clear();

  const PolyMesh& mesh = result.result.mesh;
  if (opt.json) {
    nlohmann::json j =
        mesh_summary(opt.method, request, mesh, result.result.summary, result.seconds, validity);
    j["output"] = opt.output;
    j["total_seconds"] = seconds_since(start);
    if (tets) j["decomposed"] = {{"tetrahedra", tets->num_cells()}, {"points", tets->num_points()}};
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << opt.output << ": " << opt.method << " mesh of " << request.domain_name;
    if (request.level) std::cout << " at level " << *request.level;
    if (request.size) std::cout << " at size " << *request.size;
    std::cout << ": " << mesh.num_cells() << " cells, " << mesh.num_faces() << " faces, "
              << mesh.num_points() << " vertices, volume " << validity.total_volume << ", "
              << result.seconds << " s";
    if (tets) std::cout << "; written as " << tets->num_cells() << " tetrahedra";
    std::cout << "\n";
  }
  return 0;
}

bool any_mesher_by_size() {
  for (const meshers::MesherInfo& m : meshers::meshers())
    if (m.resolution == meshers::Resolution::size) return true;
  return false;
}

}  // namespace

Command add_mesh_command(CLI::App& root) {
  auto opt = std::make_shared<MeshOptions>();
  CLI::App* app = root.add_subcommand("mesh", "Mesh a domain with one of the methods below");
  app->add_option("method", opt->method, "meshing method (see Methods below)")
      ->required()
      ->check(CLI::IsMember(mesher_names()));
  app->add_option("domain", opt->domain,
                  "builtin:NAME, a closed surface (.stl .off .obj .ply), an image (.inr .nrrd), "
                  "an SDF grid (.rawiv .vti) or a domain file (.json)")
      ->required();
  app->add_option("-o,--output", opt->output, "output mesh (.vtu .msh .mesh .inp DIR.foam/)")
      ->required();
  CLI::Option* level = app->add_option("--level", opt->level,
                  "octree depth at boundaries and interfaces (grid: 2^level cells per axis)")
      ->capture_default_str();
  // The meshers by size check it themselves, naming the domain and the limits they take.
  if (any_mesher_by_size())
    app->add_option_function<double>(
        "--size", [opt](const double& h) { opt->size = h; }, "target edge length");
  add_mesher_options(*app, opt->given, true);
  app->add_option("--decompose", opt->decompose,
                  "write every cell as conforming tetrahedra (for .msh .mesh .inp, which take "
                  "tetrahedra and hexahedra only)")
      ->check(CLI::IsMember({"tets"}));
  app->add_flag("--json", opt->json, "print one JSON object on stdout");
  add_quiet_flag(*app, opt->quiet);
  app->add_option("--threads", opt->threads, "at most this many threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  app->footer(meshers_help() + R"(
Examples:
  volmesh mesh cutcell builtin:primitives --level 5 -o primitives.vtu --json
  volmesh mesh cutcell fandisk.off --level 6 -o fandisk.foam/
  volmesh mesh staircase builtin:ball --level 6 -o ball.vtu
  volmesh mesh staircase part.stl --level 7 -o part.foam/ --json
  volmesh mesh grid builtin:box --level 4 --tets -o box.msh
  volmesh mesh cutcell builtin:primitives --level 4 -o primitives.msh --decompose tets)");
  return {app, [opt, level] {
            opt->level_given = level->count() > 0;
            return run_mesh(*opt);
          }};
}

}  // namespace volmesh::cli
