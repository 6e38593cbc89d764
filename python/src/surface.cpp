// volmesh.surface(vertices, triangles), volmesh.info(surface), volmesh.sdf(surface, dim).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "convert.hpp"
#include "handles.hpp"
#include "long_call.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/io/voxel_grid_io.hpp"
#include "volmesh/runs/mesh_input.hpp"
#include "volmesh/runs/reports.hpp"

namespace volmesh::python {

namespace {

std::shared_ptr<Surface> make_surface(py::handle vertices, py::handle triangles,
                                      const std::string& name) {
  auto s = std::make_shared<Surface>();
  s->name = name;
  s->surface.points = points_from(vertices, name, "vertex");
  const std::vector<Index> corners =
      indices_from(triangles, 3, s->surface.num_points(), name, "triangle");
  for (std::size_t t = 0; t < corners.size(); t += 3)
    s->surface.triangles.push_back({corners[t], corners[t + 1], corners[t + 2]});
  // Refuses an open or non-manifold surface with one line; orients it outward.
  s->report = check_surface(s->surface, name);
  return s;
}

std::shared_ptr<Surface> read_checked_surface(const std::string& path) {
  auto s = std::make_shared<Surface>();
  s->name = path;
  s->surface = read_surface(path);
  s->report = check_surface(s->surface, path);
  return s;
}

// A Surface, or a surface file's path.
std::shared_ptr<Surface> surface_of(py::handle object) {
  if (py::isinstance<Surface>(object)) return object.cast<std::shared_ptr<Surface>>();
  return read_checked_surface(path_from(object));
}

py::array sdf(py::handle surface_object, Index dim, double margin, py::handle output_path,
              py::handle progress, int threads) {
  const std::shared_ptr<Surface> s = surface_of(surface_object);
  const std::optional<std::string> output =
      output_path.is_none() ? std::nullopt : std::optional(path_from(output_path));
  if (dim > cli::kMaxSdfDim || !is_octree_dim(dim))
    throw InputError("dim " + std::to_string(dim) + ": must be 2^k + 1, from 3 to " +
                     std::to_string(cli::kMaxSdfDim));
  LongCall call(progress, threads);
  auto grid = std::make_unique<VoxelGrid>(call([&] {
    const SignedDistance distance(s->surface, s->name);
    VoxelGrid g = sdf_layout(distance.bounds(), dim, margin);
    distance.sample(g, [&](double fraction) { report(call.progress(), "distances", fraction); });
    if (output) write_rawiv(g, *output);
    return g;
  }));
  // Indexed [i, j, k] along x, y, z: the grid's x-fastest order is numpy's Fortran order.
  const py::ssize_t n = dim, item = sizeof(float);
  py::capsule owner(grid.get(), [](void* g) { delete static_cast<VoxelGrid*>(g); });
  const VoxelGrid* g = grid.release();
  py::array a(py::dtype::of<float>(), {n, n, n}, {item, item * n, item * n * n},
              g->values.data(), owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

}  // namespace

void bind_surface(py::module_& m) {
  py::class_<Surface, std::shared_ptr<Surface>>(m, "Surface",
                                                "A closed triangulated surface, checked")
      .def_property_readonly(
          "vertices", [](py::object self) { return view(self.cast<Surface&>().surface.points, self); })
      .def_property_readonly("triangles",
                             [](py::object self) {
                               const TriSurface& s = self.cast<Surface&>().surface;
                               return view(s.triangles.empty() ? nullptr : s.triangles.front().data(),
                                           s.triangles.size(), 3, self);
                             })
      .def_readonly("name", &Surface::name)
      .def(
          "write", [](const Surface& s, py::handle path) { write_surface(s.surface, path_from(path)); },
          py::arg("path"), "Writes by extension: .stl (binary) .off .obj .ply.")
      .def("__repr__", [](const Surface& s) {
        return "<volmesh.Surface " + s.name + ": " + std::to_string(s.surface.num_points()) +
               " vertices, " + std::to_string(s.surface.num_triangles()) + " triangles>";
      });

  m.def("surface", &make_surface, py::arg("vertices"), py::arg("triangles"),
        py::arg("name") = "surface",
        "A closed surface from an (n, 3) array of vertices and an (m, 3) array of triangles "
        "(any numeric dtypes); checked as a surface file is (closed, manifold, oriented), "
        "oriented outward. Raises InputError with one line otherwise.");
  m.def("read_surface", [](py::handle path) { return read_checked_surface(path_from(path)); },
        py::arg("path"), "A closed surface from a .stl .off .obj or .ply file, checked.");
  m.def(
      "info",
      [](py::handle surface) {
        const std::shared_ptr<Surface> s = surface_of(surface);
        return to_python(cli::surface_info(s->report, s->surface));
      },
      py::arg("surface"),
      "`volmesh info --json`'s report of a surface (a Surface or a file): counts, closedness, "
      "area, enclosed volume, self-intersections, bounding box.");
  m.def("sdf", &sdf, py::arg("surface"), py::arg("dim"), py::arg("margin") = 0.05,
        py::arg("output") = py::none(), py::arg("progress") = py::none(), py::arg("threads") = 0,
        "Signed distances (positive inside) of a surface on a dim^3 grid (dim = 2^k + 1) around "
        "it, as `volmesh sdf` samples them: a float32 array indexed [i, j, k] along x, y, z; "
        "output=PATH.rawiv also writes the grid there, as `volmesh sdf -o`.");
}

}  // namespace volmesh::python
