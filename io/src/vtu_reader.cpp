// VTU input through VTK's XML reader: tetrahedra, hexahedra, wedges, pyramids and polyhedra
// become PolyMesh cells, in the order "cell_id" gives (vtu_cell_order.hpp); "region" cell
// data and the writer's boundary tags are read back, and for a piece of a partitioned set
// the global ids of its points and cells.
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkPointData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "volmesh/core/cell_soup.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "cell_list_soup.hpp"
#include "volmesh/io/partitioned_io.hpp"
#include "vtu_boundary_tags.hpp"
#include "vtu_cell_order.hpp"
#include "vtu_errors.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

class VtuCells {
 public:
  VtuCells(vtkUnstructuredGrid& grid, std::string source)
      : grid_(grid), source_(std::move(source)) {}

  // The file's cells; with_ids: also each point's and cell's global id (a piece of a set).
  CellList read(bool with_ids) {
    read_points();
    read_cells();
    read_boundary_tags();
    if (with_ids) read_global_ids();
    return std::move(list_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(source_ + ": " + what); }

  Index checked_count(vtkIdType n, const char* what) const {
    if (n > kMaxIndex) fail(std::to_string(n) + " " + what + ": more than 32-bit indices allow");
    return static_cast<Index>(n);
  }

  Index point_id(vtkIdType id, const std::string& entity) const {
    if (id < 0 || id >= static_cast<vtkIdType>(list_.points.size()))
      fail(entity + ": point index " + std::to_string(id) + " out of range (" +
           std::to_string(list_.points.size()) + " points)");
    return static_cast<Index>(id);
  }

  void read_points() {
    const Index n = checked_count(grid_.GetNumberOfPoints(), "points");
    list_.points.resize(n);
    for (Index p = 0; p < n; ++p) grid_.GetPoint(p, list_.points[p].data());
  }

  std::vector<Index> regions(Index num_cells) const {
    std::vector<Index> region(num_cells, 1);
    vtkDataArray* array = grid_.GetCellData()->GetArray("region");
    if (array == nullptr) return region;
    if (array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() != num_cells)
      fail("cell data 'region': expected one value per cell");
    for (Index c = 0; c < num_cells; ++c) {
      const double r = array->GetTuple1(c);
      if (!(r >= 1.0 && r <= static_cast<double>(kMaxIndex)) || r != std::floor(r))
        fail("cell " + std::to_string(c) + ": region " + std::to_string(r) +
             " (regions are integers >= 1)");
      region[c] = static_cast<Index>(r);
    }
    return region;
  }

  static std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
  }

  // The file's cells in mesh order: by "cell_id" when the file has it (vtu_cell_order.hpp),
  // else as they come.
  std::vector<Index> mesh_order(Index num_cells) const {
    std::vector<Index> order(num_cells);
    vtkDataArray* array = grid_.GetCellData()->GetArray(std::string(kCellIdArray).c_str());
    if (array == nullptr) {
      std::iota(order.begin(), order.end(), Index{0});
      return order;
    }
    const std::string entity = "cell data '" + std::string(kCellIdArray) + "'";
    if (array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() != num_cells)
      fail(entity + ": expected one value per cell");
    std::fill(order.begin(), order.end(), kNoIndex);
    for (Index c = 0; c < num_cells; ++c) {
      const double id = array->GetTuple1(c);
      if (!(id >= 0.0 && id < num_cells) || id != std::floor(id))
        fail(entity + ": cell " + std::to_string(c) + " has id " + number(id) +
             " (ids are 0 .. " + std::to_string(num_cells - 1) + ")");
      Index& slot = order[static_cast<Index>(id)];
      if (slot != kNoIndex)
        fail(entity + ": cells " + std::to_string(slot) + " and " + std::to_string(c) +
             " have the same id " + std::to_string(static_cast<Index>(id)));
      slot = c;
    }
    return order;
  }

