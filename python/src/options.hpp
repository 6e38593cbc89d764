#pragma once
// Mesher options from Python keywords: names as on the command line with `_` for `-`
// (cells_between_levels=2), values as the registry declares them; the registry refuses what
// a method does not take.
#include <pybind11/pybind11.h>

#include "volmesh/meshers/registry.hpp"

namespace volmesh::python {

namespace py = pybind11;

meshers::MethodOptions method_options(const meshers::MesherInfo& info, const py::kwargs& given);

}  // namespace volmesh::python
