// METIS partitioning of one mesh into K = 2 .. 64 parts with k-way and recursive bisection:
// graph time, METIS time (wall, and CPU including the statistics), edge cut (faces between
// parts), imbalance, contiguity. One JSON object per line on stdout.
//   bench_partition --grid N [--parts 2,4,8] [--method kway|recursive|all]
//   bench_partition --tets N [...]      N^3 cubes split into 6 Kuhn tets each
//   bench_partition mesh.vtu [...] [--contiguous]
//   bench_partition --grid N --write mesh.msh --parts ''   writes the mesh (for gmsh) only
#include <chrono>
#include <ctime>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/partition/partition.hpp"

namespace {

using namespace volmesh;

std::vector<Index> parse_list(const std::string& text) {
  std::vector<Index> values;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) values.push_back(std::stoi(item));
  return values;
}

int run(int argc, char** argv) {
  std::string mesh_file, methods = "all", write_file;
  Index grid = 0;
  bool tets = false, contiguous = false;
  std::vector<Index> parts{2, 4, 8, 16, 32, 64};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--grid" || arg == "--tets") && i + 1 < argc) {
      grid = std::stoi(argv[++i]);
      tets = arg == "--tets";
    } else if (arg == "--parts" && i + 1 < argc) {
      parts = parse_list(argv[++i]);
    } else if (arg == "--method" && i + 1 < argc) {
      methods = argv[++i];
    } else if (arg == "--contiguous") {
      contiguous = true;
    } else if (arg == "--write" && i + 1 < argc) {
      write_file = argv[++i];
    } else {
      mesh_file = arg;
    }
  }
  if (grid < 1 && mesh_file.empty()) {
    std::cerr << "usage: bench_partition (--grid N | --tets N | MESH) [--parts 2,4,..] "
                 "[--method M] [--contiguous] [--write FILE]\n";
    return 2;
  }
  const std::string name =
      grid > 0 ? (tets ? "Kuhn tets " : "hex grid ") + std::to_string(grid) + "^3" : mesh_file;
  const std::array<Index, 3> n{grid, grid, grid};
  const PolyMesh mesh = grid == 0 ? read_mesh(mesh_file)
                        : tets    ? to_poly_mesh(kuhn_tet_mesh(Vec3::Zero(), Vec3::Ones(), n))
                               : to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), n));

  if (!write_file.empty()) write_mesh(mesh, write_file);

  const auto start = std::chrono::steady_clock::now();
  const DualGraph graph = build_dual_graph(mesh, name);
  const double graph_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<PartitionMethod> runs;
  if (methods == "all" || methods == "kway") runs.push_back(PartitionMethod::KWay);
  if (methods == "all" || methods == "recursive") runs.push_back(PartitionMethod::Recursive);
  for (Index k : parts)
    for (PartitionMethod method : runs) {
      PartitionOptions options;
      options.parts = k;
      options.method = method;
      options.contiguous = contiguous;
      const std::clock_t cpu_start = std::clock();
      const PartitionStats s = partition_graph(graph, options, name).stats;
      const double cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
      const nlohmann::json j{{"mesh", name},
                             {"cells", mesh.num_cells()},
                             {"graph_edges", graph.num_edges()},
                             {"graph_seconds", graph_seconds},
                             {"parts", k},
                             {"method", s.method},
                             {"metis_seconds", s.metis_seconds},
                             {"cpu_seconds", cpu_seconds},
                             {"edge_cut", s.edge_cut},
                             {"imbalance", s.imbalance},
                             {"contiguous", s.all_contiguous()},
                             {"contiguity_enforced", s.contiguity_enforced},
                             {"filled_empty_parts", s.filled_empty_parts}};
      std::cout << j.dump() << std::endl;
    }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "bench_partition: error: " << e.what() << "\n";
    return 1;
  }
}
