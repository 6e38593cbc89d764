// volmesh.Mesh and the calls on meshes: mesh, read, write, check, partition, improve, methods.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <map>
#include <numeric>

#include "convert.hpp"
#include "handles.hpp"
#include "long_call.hpp"
#include "options.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/geometry/tet_decomposition.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/partition/partition.hpp"
#include "volmesh/runs/check_run.hpp"
#include "volmesh/runs/partition_run.hpp"
#include "volmesh/runs/improve_run.hpp"
#include "volmesh/runs/mesh_run.hpp"

namespace volmesh::python {

using namespace pybind11::literals;

namespace {

using MeshClass = py::class_<Mesh, std::shared_ptr<Mesh>>;

const char* resolution_name(meshers::Resolution r) {
  switch (r) {
    case meshers::Resolution::level:
      return "level";
    case meshers::Resolution::size:
      return "size";
    case meshers::Resolution::surface:
      return "surface";
  }
  return "";
}

const char* type_name(meshers::OptionSpec::Type t) {
  switch (t) {
    case meshers::OptionSpec::Type::flag:
      return "flag";
    case meshers::OptionSpec::Type::integer:
      return "integer";
    case meshers::OptionSpec::Type::real:
      return "real";
    case meshers::OptionSpec::Type::choice:
      return "choice";
    case meshers::OptionSpec::Type::text:
      return "text";
  }
  return "";
}

// The registry as data: what volmesh.mesh takes.
py::list methods() {
  py::list out;
  for (const meshers::MesherInfo& m : meshers::meshers()) {
    py::list options;
    for (const meshers::OptionSpec& s : meshers::options_of(m)) {
      std::string keyword = s.name;
      std::replace(keyword.begin(), keyword.end(), '-', '_');
      py::dict o("name"_a = keyword, "help"_a = s.help, "type"_a = type_name(s.type));
      if (s.type == meshers::OptionSpec::Type::integer || s.type == meshers::OptionSpec::Type::real)
        o["range"] = py::make_tuple(s.min, s.max);
      if (s.type == meshers::OptionSpec::Type::choice) o["choices"] = s.choices;
      options.append(o);
    }
    out.append(py::dict("name"_a = m.name, "description"_a = m.description,
                        "resolution"_a = resolution_name(m.resolution),
                        "default_domain"_a = m.default_domain, "options"_a = options));
  }
  return out;
}

// The validity check of a mesher's mesh, as `volmesh mesh` runs it before writing: throws
// "METHOD produced an invalid mesh of DOMAIN (...)" for a mesh that fails it.
const nlohmann::json& figures(Mesh& m) {
  if (!m.mesher) return m.figures;
  const MesherReport& r = *m.mesher;
  LongCall call(py::none(), 0);
  m.figures = call([&] {
    const ValidityReport validity =
        cli::require_valid_output(m.mesh, r.method, r.request.domain_name);
    nlohmann::json j = cli::mesh_summary(r.method, r.request, m.mesh, r.summary, r.seconds, validity);
    j["h"] = r.h;
    return j;
  });
  m.mesher.reset();
  return m.figures;
}

std::shared_ptr<Mesh> mesh_domain(const std::string& method, py::handle domain_spec,
                                  std::optional<int> level, std::optional<double> size,
                                  py::handle progress, int threads, const py::kwargs& options) {
  const meshers::MesherInfo& info = meshers::find_mesher(method);
  meshers::MeshRequest request;
  request.options = method_options(info, options);
  const DomainHandle domain = to_domain(domain_spec);
  request.domain_name = domain.name;
  request.level = level;
  request.size = size;
  LongCall call(progress, threads);
  request.progress = call.progress();
  auto out = std::make_shared<Mesh>();
  call([&] {
    cli::TimedMesh timed = cli::mesh_timed(info, *domain.domain, request);
    request.progress = nullptr;
    out->mesher = MesherReport{method, request, std::move(timed.result.summary), timed.seconds,
                               timed.result.h};
    out->mesh = std::move(timed.result.mesh);
  });
  out->name = method + " mesh of " + domain.name;
  out->default_space = info.default_space;
  return out;
}

std::shared_ptr<Mesh> read(py::handle path_object, py::handle progress) {
  const std::string path = path_from(path_object);
  auto out = std::make_shared<Mesh>();
  out->name = path;
  LongCall call(progress, 0);
  out->mesh = call([&] { return read_mesh(path); });
  return out;
}

void write(Mesh& m, py::handle path_object, std::optional<std::string> decompose) {
  const std::string path = path_from(path_object);
  // A mesher's mesh is checked as `volmesh mesh` checks it, any other as `volmesh convert`.
  const bool from_mesher = m.mesher.has_value();
  figures(m);
  if (decompose && *decompose != "tets")
    throw InputError("decompose=" + *decompose + ": the only decomposition is \"tets\"");
  LongCall call(py::none(), 0);
  call([&] {
    if (std::filesystem::path(path).extension() != ".pvtu") require_writable_mesh_path(path);
    // Never pass a broken mesh on under a new name.
    const ValidityReport r = from_mesher ? ValidityReport{} : check_validity(m.mesh);
    if (!from_mesher && !r.valid())
      throw InputError(m.name + ": invalid mesh, not written to " + path + " (" +
                       (r.problems.empty() ? std::string("see volmesh check") : r.problems.front()) +
                       ")");
    const PolyMesh tets = decompose ? decompose_into_tets(m.mesh, path) : PolyMesh{};
    const PolyMesh& out = decompose ? tets : m.mesh;
    // A .pvtu is one piece, as `volmesh partition --parts 1` writes it.
    if (std::filesystem::path(path).extension() == ".pvtu")
      cli::write_partitioned(out, std::vector<Index>(out.num_cells(), 0), 1, path);
    else
      write_mesh(out, path);
  });
}

py::object check(const Mesh& m, py::handle surface, py::handle progress) {
  cli::ReferenceOpener reference;
  if (py::isinstance<Surface>(surface)) {
    const auto s = surface.cast<std::shared_ptr<Surface>>();
    reference = [s](const ValidityReport&) { return cli::surface_reference(s->surface, s->name); };
  } else if (!surface.is_none()) {
    const std::string spec = path_from(surface);
    reference = [spec](const ValidityReport& v) { return cli::open_reference(spec, v); };
  }
  LongCall call(progress, 0);
  const nlohmann::json j = call([&] {
    return cli::to_json(cli::check_mesh(m.mesh, reference, call.progress()), m.mesh, m.name);
  });
  return to_python(j);
}

py::array partition(py::object self, Index parts, bool contiguous, const std::string& method,
                    py::handle output) {
  const Mesh& m = self.cast<Mesh&>();
  if (method != "kway" && method != "recursive")
    throw InputError("method=" + method + ": kway or recursive");
  PartitionOptions options;
  options.parts = parts;
  options.contiguous = contiguous;
  options.method = method == "recursive" ? PartitionMethod::Recursive : PartitionMethod::KWay;
  const std::string output_path = output.is_none() ? std::string() : path_from(output);
  LongCall call(py::none(), 0);
  auto result = std::make_shared<Partition>(call([&] {
    const ValidityReport r = check_validity(m.mesh);
    if (!r.valid())
      throw InputError(m.name + ": invalid mesh, not partitioned (" +
                       (r.problems.empty() ? std::string("see volmesh check") : r.problems.front()) +
                       ")");
    Partition p = partition_mesh(m.mesh, options, m.name);
    if (!output.is_none()) cli::write_partitioned(m.mesh, p.cell_part, parts, output_path);
    return p;
  }));
  py::capsule owner(new std::shared_ptr<Partition>(result),
                    [](void* p) { delete static_cast<std::shared_ptr<Partition>*>(p); });
  return view(result->cell_part, owner);
}

std::shared_ptr<Mesh> improve(const Mesh& m, py::handle surface, std::optional<double> max_seconds,
                              py::handle progress, int threads) {
  TriSurface slide_on;
  if (py::isinstance<Surface>(surface))
    slide_on = surface.cast<std::shared_ptr<Surface>>()->surface;
  else if (!surface.is_none())
    slide_on = read_surface(path_from(surface));
  LongCall call(progress, threads);
  auto out = std::make_shared<Mesh>();
  out->name = m.name;
  call([&] {
    cli::Improved improved = cli::improve_checked(
        cli::tet_mesh_to_improve(m.mesh, m.name), slide_on,
        max_seconds.value_or(std::numeric_limits<double>::infinity()), m.name, call.progress());
    out->figures = cli::improve_summary(improved.stats);
    out->mesh = std::move(improved.mesh);
  });
  return out;
}

// Cells in meshio's form: runs of tetrahedra and hexahedra as (k, 4) and (k, 8) arrays in
// cell order; or, when any cell is another polyhedron, every cell as a list of outward face
// arrays in blocks "polyhedron<N>" by their number N of vertices, increasing, each in cell
// order (meshio's VTU writer takes no mix of polyhedra and elements, and its reader gives the
// cell data back in that order only).
CellBlocks cell_blocks(const PolyMesh& mesh) {
  const CellFaces cell_faces = build_cell_faces(mesh);
  std::vector<CellCorners> corners(mesh.num_cells());
  bool elements = true;
  for (Index c = 0; c < mesh.num_cells() && elements; ++c) {
    corners[c] = classify_cell(mesh, cell_faces, c);
    elements = corners[c].shape != CellShape::Polyhedron;
  }
  CellBlocks out;
  if (!elements) {
    std::map<std::size_t, std::vector<Index>> by_vertices;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      std::vector<Index> vertices;
      for (const Index f : cell_faces.of(c))
        vertices.insert(vertices.end(), mesh.face(f).begin(), mesh.face(f).end());
      std::sort(vertices.begin(), vertices.end());
      by_vertices[std::unique(vertices.begin(), vertices.end()) - vertices.begin()].push_back(c);
    }
    for (const auto& [n, cells] : by_vertices) {
      py::list data;
      for (const Index c : cells) {
        py::list faces;
        for (const Index f : cell_faces.of(c)) {
          const std::span<const Index> loop = mesh.face(f);
          std::vector<Index> v(loop.begin(), loop.end());
          if (mesh.owner[f] != c) std::reverse(v.begin(), v.end());  // outward from c
          faces.append(py::array_t<Index>(static_cast<py::ssize_t>(v.size()), v.data()));
        }
        data.append(faces);
      }
      out.blocks.append(py::make_tuple("polyhedron" + std::to_string(n), data));
      out.order.insert(out.order.end(), cells.begin(), cells.end());
    }
    return out;
  }
  for (Index begin = 0; begin < mesh.num_cells();) {
    const CellShape shape = corners[begin].shape;
    Index end = begin;
    while (end < mesh.num_cells() && corners[end].shape == shape) ++end;
    const py::ssize_t width = shape == CellShape::Tetrahedron ? 4 : 8;
    py::array_t<Index> data({static_cast<py::ssize_t>(end - begin), width});
    auto d = data.mutable_unchecked<2>();
    for (Index c = begin; c < end; ++c)
      for (py::ssize_t k = 0; k < width; ++k) d(c - begin, k) = corners[c].corners[k];
    out.blocks.append(py::make_tuple(shape == CellShape::Tetrahedron ? "tetra" : "hexahedron", data));
    begin = end;
  }
  out.order.resize(mesh.num_cells());
  std::iota(out.order.begin(), out.order.end(), 0);
  return out;
}

}  // namespace

