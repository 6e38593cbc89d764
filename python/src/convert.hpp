#pragma once
// Between the library's data and Python's: JSON as dicts, vectors as read-only numpy views,
// and numpy input checked with the library's one-line errors.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::python {

namespace py = pybind11;

// The same values as the CLI's --json prints (NaN and infinities as None).
py::object to_python(const nlohmann::json& j);

// A read-only view of `size` rows of `columns` values at `data` (columns 0: one dimension),
// kept alive by `owner`.
template <class T>
py::array view(const T* data, std::size_t size, std::size_t columns, py::handle owner) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(size)};
  std::vector<py::ssize_t> strides{static_cast<py::ssize_t>(sizeof(T) * std::max<std::size_t>(columns, 1))};
  if (columns > 0) {
    shape.push_back(static_cast<py::ssize_t>(columns));
    strides.push_back(sizeof(T));
  }
  py::array a(py::dtype::of<T>(), shape, strides, data, owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}
template <class T>
py::array view(const std::vector<T>& v, py::handle owner) {
  return view(v.data(), v.size(), 0, owner);
}
py::array view(const std::vector<Vec3>& points, py::handle owner);

// An (n, 3) array of finite numbers of any numeric dtype; InputError "NAME: WHAT: ..." for
// another shape or a value that is not finite.
std::vector<Vec3> points_from(py::handle array, const std::string& name, const std::string& what);
// An (n, columns) array of integers (any integer dtype, or floats holding integers) in
// [0, limit): InputError "NAME: WHAT ROW: vertex index V out of range (LIMIT vertices)" for a
// value outside, as the surface readers word it, and "NAME: WHATs: ..." for a wrong shape.
std::vector<Index> indices_from(py::handle array, std::size_t columns, Index limit,
                                const std::string& name, const std::string& what);

// A str or os.PathLike as a path string.
std::string path_from(py::handle path);

}  // namespace volmesh::python
