// volmesh: one binary, subcommands (docs/architecture.md). Exit codes: 0 success, 2 bad usage,
// 1 bad input or failure with one line on stderr.
#include <CLI/CLI.hpp>
#include <iostream>
#include <new>
#include <vector>

#include "commands.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/meshers/registry.hpp"

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace {

// The meshers build and drop tables of tens of megabytes pass after pass. glibc hands large
// blocks back to the system on free, and every pass would pay its page faults again (up to
// a tenth of a run); kept in the heap, they are reused: blocks up to kMmapThreshold come
// from the heap, which is trimmed only past kTrimThreshold of free memory and grows by
// kTopPad at a time.
constexpr int kMmapThreshold = 32 << 20;
constexpr int kTrimThreshold = 1 << 30;
constexpr int kTopPad = 256 << 20;

void keep_freed_memory() {
#ifdef __GLIBC__
  mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
  mallopt(M_TOP_PAD, kTopPad);
#endif
}

}  // namespace

int main(int argc, char** argv) {
  using namespace volmesh;
  keep_freed_memory();
  CLI::App app{"volmesh — volume meshing (" + meshers::mesher_names() +
               "), checking, partitioning, Poisson and elasticity solves, export"};
  app.set_version_flag("--version", std::string("volmesh ") + VOLMESH_VERSION);
  app.require_subcommand(1);
  app.footer(R"(Examples:
  volmesh info elephant.off                 counts, bounding box, closedness, volume
  volmesh check mesh.vtu --surface part.stl validity, quality, distance to the surface
  volmesh check mesh.vtu --json             the same as one JSON object on stdout
  volmesh convert mesh.msh case.foam        Gmsh 4.1 to an OpenFOAM case directory
  volmesh convert part.stl part.off         surfaces convert too)");

  std::vector<cli::Command> commands{cli::add_info_command(app), cli::add_convert_command(app),
                                     cli::add_check_command(app), cli::add_demo_command(app),
                                     cli::add_sdf_command(app), cli::add_mesh_command(app), cli::add_partition_command(app), cli::add_solve_command(app),
                                     cli::add_study_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  try {
    for (auto& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const InputError& e) {
    std::cerr << "volmesh: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "volmesh: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "volmesh: error: " << e.what() << "\n";
    return 1;
  }
  return 2;
}