CellBlocks mesh_cell_blocks(const PolyMesh& mesh) { return cell_blocks(mesh); }

void bind_mesh(py::module_& m) {
  MeshClass mesh(m, "Mesh",
                 "A volume mesh (face-based, like OpenFOAM's polyMesh). Its arrays are read-only "
                 "views that keep the mesh alive.");
  mesh.def_property_readonly("points",
                             [](py::object self) { return view(self.cast<Mesh&>().mesh.points, self); })
      .def_property_readonly(
          "regions", [](py::object self) { return view(self.cast<Mesh&>().mesh.cell_region, self); },
          "The region of each cell (>= 1).")
      .def_property_readonly(
          "face_offsets",
          [](py::object self) { return view(self.cast<Mesh&>().mesh.face_offsets, self); },
          "Face f's vertices are face_vertices[face_offsets[f]:face_offsets[f + 1]].")
      .def_property_readonly(
          "face_vertices",
          [](py::object self) { return view(self.cast<Mesh&>().mesh.face_vertices, self); })
      .def_property_readonly(
          "owner", [](py::object self) { return view(self.cast<Mesh&>().mesh.owner, self); },
          "The cell each face's normal points out of.")
      .def_property_readonly(
          "neighbour", [](py::object self) { return view(self.cast<Mesh&>().mesh.neighbour, self); },
          "The cell on the other side of each face, -1 on the boundary.")
      .def_property_readonly(
          "face_tags", [](py::object self) { return view(self.cast<Mesh&>().mesh.face_tag, self); },
          "The boundary tag of each face (an index into tag_names), -1 inside.")
      .def_property_readonly("tag_names", [](const Mesh& self) { return self.mesh.tag_names; })
      .def_property_readonly("cells", [](const Mesh& self) { return cell_blocks(self.mesh).blocks; },
                             "The cells as meshio takes them: a list of (type, data) blocks, "
                             "tetra and hexahedron in cell order, or polyhedron<N> blocks of "
                             "face arrays by vertex count (a copy).")
      .def_property_readonly("figures", [](Mesh& self) { return to_python(figures(self)); },
                             "What made the mesh reports, as `volmesh mesh --json` prints it "
                             "(a mesher's mesh is checked first, as the command checks it).")
      .def_readonly("name", &Mesh::name)
      .def_property_readonly("num_cells", [](const Mesh& self) { return self.mesh.num_cells(); })
      .def_property_readonly("num_faces", [](const Mesh& self) { return self.mesh.num_faces(); })
      .def_property_readonly("num_points", [](const Mesh& self) { return self.mesh.num_points(); })
      .def("write", &write, py::arg("path"), py::arg("decompose") = py::none(),
           "Writes by extension (.vtu .pvtu .msh .mesh .inp DIR.foam), as `volmesh mesh -o` does; "
           "decompose=\"tets\" writes every cell as conforming tetrahedra first.")
      .def("__repr__", [](const Mesh& self) {
        return "<volmesh.Mesh " + self.name + ": " + std::to_string(self.mesh.num_cells()) +
               " cells, " + std::to_string(self.mesh.num_points()) + " points>";
      });

  m.def("methods", &methods, "The meshers of the registry with their options.");
  m.def("mesh", &mesh_domain, py::arg("method"), py::arg("domain"), py::kw_only(),
        py::arg("level") = py::none(), py::arg("size") = py::none(),
        py::arg("progress") = py::none(), py::arg("threads") = 0,
        "Meshes a domain (anything volmesh.domain takes) with a method of the registry at a "
        "level or a size; its options as keywords, named as on the command line with _ for - "
        "(cells_between_levels=2). The mesh passes the validity check, as `volmesh mesh`'s.");
  m.def("read", &read, py::arg("path"), py::arg("progress") = py::none(),
        "Reads a mesh: .vtu .pvtu .msh .mesh .node/.ele or an OpenFOAM case.");
  m.def("check", &check, py::arg("mesh"), py::arg("surface") = py::none(),
        py::arg("progress") = py::none(),
        "`volmesh check --json`'s report: validity, quality and, against a surface (a "
        "volmesh.Surface, a surface file or an analytic domain such as builtin:ball), the volume "
        "error and the Hausdorff distance.");
  m.def("partition", &partition, py::arg("mesh"), py::arg("parts"), py::arg("contiguous") = false,
        py::arg("method") = "kway", py::arg("output") = py::none(),
        "The part of each cell: METIS on the face-adjacency graph; output= writes the parts as "
        "`volmesh partition -o` does (.pvtu, .msh or .vtu).");
  m.def("improve", &improve, py::arg("mesh"), py::arg("surface") = py::none(),
        py::arg("max_seconds") = py::none(), py::arg("progress") = py::none(),
        py::arg("threads") = 0,
        "A tet mesh with its worst dihedral angles raised, its boundary kept (or sliding on "
        "`surface`); its figures as `volmesh improve --json`'s.");
  bind_meshio(m, mesh);
}

}  // namespace volmesh::python
