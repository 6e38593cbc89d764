// volmesh mesh <method> <domain> -o <out> [--level N] [--json] [--threads T]: the meshers of
// the registry (volmesh/meshers/registry.hpp). Every mesh is checked before it is written.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>

#include "commands.hpp"
#include "mesher_cli.hpp"
#include "progress_line.hpp"
#include "volmesh/runs/thread_limit.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/fem/parallel.hpp"
#include "volmesh/geometry/tet_decomposition.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/io/partitioned_io.hpp"
#include "volmesh/meshers/registry.hpp"
#include "volmesh/runs/mesh_pieces.hpp"
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

meshers::MeshRequest mesh_request(const MeshOptions& opt, const meshers::MesherInfo& info,
                                  const Progress& progress) {
  meshers::MeshRequest request;
  request.domain_name = domain_display_name(opt.domain);
  if (info.resolution == meshers::Resolution::level || opt.level_given) request.level = opt.level;
  request.size = opt.size;
  request.options = opt.given;
  request.progress = part_of(progress, 0.0, kMeshingShare);
  return request;
}

void print_summary_line(const MeshOptions& opt, const meshers::MeshRequest& request,
                        std::int64_t cells, double faces, std::int64_t points, double volume,
                        double mesh_seconds) {
  std::cout << opt.output << ": " << opt.method << " mesh of " << request.domain_name;
  if (request.level) std::cout << " at level " << *request.level;
  if (request.size) std::cout << " at size " << *request.size;
  std::cout << ": " << cells << " cells, " << faces << " faces, " << points << " vertices, volume "
            << volume << ", " << mesh_seconds << " s";
}

int run_mesh_alone(const MeshOptions& opt, const meshers::MesherInfo& info) {
  const bool pieces = std::filesystem::path(opt.output).extension() == ".pvtu";
  if (!pieces) require_writable_mesh_path(opt.output);

  const Clock::time_point start = Clock::now();
  const std::unique_ptr<Domain> domain = open_domain(opt.domain);
  ProgressLine progress(opt.method, opt.quiet);
  const meshers::MeshRequest request = mesh_request(opt, info, progress.progress());
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
  const PolyMesh& written = tets ? *tets : result.result.mesh;
  if (pieces) {
    const MeshPiece piece = pvtu_piece(whole_mesh_piece(written), {}, 0);
    write_pvtu(std::span(&piece, 1), opt.output);
  } else {
    write_mesh(written, opt.output);
  }
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
    print_summary_line(opt, request, mesh.num_cells(), mesh.num_faces(), mesh.num_points(),
                       validity.total_volume, result.seconds);
    if (tets) std::cout << "; written as " << tets->num_cells() << " tetrahedra";
    std::cout << "\n";
  }
  return 0;
}

// Faces counted once over the ranks: a face between two ranks is in both pieces.
double faces_once(const PolyMesh& piece) {
  double count = 0.0;
  for (Index f = 0; f < piece.num_faces(); ++f)
    count += piece.is_boundary(f) && piece.tag_names[piece.face_tag[f]].starts_with(kPieceBoundaryPrefix)
                 ? 0.5
                 : 1.0;
  return count;
}

// The regions over all ranks, each with its cells and volume, on rank 0.
nlohmann::json regions_over_ranks(const PolyMesh& piece, const ValidityReport& validity) {
  std::vector<double> mine;  // (region, cells, volume) per region of the piece
  const nlohmann::json own = region_summary(piece, validity);
  for (const auto& [region, summary] : own.items())
    mine.insert(mine.end(), {std::stod(region), summary["cells"].get<double>(),
                             summary["volume"].get<double>()});
  const std::vector<double> all = fem::gather_to_all(mine.data(), mine.size());
  std::map<Index, std::pair<double, double>> regions;
  for (std::size_t k = 0; k < all.size(); k += 3) {
    auto& [cells, volume] = regions[static_cast<Index>(all[k])];
    cells += all[k + 1];
    volume += all[k + 2];
  }
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [region, sums] : regions)
    out[std::to_string(region)] = {{"cells", static_cast<std::int64_t>(sums.first)},
                                   {"volume", sums.second}};
  return out;
}

