// volmesh.solve(...) → Solution and volmesh.study.convergence(...): `volmesh solve` and
// `volmesh study convergence` on one process (mpirun stays the command line's).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>

#include "convert.hpp"
#include "handles.hpp"
#include "long_call.hpp"
#include "options.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/runs/distributed.hpp"
#include "volmesh/runs/mesh_run.hpp"
#include "volmesh/runs/solve_run.hpp"
#include "volmesh/runs/study_run.hpp"

namespace volmesh::python {

using namespace pybind11::literals;

namespace {

// The share of the progress that meshing takes when solve meshes (as the command line's).
constexpr double kMeshShare = 0.5;

struct Solution {
  std::shared_ptr<Mesh> mesh;
  cli::SolveRun run;
  nlohmann::json figures;
};

cli::SolverBackend backend(const std::string& name) {
  const auto& names = cli::solver_backends();
  const auto it = names.find(name);
  if (it == names.end()) throw InputError("solver=" + name + ": auto, eigen or petsc");
  return it->second;
}

cli::ProblemSpec problem_spec(const std::optional<std::string>& problem,
                              const std::optional<std::string>& exact,
                              const std::optional<std::string>& source, double k) {
  return {problem.value_or(""), exact.value_or(""), source.value_or(""), k};
}

// The field named `name` of the solution, as an (n,) or (n, components) view.
py::object field(py::object self, const std::string& name) {
  const Solution& s = self.cast<Solution&>();
  for (const std::vector<Field>* fields : {&s.run.fields.point, &s.run.fields.cell})
    for (const Field& f : *fields)
      if (f.name == name)
        return view(f.values.data(), f.values.size() / f.components,
                    f.components == 1 ? 0 : f.components, self);
  return py::none();
}

std::shared_ptr<Solution> solve(const std::string& kind, std::optional<std::string> problem,
                                std::shared_ptr<Mesh> mesh, std::optional<std::string> method,
                                py::handle domain_spec, std::optional<int> level,
                                std::optional<std::string> space, std::optional<std::string> exact,
                                std::optional<std::string> source, double k,
                                const std::string& solver, int threads, py::handle progress,
                                const py::kwargs& options) {
  if (kind != "poisson" && kind != "elasticity")
    throw InputError("kind=" + kind + ": poisson or elasticity");
  cli::SolveRequest request{.kind = kind,
                            .problem = problem_spec(problem, exact, source, k),
                            .space = space.value_or(""),
                            .solver = {backend(solver), nullptr}};
  cli::require_problem_kind(kind, request.problem);
  if (mesh && method) throw InputError("solve: give mesh= or method=, not both");
  if (!mesh && !method) throw InputError("solve: give a mesh (mesh=) or a method (method=, level=)");
  LongCall call(progress, threads);
  auto out = std::make_shared<Solution>();
  std::shared_ptr<const Domain> domain;
  std::string domain_name;
  nlohmann::json meshed = nlohmann::json::object();  // the mesher's method, h and level
  std::optional<meshers::MeshRequest> mesh_request;
  const meshers::MesherInfo* info = nullptr;
  if (mesh) {
    if (!options.empty())
      throw InputError(py::str(options.begin()->first).cast<std::string>() +
                       " is a meshing option: it needs method=");
    out->mesh = mesh;
    request.own_boundary = domain_spec.is_none();
    if (request.own_boundary) {
      domain = cli::mesh_as_domain(mesh->mesh, mesh->name);
      domain_name = mesh->name;
    } else {
      const DomainHandle d = to_domain(domain_spec);
      domain = d.domain;
      domain_name = d.name;
    }
  } else {
    info = &meshers::find_mesher(*method);
    if (!level && info->resolution != meshers::Resolution::surface)
      throw InputError("method=" + *method + ": needs level=");
    const DomainHandle d = to_domain(domain_spec.is_none() ? py::str(info->default_domain) : domain_spec);
    domain = d.domain;
    domain_name = d.name;
    request.default_space = info->default_space;
    mesh_request = cli::uniform_request(d.name, level.value_or(0), method_options(*info, options),
                                        part_of(call.progress(), 0.0, kMeshShare, "meshing: "));
    if (!level) mesh_request->level.reset();
  }
  call([&] {
    if (mesh_request) {
      meshers::MeshResult m = meshers::mesh(*info, *domain, *mesh_request);
      out->mesh = std::make_shared<Mesh>();
      out->mesh->mesh = std::move(m.mesh);
      out->mesh->name = *method + " mesh of " + domain_name;
      out->mesh->default_space = info->default_space;
      meshed = {{"method", *method}, {"h", m.h}};
      if (level) meshed["level"] = *level;
    }
    const double start = mesh_request ? kMeshShare : 0.0;
    try {
      out->run = cli::solve_problem(request, *domain, out->mesh->mesh,
                                    part_of(call.progress(), start, 1.0));
    } catch (const InputError& e) {
      // As the command line: what the problem finds wrong with a mesh file names the file.
      if (mesh_request) throw;
      throw InputError(out->mesh->name + ": " + e.what());
    }
  });
  out->figures = cli::solve_summary(request, out->run, domain_name, out->mesh->mesh);
  out->figures.update(meshed);
  return out;
}

std::pair<int, int> levels_of(py::handle levels) {
  if (py::isinstance<py::str>(levels)) return cli::parse_levels(levels.cast<std::string>());
  if (py::isinstance<py::int_>(levels)) return {levels.cast<int>(), levels.cast<int>()};
  const auto pair = levels.cast<std::vector<int>>();
  if (pair.size() != 2) throw InputError("levels: expected \"A..B\", (A, B) or N");
  return {pair[0], pair[1]};
}

py::dict convergence(std::optional<std::string> problem, py::handle methods, py::handle levels,
                     py::handle domain, std::optional<std::string> space,
                     std::optional<std::string> exact, std::optional<std::string> source,
                     double k, const std::string& solver, py::handle output_path, int threads,
                     py::handle progress, const py::kwargs& options) {
  const std::optional<std::string> output =
      output_path.is_none() ? std::nullopt : std::optional(path_from(output_path));
  cli::StudySpec spec;
  spec.problem = problem_spec(problem, exact, source, k);
  spec.methods = py::isinstance<py::str>(methods)
                     ? std::vector<std::string>{methods.cast<std::string>()}
                     : methods.cast<std::vector<std::string>>();
  if (spec.methods.empty()) throw InputError("methods: none given");
  spec.options = method_options(meshers::find_mesher(spec.methods.front()), options);
  // The study opens its domain by name, as the command line's: builtin:NAME or a file.
  if (!domain.is_none()) spec.domain = path_from(domain);
  spec.space = space.value_or("");
  spec.solver = backend(solver);
  std::tie(spec.first_level, spec.last_level) = levels_of(levels);
  LongCall call(progress, threads);
  const nlohmann::json summary = call([&] {
    const cli::StudyOutcome outcome = cli::run_study(spec, call.progress());
    if (output) cli::write_study_outputs(*output, outcome);
    return cli::study_summary(outcome);
  });
  py::list rows;
  py::dict slopes;
  for (const nlohmann::json& s : summary["series"]) {
    for (const nlohmann::json& level : s["levels"]) {
      py::dict row = to_python(level);
      row["label"] = s["label"].get<std::string>();
      row["method"] = s["method"].get<std::string>();
      row["space"] = s["space"].get<std::string>();
      rows.append(row);
    }
    slopes[py::str(s["label"].get<std::string>())] = to_python(s["slope"]);
  }
  py::object png = py::none();
  if (output) png = py::str((std::filesystem::path(*output) / "convergence.png").string());
  return py::dict("rows"_a = rows, "slopes"_a = slopes, "png"_a = png,
                  "summary"_a = to_python(summary));
}

}  // namespace

void bind_solve(py::module_& m) {
  py::class_<Solution, std::shared_ptr<Solution>>(m, "Solution",
                                                  "A solve's result on its mesh")
      .def_property_readonly(
          "u",
          [](py::object self) {
            const py::object u = field(self, "u");
            return u.is_none() ? field(self, "displacement") : u;
          },
          "The solution: (n,) at the points (or the cells for finite volumes), (n, 3) "
          "displacements for elasticity.")
      .def_property_readonly("error", [](py::object self) { return field(self, "error"); },
                             "u_h - u where the problem has an exact solution, else None.")
      .def_property_readonly("errors",
                             [](const Solution& s) { return to_python(s.figures["errors"]); },
                             "{'l2', 'linf', 'h1'}, or None without an exact solution.")
      .def_property_readonly("figures", [](const Solution& s) { return to_python(s.figures); },
                             "As `volmesh solve --json` prints them, but the seconds.")
      .def_readonly("mesh", &Solution::mesh)
      .def(
          "write",
          [](const Solution& s, py::handle path) {
            const std::string p = path_from(path);
            LongCall call(py::none(), 0);
            call([&] { cli::write_solution(s.mesh->mesh, s.run.fields, {}, p); });
          },
          py::arg("path"), "Writes the mesh with the solution (.vtu), as `volmesh solve -o`.");

  m.def("solve", &solve, py::arg("kind") = "poisson", py::kw_only(),
        py::arg("problem") = py::none(), py::arg("mesh") = py::none(),
        py::arg("method") = py::none(), py::arg("domain") = py::none(),
        py::arg("level") = py::none(), py::arg("space") = py::none(),
        py::arg("exact") = py::none(), py::arg("source") = py::none(), py::arg("k") = 1.0,
        py::arg("solver") = "auto", py::arg("threads") = 0, py::arg("progress") = py::none(),
        "Poisson or linear elasticity, as `volmesh solve`, on one process: on a Mesh (its own "
        "boundary the true one unless domain= is given), or on a domain meshed by a method at "
        "a level (the same depth inside); the method's options as keywords.");

  py::module_ study = m.def_submodule("study", "Convergence studies");
  study.def("convergence", &convergence, py::kw_only(), py::arg("problem") = py::none(),
            py::arg("methods"), py::arg("levels"), py::arg("domain") = py::none(),
            py::arg("space") = py::none(), py::arg("exact") = py::none(),
            py::arg("source") = py::none(), py::arg("k") = 1.0, py::arg("solver") = "auto",
            py::arg("output") = py::none(), py::arg("threads") = 0,
            py::arg("progress") = py::none(),
            "`volmesh study convergence` on one process: rows (one dict per method and level), "
            "slopes (per series and norm), and with output=DIR the CSV, the PNG (its path as "
            "'png') and summary.json written there; 'summary' is the whole --json object.");
}

}  // namespace volmesh::python
