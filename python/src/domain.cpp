// volmesh.domain(spec): builtin:NAME, a file, a domain file's contents as a dict, or surfaces.
#include <pybind11/stl.h>

#include <sstream>

#include "handles.hpp"
#include "convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/io/domain_file.hpp"
#include "volmesh/io/open_domain.hpp"

namespace volmesh::python {

namespace {

// The name a dict domain goes by in messages ("domain: solids[0].solid: ...").
constexpr const char* kDictName = "domain";

DomainHandle surfaces_domain(const std::vector<std::shared_ptr<Surface>>& surfaces) {
  std::vector<LabelledSurface> labelled;
  std::string name;
  for (const auto& s : surfaces) {
    // Label 0: the region follows from the nesting (1 outermost, 2 inside it, ...).
    labelled.push_back({s->surface, 0, s->name});
    name += (name.empty() ? "" : "+") + s->name;
  }
  return {std::make_shared<SurfaceDomain>(std::move(labelled)), name, ""};
}

}  // namespace

DomainHandle to_domain(py::handle spec) {
  if (py::isinstance<DomainHandle>(spec)) return spec.cast<DomainHandle>();
  if (py::isinstance<Surface>(spec)) return surfaces_domain({spec.cast<std::shared_ptr<Surface>>()});
  if (py::isinstance<py::dict>(spec)) {
    const std::string text = py::module_::import("json").attr("dumps")(spec).cast<std::string>();
    std::istringstream in(text);
    return {read_domain_json(in, kDictName, std::filesystem::current_path()), kDictName, ""};
  }
  if (py::isinstance<py::list>(spec) || py::isinstance<py::tuple>(spec)) {
    std::vector<std::shared_ptr<Surface>> surfaces;
    for (py::handle item : spec) {
      if (!py::isinstance<Surface>(item))
        throw InputError("domain: a list of surfaces takes volmesh.surface(...) objects only");
      surfaces.push_back(item.cast<std::shared_ptr<Surface>>());
    }
    if (surfaces.empty()) throw InputError("domain: an empty list of surfaces");
    return surfaces_domain(surfaces);
  }
  if (py::isinstance<py::str>(spec) || py::hasattr(spec, "__fspath__")) {
    const std::string text = path_from(spec);
    return {open_domain(text), domain_display_name(text), text};
  }
  throw InputError("domain: expected builtin:NAME, a path, a dict, a volmesh.Surface or a list "
                   "of them, got " + py::repr(py::type::of(spec)).cast<std::string>());
}

void bind_domain(py::module_& m) {
  py::class_<DomainHandle>(m, "Domain", "A domain to mesh: regions, interfaces, bounds")
      .def_readonly("name", &DomainHandle::name)
      .def_property_readonly("regions", [](const DomainHandle& d) { return d.domain->regions(); })
      .def_property_readonly("bounds",
                             [](const DomainHandle& d) {
                               const Box3 b = d.domain->bounds();
                               return py::make_tuple(
                                   py::make_tuple(b.lo.x(), b.lo.y(), b.lo.z()),
                                   py::make_tuple(b.hi.x(), b.hi.y(), b.hi.z()));
                             })
      .def("region",
           [](const DomainHandle& d, py::handle points) {
             const std::vector<Vec3> p = points_from(points, d.name, "point");
             std::vector<Index> out;
             for (const Vec3& x : p) out.push_back(d.domain->region(x));
             return out;
           },
           py::arg("points"), "The region at each of an (n, 3) array of points (0 outside).")
      .def("__repr__", [](const DomainHandle& d) { return "<volmesh.Domain " + d.name + ">"; });
  m.def("domain", &to_domain, py::arg("spec"),
        "A domain: 'builtin:NAME', a file (surface, image, SDF grid, .json domain file), a dict "
        "holding a domain file's contents (paths relative to the working directory), a "
        "volmesh.Surface, or a list of nested Surfaces (each nesting level a region).");
}

}  // namespace volmesh::python
