#pragma once
// Subcommands of the `volmesh` binary. Each add_* registers its options on the root app and
// returns the function that runs it once the command line is parsed.
#include <functional>

namespace CLI {
class App;
}

namespace volmesh::cli {

struct Command {
  CLI::App* app;
  std::function<int()> run;  // returns the exit code
};

Command add_info_command(CLI::App& root);
Command add_convert_command(CLI::App& root);
Command add_check_command(CLI::App& root);
Command add_demo_command(CLI::App& root);
Command add_sdf_command(CLI::App& root);
Command add_mesh_command(CLI::App& root);
Command add_partition_command(CLI::App& root);
Command add_solve_command(CLI::App& root);
Command add_study_command(CLI::App& root);
Command add_improve_command(CLI::App& root);

}  // namespace volmesh::cli
