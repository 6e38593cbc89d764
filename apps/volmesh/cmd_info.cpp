// volmesh info <mesh | surface>: counts, bounding box, validity, enclosed volume.
#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.hpp"
#include "volmesh/runs/reports.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh::cli {

namespace {

struct InfoOptions {
  std::string input;
  bool json = false;
};

void print_box(const Box& b) {
  std::cout << "bounding box (" << b.lo.transpose() << ") - (" << b.hi.transpose()
            << "), diagonal " << b.diagonal() << "\n";
}

int run_info(const InfoOptions& opt) {
  require_known_format(opt.input);
  nlohmann::json j{{"file", opt.input}};
  bool ok = true;
  Box box;
  if (is_surface_file(opt.input)) {
    TriSurface s = read_surface(opt.input);
    const SurfaceReport r = check_surface(s, opt.input);
    box = bounding_box(s.points);
    j.update(surface_info(r, s));
    if (!opt.json) {
      std::cout << opt.input << ": surface\n";
      print_surface(std::cout, r);
    }
  } else {
    const PolyMesh m = read_mesh(opt.input);
    const ValidityReport r = check_validity(m);
    ok = r.valid();
    box = bounding_box(m.points);
    j["kind"] = "mesh";
    j["validity"] = to_json(r);
    if (!opt.json) {
      std::cout << opt.input << ": mesh\n";
      print_validity(std::cout, r);
    }
  }
  j["bounding_box"] = to_json(box);
  if (opt.json)
    std::cout << j.dump(2) << "\n";
  else
    print_box(box);
  if (!ok) std::cerr << "volmesh: error: " << opt.input << ": the mesh is invalid (see above)\n";
  return ok ? 0 : 1;
}

}  // namespace

Command add_info_command(CLI::App& root) {
  auto opt = std::make_shared<InfoOptions>();
  CLI::App* app = root.add_subcommand(
      "info", "Counts, bounding box, validity and enclosed volume of a mesh or a surface");
  app->add_option("input", opt->input, "mesh (.vtu .msh) or surface (.stl .off .obj .ply)")
      ->required();
  app->add_flag("--json", opt->json, "print one JSON object on stdout");
  app->footer(R"(Examples:
  volmesh info elephant.off                          counts, bounding box, closedness, volume
  volmesh info mesh.vtu --json)");
  return {app, [opt] { return run_info(*opt); }};
}

}  // namespace volmesh::cli