  void read_cells() {
    const Index num_cells = checked_count(grid_.GetNumberOfCells(), "cells");
    const std::vector<Index> region = regions(num_cells);
    file_cells_ = mesh_order(num_cells);
    for (Index c : file_cells_) {
      list_.cell_region.push_back(region[c]);
      const int type = grid_.GetCellType(c);
      if (type == VTK_POLYHEDRON) {
        list_.cell_kind.push_back(CellList::kPolyhedron);
        read_polyhedron(c);
      } else {
        vtkIdType npts = 0;
        const vtkIdType* pts = nullptr;
        grid_.GetCellPoints(c, npts, pts);
        const std::string entity = "cell " + std::to_string(c);
        list_.cell_kind.push_back(static_cast<Index>(linear_cell(type, npts, entity)));
        for (vtkIdType i = 0; i < npts; ++i) list_.items.push_back(point_id(pts[i], entity));
      }
      list_.cell_begin.push_back(static_cast<Index>(list_.items.size()));
    }
  }

  LinearCell linear_cell(int type, vtkIdType npts, const std::string& entity) const {
    auto expect = [&](LinearCell kind, vtkIdType corners) {
      if (npts != corners)
        fail(entity + ": VTK cell type " + std::to_string(type) + " with " + std::to_string(npts) +
             " points instead of " + std::to_string(corners));
      return kind;
    };
    switch (type) {
      case VTK_TETRA: return expect(LinearCell::Tetrahedron, 4);
      case VTK_HEXAHEDRON: return expect(LinearCell::Hexahedron, 8);
      case VTK_WEDGE: return expect(LinearCell::Wedge, 6);
      case VTK_PYRAMID: return expect(LinearCell::Pyramid, 5);
      default:
        fail(entity + ": VTK cell type " + std::to_string(type) +
             " is not read (tetra, hexahedron, wedge, pyramid and polyhedron are)");
    }
  }

  // The face stream [nfaces, n, v_1 .. v_n, ...] at the cell's face location, bounds-checked
  // because VTK does not validate it.
  void read_polyhedron(Index c) {
    const std::string entity = "cell " + std::to_string(c);
    vtkIdTypeArray* stream = grid_.GetFaces();
    vtkIdTypeArray* locations = grid_.GetFaceLocations();
    if (stream == nullptr || locations == nullptr || locations->GetNumberOfValues() <= c)
      fail(entity + ": polyhedron without faces");
    const vtkIdType size = stream->GetNumberOfValues();
    vtkIdType at = locations->GetValue(c);
    auto next = [&]() {
      if (at < 0 || at >= size) fail(entity + ": polyhedron face stream ends early");
      return stream->GetValue(at++);
    };
    const vtkIdType num_faces = next();
    if (num_faces < 4 || num_faces > size)
      fail(entity + ": polyhedron with " + std::to_string(num_faces) + " faces");
    for (vtkIdType f = 0; f < num_faces; ++f) {
      const vtkIdType n = next();
      if (n < 0 || n > size)
        fail(entity + ": polyhedron face with " + std::to_string(n) + " vertices");
      list_.items.push_back(static_cast<Index>(n));
      for (vtkIdType i = 0; i < n; ++i) list_.items.push_back(point_id(next(), entity));
    }
  }

