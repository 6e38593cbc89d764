#include "convert.hpp"

#include <cmath>
#include <sstream>

#include "volmesh/core/errors.hpp"
#include "volmesh/core/tri_surface.hpp"

namespace volmesh::python {

namespace {

std::string shape_text(const py::array& a) {
  std::ostringstream out;
  out << "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) out << (d ? ", " : "") << a.shape(d);
  out << (a.ndim() == 1 ? ",)" : ")");
  return out.str();
}

// `object` as a numpy array of numbers with `columns` columns (0: one dimension).
py::array numeric(py::handle object, std::size_t columns, const std::string& name,
                  const std::string& what) {
  const py::array a = py::array::ensure(object);
  const std::string expected = columns > 0 ? "(n, " + std::to_string(columns) + ")" : "(n,)";
  if (!a) throw InputError(name + ": " + what + ": expected an " + expected + " array of numbers");
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f' && kind != 'b')
    throw InputError(name + ": " + what + ": expected numbers, got an array of dtype " +
                     py::str(a.dtype()).cast<std::string>());
  const bool shaped = columns > 0 ? a.ndim() == 2 && a.shape(1) == static_cast<py::ssize_t>(columns)
                                  : a.ndim() == 1;
  if (!shaped && !(a.size() == 0 && columns > 0 && a.ndim() == 1))
    throw InputError(name + ": " + what + ": expected an " + expected + " array, got shape " +
                     shape_text(a));
  return a;
}

}  // namespace

py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: {
      const double x = j.get<double>();
      return std::isfinite(x) ? py::object(py::float_(x)) : py::object(py::none());
    }
    case nlohmann::json::value_t::string:
      return py::str(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list out;
      for (const nlohmann::json& item : j) out.append(to_python(item));
      return std::move(out);
    }
    case nlohmann::json::value_t::object: {
      py::dict out;
      for (const auto& [key, value] : j.items()) out[py::str(key)] = to_python(value);
      return std::move(out);
    }
    default:
      return py::none();
  }
}

py::array view(const std::vector<Vec3>& points, py::handle owner) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "points are packed triples");
  return view(points.empty() ? nullptr : points.front().data(), points.size(), 3, owner);
}

std::vector<Vec3> points_from(py::handle object, const std::string& name, const std::string& what) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(
      numeric(object, 3, name, what));
  const std::size_t n = a.size() / 3;
  std::vector<Vec3> points(n);
  const double* p = a.data();
  for (std::size_t i = 0; i < n; ++i) {
    points[i] = Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    if (!points[i].allFinite())
      throw InputError(name + ": " + what + " " + std::to_string(i) + ": coordinates not finite");
  }
  return points;
}

std::vector<Index> indices_from(py::handle object, std::size_t columns, Index limit,
                                const std::string& name, const std::string& what) {
  const py::array given = numeric(object, columns, name, what + "s");
  const bool floats = given.dtype().kind() == 'f';
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given);
  const std::size_t width = std::max<std::size_t>(columns, 1);
  std::vector<Index> out(a.size());
  const double* v = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::string row = name + ": " + what + " " + std::to_string(i / width) + ": ";
    if (floats && v[i] != std::floor(v[i]))
      throw InputError(row + "vertex index " + py::repr(py::float_(v[i])).cast<std::string>() +
                       " is not an integer");
    if (!(v[i] >= 0.0 && v[i] < static_cast<double>(limit)))
      throw InputError(row + vertex_index_error(static_cast<std::int64_t>(v[i]), limit));
    out[i] = static_cast<Index>(v[i]);
  }
  return out;
}

std::string path_from(py::handle path) {
  return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

}  // namespace volmesh::python
