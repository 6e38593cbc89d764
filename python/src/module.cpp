// The Python module `volmesh`: the library on numpy arrays (the README's "From Python").
// Errors the library throws as InputError raise volmesh.InputError,
// a ValueError, with the command line's one line.
#include <pybind11/pybind11.h>

#include "handles.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/parallel.hpp"
#include "volmesh/runs/allocator.hpp"

namespace py = pybind11;

namespace {

// PETSc starts at the first PETSc solve and stops with the Session, here at the
// interpreter's exit.
volmesh::fem::Session* session = nullptr;

void start_session() {
  static char name[] = "python";
  static char* argv[] = {name, nullptr};
  int argc = 1;
  session = new volmesh::fem::Session(argc, argv);
  py::module_::import("atexit").attr("register")(py::cpp_function([] {
    delete session;
    session = nullptr;
  }));
}

}  // namespace

PYBIND11_MODULE(volmesh, m) {
  using namespace volmesh::python;
  m.doc() = "volmesh: volume meshing, checking, partitioning, Poisson and elasticity solves";
  m.attr("__version__") = VOLMESH_VERSION;
  volmesh::cli::keep_freed_memory();
  start_session();
  py::register_exception<volmesh::InputError>(m, "InputError", PyExc_ValueError);
  bind_surface(m);
  bind_domain(m);
  bind_mesh(m);
  bind_solve(m);
}