// Under mpirun: every rank meshes its piece and writes it (mesh_pieces.hpp), rank 0 reports.
// Each step is a stage (fem::stage): a failure on any rank ends every rank.
int run_mesh_on_ranks(const MeshOptions& opt, const meshers::MesherInfo& info) {
  const Clock::time_point start = Clock::now();
  const bool rank_zero = fem::rank() == 0;
  std::unique_ptr<Domain> domain;
  fem::stage("mesh", [&] { domain = open_domain(opt.domain); });
  ProgressLine progress(opt.method, opt.quiet || !rank_zero);
  const meshers::MeshRequest request = mesh_request(opt, info, progress.progress());
  progress("meshing on " + std::to_string(fem::ranks()) + " ranks", 0.0);
  const Clock::time_point meshing = Clock::now();
  RankMesh m = mesh_on_every_rank(info, *domain, request);
  const double mesh_seconds = fem::max_over_ranks(seconds_since(meshing));

  progress("checking", kMeshingShare);
  ValidityReport validity;
  fem::stage("check", [&] {
    validity = require_valid_output(m.piece.mesh, opt.method, opt.domain);
  });
  const nlohmann::json regions = regions_over_ranks(m.piece.mesh, validity);
  double sums[2] = {faces_once(m.piece.mesh), validity.total_volume};
  fem::sum_over_ranks(sums, 2);
  const std::int64_t cells = m.piece.global_cell_count, points = m.piece.global_point_count;
  progress("writing " + opt.output, kWritingAt);
  write_rank_piece(std::move(m.piece), {}, opt.output);
  progress.clear();
  const double total_seconds = fem::max_over_ranks(seconds_since(start));
  if (!rank_zero) return 0;

  if (opt.json) {
    nlohmann::json j = request_summary(opt.method, request, mesh_seconds);
    j["output"] = opt.output;
    j["total_seconds"] = total_seconds;
    j["regions"] = regions;
    j["ranks"] = fem::ranks();
    j["cells"] = cells;
    j["faces"] = static_cast<std::int64_t>(sums[0]);
    j["vertices"] = points;
    j["volume"] = sums[1];
    j["h"] = m.h;
    std::cout << j.dump(2) << "\n";
  } else {
    print_summary_line(opt, request, cells, sums[0], points, sums[1], mesh_seconds);
    std::cout << "; " << fem::ranks() << " pieces\n";
  }
  return 0;
}

// Why a run under mpirun meshes on rank 0 alone ("" when every rank meshes its piece).
std::string why_rank_zero_alone(const MeshOptions& opt, const meshers::MesherInfo& info) {
  const std::string why = why_not_on_every_rank(info, opt.given);
  if (!why.empty()) return why;
  if (!opt.decompose.empty()) return "--decompose writes one file";
  if (std::filesystem::path(opt.output).extension() != ".pvtu")
    return "the ranks write their pieces to a .pvtu, not " + opt.output;
  return "";
}

int run_mesh(const MeshOptions& opt) {
  const meshers::MesherInfo& info = meshers::find_mesher(opt.method);
  if (!options_apply("mesh", info, opt.given)) return 2;
  const auto threads = limit_threads(opt.threads);
  if (!fem::distributed_run()) return run_mesh_alone(opt, info);
  const std::string why = why_rank_zero_alone(opt, info);
  if (why.empty()) return run_mesh_on_ranks(opt, info);
  if (fem::rank() == 0) std::cerr << "note: " << why << ": rank 0 meshes alone\n";
  int code = 0;
  fem::stage("mesh", [&] {
    if (fem::rank() == 0) code = run_mesh_alone(opt, info);
  });
  return code;
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
