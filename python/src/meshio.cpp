// Mesh.to_meshio() and volmesh.from_meshio(m): meshes to and from meshio, regions and boundary
// tags as cell data ("region", "boundary_tag"), tag names as field data.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <map>

#include "convert.hpp"
#include "handles.hpp"
#include "volmesh/core/cell_soup.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/geometry/tet_decomposition.hpp"

namespace volmesh::python {

using namespace pybind11::literals;

namespace {

// How from_meshio names the mesh in messages.
constexpr const char* kSource = "meshio mesh";
// meshio's field data for a named tag: [id, dimension], as its Gmsh reader gives it.
constexpr int kFaceDimension = 2;

py::object to_meshio(const Mesh& m, std::optional<std::string> decompose, std::optional<bool> boundary) {
  if (decompose && *decompose != "tets")
    throw InputError("decompose=" + *decompose + ": the only decomposition is \"tets\"");
  const py::module_ meshio = py::module_::import("meshio");
  std::optional<PolyMesh> tets;
  if (decompose) {
    py::gil_scoped_release release;
    tets = decompose_into_tets(m.mesh, m.name);
  }
  const PolyMesh& mesh = tets ? *tets : m.mesh;
  CellBlocks cells = mesh_cell_blocks(mesh);
  py::list& blocks = cells.blocks;
  const bool polyhedra = mesh.num_cells() > 0 &&
                         blocks[0].cast<py::tuple>()[0].cast<std::string>().starts_with("polyhedron");
  py::list regions, tags;
  {
    std::size_t begin = 0;
    for (py::handle b : blocks) {
      const std::size_t n = py::len(b.cast<py::tuple>()[1]);
      std::vector<Index> region(n);
      for (std::size_t i = 0; i < n; ++i) region[i] = mesh.cell_region[cells.order[begin + i]];
      regions.append(py::array_t<Index>(static_cast<py::ssize_t>(n), region.data()));
      const std::vector<Index> none(n, kNoIndex);
      tags.append(py::array_t<Index>(static_cast<py::ssize_t>(n), none.data()));
      begin += n;
    }
  }
  // Boundary faces as triangle, quad and polygon blocks: by default only beside elements.
  if (boundary.value_or(!polyhedra)) {
    std::map<std::size_t, std::vector<Index>> by_size;  // corners -> faces, in face order
    for (Index f = 0; f < mesh.num_faces(); ++f)
      if (mesh.is_boundary(f)) by_size[mesh.face(f).size()].push_back(f);
    for (const auto& [corners, faces] : by_size) {
      std::vector<Index> data, tag;
      for (const Index f : faces) {
        const std::span<const Index> loop = mesh.face(f);
        data.insert(data.end(), loop.begin(), loop.end());
        tag.push_back(mesh.face_tag[f]);
      }
      const py::ssize_t n = static_cast<py::ssize_t>(faces.size()), c = static_cast<py::ssize_t>(corners);
      const char* type = corners == 3 ? "triangle" : corners == 4 ? "quad" : "polygon";
      blocks.append(py::make_tuple(type, py::array_t<Index>({n, c}, data.data())));
      const std::vector<Index> outside(faces.size(), 0);
      regions.append(py::array_t<Index>(n, outside.data()));
      tags.append(py::array_t<Index>(n, tag.data()));
    }
  }
  py::dict field_data;
  for (std::size_t t = 0; t < mesh.tag_names.size(); ++t)
    field_data[py::str(mesh.tag_names[t])] =
        py::array_t<Index>(2, std::array<Index, 2>{static_cast<Index>(t), kFaceDimension}.data());
  py::dict cell_data;
  cell_data["region"] = regions;
  cell_data["boundary_tag"] = tags;
  return meshio.attr("Mesh")(view(mesh.points, py::none()).attr("copy")(), blocks,
                             "cell_data"_a = cell_data, "field_data"_a = field_data);
}

// The cell data array `name` of block b, if the mesh has it.
std::optional<py::array_t<std::int64_t>> block_data(py::handle m, const char* name, std::size_t b) {
  const py::dict data = m.attr("cell_data");
  if (!data.contains(name)) return std::nullopt;
  return py::array_t<std::int64_t, py::array::forcecast>::ensure(data[name].cast<py::list>()[b]);
}

std::shared_ptr<Mesh> from_meshio(py::handle m) {
  CellSoup soup(kSource);
  soup.points = points_from(m.attr("points"), kSource, "point");
  const Index n = static_cast<Index>(soup.points.size());
  const py::dict field_data = m.attr("field_data");
  // Named tags from the field data ([id, 2]), in id order; tags without a name get "tag_ID".
  std::map<Index, std::string> names;
  for (const auto& [key, value] : field_data) {
    const auto v = py::array_t<std::int64_t, py::array::forcecast>::ensure(value);
    if (v && v.size() == 2 && v.at(1) == kFaceDimension) names[static_cast<Index>(v.at(0))] = key.cast<std::string>();
  }
  std::map<Index, Index> tag_of;  // meshio tag -> soup tag
  const auto soup_tag = [&](Index t) {
    const auto [it, added] = tag_of.emplace(t, static_cast<Index>(soup.tag_names.size()));
    if (added) soup.tag_names.push_back(names.contains(t) ? names[t] : "tag_" + std::to_string(t));
    return it->second;
  };
  const py::list cells = m.attr("cells");
  for (std::size_t b = 0; b < cells.size(); ++b) {
    const std::string type = cells[b].attr("type").cast<std::string>();
    const py::object data = cells[b].attr("data");
    const auto region = block_data(m, "region", b);
    const auto tag = block_data(m, "boundary_tag", b);
    const auto region_of = [&](std::size_t c) { return region ? static_cast<Index>(region->at(c)) : 1; };
    const std::string what = type + " cell";
    if (type.starts_with("polyhedron")) {
      std::size_t c = 0;
      for (py::handle cell : data) {
        for (py::handle face : cell) soup.add_face(indices_from(face, 0, n, kSource, what));
        soup.end_cell(region_of(c++));
      }
      continue;
    }
    const std::map<std::string, std::pair<LinearCell, std::size_t>> linear{
        {"tetra", {LinearCell::Tetrahedron, 4}},
        {"hexahedron", {LinearCell::Hexahedron, 8}},
        {"pyramid", {LinearCell::Pyramid, 5}}};
    if (const auto l = linear.find(type); l != linear.end()) {
      const auto [kind, width] = l->second;
      const std::vector<Index> corners = indices_from(data, width, n, kSource, what);
      for (std::size_t c = 0; c * width < corners.size(); ++c)
        soup.add_cell(kind, std::span(corners).subspan(c * width, width), region_of(c));
      continue;
    }
    if (type == "wedge") {  // meshio's wedge is Gmsh's prism: VTK's with each triangle reversed
      constexpr std::array<std::size_t, 6> kToVtk{0, 2, 1, 3, 5, 4};
      const std::vector<Index> corners = indices_from(data, 6, n, kSource, what);
      for (std::size_t c = 0; c * 6 < corners.size(); ++c) {
        std::array<Index, 6> v;
        for (std::size_t k = 0; k < 6; ++k) v[k] = corners[c * 6 + kToVtk[k]];
        soup.add_cell(LinearCell::Wedge, v, region_of(c));
      }
      continue;
    }
    if (type == "triangle" || type == "quad") {  // boundary faces, tagged when the data say so
      if (!tag) continue;
      const std::size_t width = type == "triangle" ? 3 : 4;
      const std::vector<Index> corners = indices_from(data, width, n, kSource, what);
      for (std::size_t f = 0; f * width < corners.size(); ++f)
        if (tag->at(f) >= 0)
          soup.add_tagged_face(std::span(corners).subspan(f * width, width),
                               soup_tag(static_cast<Index>(tag->at(f))));
      continue;
    }
    if (type == "vertex" || type == "line" || type == "polygon") continue;  // not volume cells
    throw InputError(std::string(kSource) + ": cells of type " + type +
                     " (volume cells: tetra, hexahedron, wedge, pyramid, polyhedron)");
  }
  auto out = std::make_shared<Mesh>();
  out->name = kSource;
  out->mesh = cells_to_poly(std::move(soup));
  drop_unused_tags(out->mesh);
  return out;
}

}  // namespace

void bind_meshio(py::module_& m, py::class_<Mesh, std::shared_ptr<Mesh>>& mesh) {
  mesh.def("to_meshio", &to_meshio, py::arg("decompose") = py::none(),
           py::arg("boundary") = py::none(),
           "A meshio.Mesh: tetra and hexahedron blocks, or every cell as a polyhedron (a list of "
           "face arrays) when any is another polyhedron; decompose=\"tets\" makes it tetrahedra "
           "first. boundary: the boundary faces as triangle/quad/polygon blocks (default: unless "
           "polyhedra, which meshio's VTU writer takes alone). Cell data \"region\" (0 on faces) "
           "and \"boundary_tag\" (-1 on cells); field data: each tag name's [id, 2].");
  m.def("from_meshio", &from_meshio, py::arg("mesh"),
        "A Mesh from a meshio.Mesh: its volume cells (tetra, hexahedron, wedge, pyramid, "
        "polyhedron blocks) with the cell data \"region\" (1 without it); its triangles and "
        "quads with \"boundary_tag\" tag the boundary, named by the field data.");
}

}  // namespace volmesh::python
