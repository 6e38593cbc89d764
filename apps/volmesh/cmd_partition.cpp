// volmesh partition <mesh> --parts K -o <out.pvtu | out.msh | out.vtu> [--contiguous]
// [--method kway|recursive] [--json] [--quiet]: METIS on the face-adjacency graph, one file
// per part (PVTU), Gmsh partitioned entities (MSH), or the whole mesh with a "partition" cell
// array.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "progress_line.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/partition/partition.hpp"
#include "volmesh/runs/partition_run.hpp"

namespace volmesh::cli {

namespace {

struct PartitionCliOptions {
  std::string mesh, output, method = "kway";
  Index parts = 0;
  bool contiguous = false, json = false, quiet = false;
};

// Where the steps start on the progress bar.
constexpr double kCheckStart = 0.2, kPartitionStart = 0.3, kWriteStart = 0.7;

std::string extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext;
}

nlohmann::json to_json(const PartitionStats& s) {
  return {{"parts", s.parts},
          {"method", s.method},
          {"edge_cut", s.edge_cut},
          {"imbalance", s.imbalance},
          {"all_contiguous", s.all_contiguous()},
          {"contiguity_enforced", s.contiguity_enforced},
          {"mesh_components", s.mesh_components},
          {"part_cells", s.part_cells},
          {"part_interface_faces", s.part_interface_faces},
          {"part_neighbours", s.part_neighbours},
          {"part_components", s.part_components}};
}

void print_stats(std::ostream& os, const std::string& output, Index cells,
                 const PartitionStats& s) {
  os << output << ": " << cells << " cells in " << s.parts << " parts (METIS " << s.method
     << "), edge cut " << s.edge_cut << " faces, imbalance " << s.imbalance << "\n"
     << "  part     cells  interface faces  neighbour parts  pieces\n";
  for (Index p = 0; p < s.parts; ++p)
    os << std::setw(6) << p << std::setw(10) << s.part_cells[p] << std::setw(17)
       << s.part_interface_faces[p] << std::setw(17) << s.part_neighbours[p] << std::setw(8)
       << s.part_components[p] << "\n";
}

int run_partition(const PartitionCliOptions& opt) {
  const Clock::time_point start = Clock::now();
  ProgressLine progress("partition", opt.quiet);
  progress("reading " + opt.mesh, 0.0);
  const PolyMesh mesh = read_mesh(opt.mesh);
  const double read_seconds = seconds_since(start);
  // Never partition (and hand on) a broken mesh.
  const Clock::time_point checking = Clock::now();
  progress("validity", kCheckStart);
  const ValidityReport validity = check_validity(mesh);
  if (!validity.valid())
    throw InputError(
        opt.mesh + ": invalid mesh, not partitioned (" +
        (validity.problems.empty() ? std::string("see volmesh check") : validity.problems.front()) +
        ")");
  const double check_seconds = seconds_since(checking);

  PartitionOptions options;
  options.parts = opt.parts;
  options.contiguous = opt.contiguous;
  options.method = opt.method == "recursive" ? PartitionMethod::Recursive : PartitionMethod::KWay;
  progress("METIS into " + std::to_string(opt.parts) + " parts", kPartitionStart);
  const Partition partition = partition_mesh(mesh, options, opt.mesh);
  const PartitionStats& s = partition.stats;
  progress.clear();
  if (opt.contiguous && !s.contiguity_enforced && opt.parts > 1)
    std::cerr << "warning: " << opt.mesh << ": the mesh is in " << s.mesh_components
              << " disconnected pieces; partitioned without the contiguity constraint\n";

  const Clock::time_point writing = Clock::now();
  progress("writing " + opt.output, kWriteStart);
  write_partitioned(mesh, partition.cell_part, opt.parts, opt.output);
  const double write_seconds = seconds_since(writing);
  progress.clear();

  if (opt.json) {
    nlohmann::json j = to_json(s);
    j["mesh"] = opt.mesh;
    j["output"] = opt.output;
    j["cells"] = mesh.num_cells();
    j["contiguous_requested"] = opt.contiguous;
    j["seconds"] = {{"read", read_seconds},     {"check", check_seconds},
                    {"graph", s.graph_seconds}, {"metis", s.metis_seconds},
                    {"write", write_seconds},   {"total", seconds_since(start)}};
    std::cout << j.dump(2) << "\n";
  } else {
    print_stats(std::cout, opt.output, mesh.num_cells(), s);
  }
  std::cerr << "wrote " << opt.output << " (" << opt.parts << " parts)\n";
  return 0;
}

}  // namespace

Command add_partition_command(CLI::App& root) {
  auto opt = std::make_shared<PartitionCliOptions>();
  CLI::App* app = root.add_subcommand(
      "partition", "Split a mesh into K parts with METIS on its face-adjacency graph");
  app->add_option("mesh", opt->mesh, "mesh (.vtu .msh)")->required();
  app->add_option("--parts", opt->parts, "number of parts K (at most the number of cells)")
      ->required()
      ->check(CLI::Range(1, 1 << 30));
  app->add_option("-o,--output", opt->output,
                  "out.pvtu (one VTU per part in out/), out.msh (Gmsh 4.1 partitioned "
                  "entities) or out.vtu (one file, cell array \"partition\")")
      ->required()
      ->check(CLI::Validator(
          [](std::string& s) {
            const std::string ext = extension(s);
            return ext == ".pvtu" || ext == ".msh" || ext == ".vtu"
                       ? std::string()
                       : "must end in .pvtu, .msh or .vtu";
          },
          "FILE"));
  app->add_option("--method", opt->method,
                  "METIS k-way (default) or recursive bisection (--contiguous always uses k-way)")
      ->check(CLI::IsMember({"kway", "recursive"}))
      ->capture_default_str();
  app->add_flag("--contiguous", opt->contiguous,
                "make every part connected (METIS_OPTION_CONTIG); a mesh in several pieces "
                "is partitioned without it, with a warning");
  app->add_flag("--json", opt->json, "print one JSON object on stdout");
  add_quiet_flag(*app, opt->quiet);
  app->footer("Example: volmesh partition mesh.vtu --parts 8 -o parts.pvtu");
  return {app, [opt] { return run_partition(*opt); }};
}

}  // namespace volmesh::cli
