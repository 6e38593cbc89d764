// volmesh convert <in> <out> [--decompose tets]: between mesh formats, or between surface
// formats. --decompose tets splits every cell that is not a tetrahedron into tetrahedra,
// conforming (geometry/tet_decomposition.hpp), so that a polyhedral mesh reaches the formats
// that take elements only.
#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.hpp"
#include "volmesh/runs/mesh_input.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/geometry/tet_decomposition.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh::cli {

namespace {

struct ConvertOptions {
  std::string input, output;
  std::string decompose;  // "" or "tets"
};

int run_convert(const ConvertOptions& opt) {
  require_known_format(opt.input);
  if (is_surface_file(opt.input)) {
    if (!opt.decompose.empty())
      throw InputError(opt.input + ": --decompose splits volume meshes, not surfaces");
    if (!is_surface_file(opt.output))
      throw InputError(opt.output + ": a surface converts to .stl .off .obj or .ply");
    // Surfaces here bound solids: refuse holes and the like rather than pass them on.
    TriSurface surface = read_surface(opt.input);
    const SurfaceReport report = check_surface(surface, opt.input);
    for (const std::string& w : report.warnings) std::cerr << "warning: " << w << "\n";
    write_surface(surface, opt.output);
    return 0;
  }
  PolyMesh mesh = read_mesh(opt.input);
  // Never pass a broken mesh on to another tool under a new name.
  const ValidityReport r = check_validity(mesh);
  if (!r.valid())
    throw InputError(opt.input + ": invalid mesh, not converted (" +
                     (r.problems.empty() ? std::string("see volmesh check") : r.problems.front()) +
                     ")");
  if (opt.decompose == "tets") {
    const Index cells = mesh.num_cells();
    mesh = decompose_into_tets(mesh, opt.input);
    std::cerr << "decomposed " << cells << " cells into " << mesh.num_cells() << " tetrahedra\n";
  }
  write_mesh(mesh, opt.output);
  std::cerr << "wrote " << opt.output << ": " << mesh.num_cells() << " cells, "
            << mesh.num_points() << " points\n";
  return 0;
}

}  // namespace

Command add_convert_command(CLI::App& root) {
  auto opt = std::make_shared<ConvertOptions>();
  CLI::App* app = root.add_subcommand(
      "convert", "Convert a mesh (.vtu .msh → .vtu .msh .mesh .inp DIR.foam) or a surface");
  app->add_option("input", opt->input, "input mesh or surface")->required();
  app->add_option("output", opt->output, "output file (format from the extension)")->required();
  app->add_option("--decompose", opt->decompose,
                  "split every cell into tetrahedra, conforming (for .msh .mesh .inp)")
      ->check(CLI::IsMember({"tets"}));
  app->footer(R"(Examples:
  volmesh convert mesh.msh case.foam                 Gmsh 4.1 to an OpenFOAM case directory
  volmesh convert cut.vtu cut.inp --decompose tets   polyhedra to Abaqus as conforming tets
  volmesh convert part.stl part.off                  surfaces convert too)");
  return {app, [opt] { return run_convert(*opt); }};
}

}  // namespace volmesh::cli
