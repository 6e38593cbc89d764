#pragma once
// What the Python objects hold: the library's own data, never a copy made for Python. Numpy
// arrays over it are views whose base is the Python object, which so stays alive as long as
// any view does.
#include <pybind11/pybind11.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/tri_surface.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/meshers/registry.hpp"

namespace volmesh::python {

namespace py = pybind11;

// A closed surface, checked (and oriented outward) as a surface file is.
struct Surface {
  TriSurface surface;
  std::string name;
  SurfaceReport report;
};

struct DomainHandle {
  std::shared_ptr<const Domain> domain;
  std::string name;  // for messages and figures: "builtin:ball", a file name, "surface"
  std::string spec;  // what opened it (builtin:NAME, a path), empty when built from data
};

// What a mesher reported, kept until the mesh's figures are first asked for: they hold the
// validity check's figures, and the check waits until then (or until the mesh is written),
// so that meshing from Python costs what meshing costs.
struct MesherReport {
  std::string method;
  meshers::MeshRequest request;  // without its progress
  nlohmann::json summary;
  double seconds = 0.0, h = 0.0;
};

struct Mesh {
  PolyMesh mesh;
  std::string name;  // the file it was read from, or "METHOD mesh of DOMAIN"
  nlohmann::json figures = nlohmann::json::object();
  std::optional<MesherReport> mesher;  // until figures holds its figures
  std::string default_space;  // the mesher's default FE space, if it came from one
};

// The Python objects' types, registered by module.cpp.
void bind_surface(py::module_& m);
void bind_domain(py::module_& m);
void bind_mesh(py::module_& m);
void bind_meshio(py::module_& m, py::class_<Mesh, std::shared_ptr<Mesh>>& mesh);
void bind_solve(py::module_& m);

// Mesh.cells: meshio's (type, data) blocks, and the cells in the order the blocks hold them
// (mesh.cpp).
struct CellBlocks {
  py::list blocks;
  std::vector<Index> order;
};
CellBlocks mesh_cell_blocks(const PolyMesh& mesh);

// A domain from whatever `volmesh.domain` takes: a DomainHandle, a str (builtin:NAME or a
// path), a dict (a domain file's contents), a Surface or a list of nested Surfaces.
DomainHandle to_domain(py::handle spec);

}  // namespace volmesh::python