  void read_boundary_tags() {
    vtkFieldData* data = grid_.GetFieldData();
    for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
      vtkDataArray* array = data->GetArray(a);
      const char* name = data->GetArrayName(a);
      if (array == nullptr || name == nullptr ||
          !std::string_view(name).starts_with(kBoundaryArrayPrefix))
        continue;
      const std::string entity = std::string("field data '") + name + "'";
      const Index tag = static_cast<Index>(list_.tag_names.size());
      list_.tag_names.push_back(boundary_tag_name(name + kBoundaryArrayPrefix.size()));
      if (array->GetNumberOfComponents() != 1) fail(entity + ": expected one component");
      const vtkIdType size = array->GetNumberOfTuples();
      auto value = [&](vtkIdType at) {
        const double v = array->GetTuple1(at);
        if (!(std::abs(v) < 9e15) || v != std::floor(v)) fail(entity + ": non-integer entry");
        return static_cast<vtkIdType>(v);
      };
      for (vtkIdType at = 0; at < size;) {
        const vtkIdType n = value(at++);
        if (n < 0 || n > size - at) fail(entity + ": face list ends early");
        for (vtkIdType i = 0; i < n; ++i) list_.tagged_vertices.push_back(point_id(value(at++), entity));
        list_.tagged_tag.push_back(tag);
        list_.tagged_begin.push_back(static_cast<Index>(list_.tagged_vertices.size()));
      }
    }
  }

  // One non-negative integer per entity from the array `name` of `data`, in file order.
  std::vector<Index> id_array(vtkDataSetAttributes& data, const char* name, const char* entities,
                              Index count) const {
    vtkDataArray* array = data.GetArray(name);
    const std::string entity = std::string(entities) + " data '" + name + "'";
    if (array == nullptr)
      fail("no " + entity + " (not a piece of a partitioned mesh: write one with volmesh "
           "partition MESH --parts K -o parts.pvtu)");
    if (array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() != count)
      fail(entity + ": expected one value per " + entities);
    std::vector<Index> ids(count);
    for (Index i = 0; i < count; ++i) {
      const double id = array->GetTuple1(i);
      if (!(id >= 0.0 && id <= static_cast<double>(kMaxIndex)) || id != std::floor(id))
        fail(entity + ": " + entities + " " + std::to_string(i) + " has id " + number(id));
      ids[i] = static_cast<Index>(id);
    }
    return ids;
  }

  void read_global_ids() {
    list_.point_ids = id_array(*grid_.GetPointData(), "GlobalPointIds", "point",
                               static_cast<Index>(list_.points.size()));
    const std::vector<Index> by_file = id_array(*grid_.GetCellData(), "GlobalCellIds", "cell",
                                                static_cast<Index>(file_cells_.size()));
    for (Index c : file_cells_) list_.cell_ids.push_back(by_file[c]);
  }

  vtkUnstructuredGrid& grid_;
  std::string source_;
  CellList list_;
  std::vector<Index> file_cells_;  // the file's cells in mesh order
};

vtkUnstructuredGrid* read_grid(vtkXMLUnstructuredGridReader& reader, const fs::path& path,
                               const VtkErrors& errors) {
  const std::string source = path.string();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError(source + ": cannot open (no such file, or not a regular file)");
  reader.SetFileName(path.c_str());
  try {
    reader.Update();
  } catch (const std::exception& e) {
    // A corrupt compression header makes VTK allocate from it (std::bad_alloc or
    // std::length_error escape from vtkXMLDataParser).
    throw InputError(source + ": not a readable VTU file (corrupt data: " + e.what() + ")");
  }
  vtkUnstructuredGrid* grid = reader.GetOutput();
  if (!errors.first().empty() || grid == nullptr)
    throw InputError(source + ": not a readable VTU file (" +
                     (errors.first().empty() ? std::string("no grid") : errors.first()) + ")");
  return grid;
}

CellList read_cells(const fs::path& path, bool with_ids) {
  const VtkErrors errors;
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  return VtuCells(*read_grid(*reader, path, errors), path.string()).read(with_ids);
}

}  // namespace

PolyMesh read_vtu(const fs::path& path) {
  const CellList list = read_cells(path, false);
  CellSoup soup(path.string());
  soup.points = list.points;
  soup.tag_names = list.tag_names;
  const auto same = [](Index i) { return i; };
  for (Index c = 0; c < static_cast<Index>(list.cell_kind.size()); ++c)
    detail::add_cell(list, c, same, soup);
  for (std::size_t t = 0; t < list.tagged_tag.size(); ++t)
    detail::add_tagged_face(list, t, same, same, soup);
  return cells_to_poly(std::move(soup));
}

CellList read_vtu_piece(const fs::path& piece) { return read_cells(piece, true); }

}  // namespace volmesh
