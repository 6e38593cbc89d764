// One octree of build_octree's for a built-in domain (NAME, as after "builtin:"), built on every rank with p4est or, with --serial, by
// build_octree on one process: one JSON object per rank on stdout, in rank order.
//   bench_octree_dist NAME LEVEL [--base-level B] [--cells-between-levels N] [--serial]
#include <mpi.h>

#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/octree_dist/distributed_octree.hpp"

namespace {

using namespace volmesh;

nlohmann::json serial(const Domain& domain, const OctreeOptions& options) {
  const Clock::time_point start = Clock::now();
  const Octree tree = build_octree(domain, options);
  return {{"ranks", 0}, {"leaves", tree.num_leaves()}, {"seconds", seconds_since(start)}};
}

nlohmann::json distributed(const Domain& domain, const OctreeOptions& options) {
  const DistributedOctree tree = build_distributed_octree(domain, options);
  return {{"rank", tree.rank},
          {"ranks", tree.ranks},
          {"global_leaves", tree.global_leaves},
          {"leaves", tree.leaves.size()},
          {"cut_leaves", std::count(tree.cut.begin(), tree.cut.end(), 1)},
          {"ghosts", tree.ghosts.size()},
          {"refinement_rounds", tree.stats.refinement_rounds},
          {"graded_levels", tree.stats.graded_levels},
          {"seconds", tree.stats.seconds}};
}

// Each rank's line, printed by rank 0 in rank order.
void print_in_rank_order(const std::string& line) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const int length = static_cast<int>(line.size());
  std::vector<int> lengths(ranks), offsets(ranks + 1, 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  for (int r = 0; r < ranks; ++r) offsets[r + 1] = offsets[r] + lengths[r];
  std::string all(rank == 0 ? offsets[ranks] : 0, ' ');
  MPI_Gatherv(line.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  if (rank == 0) std::cout << all;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: bench_octree_dist NAME LEVEL [--base-level B] [--cells-between-levels N] [--serial]\n";
    return 2;
  }
  OctreeOptions options;
  options.level = std::stoi(argv[2]);
  bool one_process = false;
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--serial") {
      one_process = true;
    } else if (arg == "--base-level" && i + 1 < argc) {
      options.base_level = std::stoi(argv[++i]);
    } else if (arg == "--cells-between-levels" && i + 1 < argc) {
      options.cells_between_levels = std::stoi(argv[++i]);
    } else {
      std::cerr << "bench_octree_dist: unknown argument " << arg << "\n";
      return 2;
    }
  }
  try {
    const auto domain = make_builtin_domain(argv[1]);
    if (one_process) {
      std::cout << serial(*domain, options).dump() << "\n";
      return 0;
    }
    MPI_Init(&argc, &argv);
    print_in_rank_order(distributed(*domain, options).dump() + "\n");
    MPI_Finalize();
  } catch (const InputError& e) {
    std::cerr << "bench_octree_dist: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
