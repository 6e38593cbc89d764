// VTU output through VTK's XML writer: tets and hexes as VTK_TETRA / VTK_HEXAHEDRON, or all
// cells as VTK_POLYHEDRON with outward faces (cell order: vtu_cell_order.hpp); boundary tags
// in field data.
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "atomic_output.hpp"
#include "canonical_order.hpp"
#include "element_export.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "vtu_boundary_tags.hpp"
#include "vtu_cell_order.hpp"
#include "vtu_errors.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

vtkNew<vtkPoints> make_points(const PolyMesh& mesh) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.num_points());
  for (Index p = 0; p < mesh.num_points(); ++p) points->SetPoint(p, mesh.points[p].data());
  return points;
}

// A polyhedron's distinct vertices (in order of first use) and its outward face stream
// [n, v_1 .. v_n, ...], as vtkUnstructuredGrid::InsertNextCell takes them.
void insert_polyhedron(vtkUnstructuredGrid& grid, const std::vector<std::vector<Index>>& faces,
                       std::vector<vtkIdType>& vertices, std::vector<vtkIdType>& stream) {
  vertices.clear();
  stream.clear();
  for (const auto& loop : faces) {
    stream.push_back(static_cast<vtkIdType>(loop.size()));
    for (Index v : loop) {
      stream.push_back(v);
      if (std::find(vertices.begin(), vertices.end(), v) == vertices.end()) vertices.push_back(v);
    }
  }
  grid.InsertNextCell(VTK_POLYHEDRON, static_cast<vtkIdType>(vertices.size()), vertices.data(),
                      static_cast<vtkIdType>(faces.size()), stream.data());
}

template <std::size_t N>
void insert_element(vtkUnstructuredGrid& grid, int type, const std::array<Index, N>& corners) {
  std::array<vtkIdType, N> ids;
  std::copy(corners.begin(), corners.end(), ids.begin());
  grid.InsertNextCell(type, static_cast<vtkIdType>(N), ids.data());
}

// Number of distinct vertices of each cell.
std::vector<Index> vertex_counts(const PolyMesh& mesh, const CellFaces& cell_faces) {
  std::vector<Index> counts(mesh.num_cells()), vertices;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    vertices.clear();
    for (Index f : cell_faces.of(c))
      vertices.insert(vertices.end(), mesh.face(f).begin(), mesh.face(f).end());
    std::sort(vertices.begin(), vertices.end());
    counts[c] =
        static_cast<Index>(std::unique(vertices.begin(), vertices.end()) - vertices.begin());
  }
  return counts;
}

// Tets and hexes as VTK_TETRA / VTK_HEXAHEDRON in mesh order unless the mesh has a
// polyhedron: then every cell is a VTK_POLYHEDRON, because meshio cannot read grids mixing
// polyhedra with other cell types, in the order of vtu_cell_order.hpp. Returns the mesh cell
// of each written cell when they are polyhedra, else nothing.
std::vector<Index> insert_cells(vtkUnstructuredGrid& grid, const PolyMesh& mesh) {
  const CellFaces cell_faces = build_cell_faces(mesh);
  std::vector<CellCorners> cells(mesh.num_cells());
  bool polyhedral = false;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    cells[c] = classify_cell(mesh, cell_faces, c);
    polyhedral = polyhedral || cells[c].shape == CellShape::Polyhedron;
  }
  grid.AllocateExact(mesh.num_cells(), static_cast<vtkIdType>(cell_faces.faces.size()) * 2);
  std::vector<Index> order;
  if (polyhedral) {
    const std::vector<Index> counts = vertex_counts(mesh, cell_faces);
    order.resize(mesh.num_cells());
    std::iota(order.begin(), order.end(), Index{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](Index a, Index b) { return counts[a] < counts[b]; });
    std::vector<vtkIdType> vertices, stream;
    for (Index c : order)
      insert_polyhedron(grid, canonical_faces(mesh, cell_faces.of(c), c), vertices, stream);
    return order;
  }
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (cells[c].shape == CellShape::Tetrahedron)
      insert_element(grid, VTK_TETRA, canonical_tet(cells[c].corners));
    else
      insert_element(grid, VTK_HEXAHEDRON, canonical_hex(cells[c].corners));
  }
  return order;
}

// Copies per-cell values, `components` each, to `out` in the written order: order[k] is the
// mesh cell written k-th (empty: mesh order). Other values (per point) with an empty order.
template <class T, class U>
void copy_in_order(const std::vector<T>& values, const std::vector<Index>& order, int components,
                   U* out) {
  if (order.empty()) {
    std::copy(values.begin(), values.end(), out);
    return;
  }
  for (Index c : order)
    out = std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(c) * components, components,
                      out);
}

vtkNew<vtkIntArray> int_array(const std::string& name, const std::vector<Index>& values,
                              const std::vector<Index>& order = {}) {
  vtkNew<vtkIntArray> array;
  array->SetName(name.c_str());
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  copy_in_order(values, order, 1, array->GetPointer(0));
  return array;
}

// Refuses a field of the wrong size, or with a name that VTK would copy unescaped into
// the XML (VTK does not escape array names).
void check_field(const std::string& source, const std::string& where, const std::string& name,
                 std::size_t values, std::size_t expected) {
  const std::string what = source + ": " + where + " field '" + name + "': ";
  if (values != expected)
    throw InputError(what + std::to_string(values) + " values, expected " +
                     std::to_string(expected));
  for (char ch : name)
    if (static_cast<unsigned char>(ch) < 0x20 ||
        std::string_view("&<>\"").find(ch) != std::string_view::npos)
      throw InputError(what + "the name cannot hold XML special or control characters");
}

void add_fields(vtkDataSetAttributes& data, const std::vector<Field>& fields, Index entities,
                const std::vector<Index>& order, const std::string& where,
                const std::string& source) {
  for (const Field& field : fields) {
    if (field.components < 1)
      throw InputError(source + ": " + where + " field '" + field.name + "': " +
                       std::to_string(field.components) + " components");
    check_field(source, where, field.name, field.values.size(),
                static_cast<std::size_t>(entities) * field.components);
    vtkNew<vtkDoubleArray> array;
    array->SetName(field.name.c_str());
    array->SetNumberOfComponents(field.components);
    array->SetNumberOfTuples(entities);
    copy_in_order(field.values, order, field.components, array->GetPointer(0));
    data.AddArray(array);
  }
}

// Cell arrays follow the written cell order; "cell_id" (vtu_cell_order.hpp) is added when
// that is not the mesh's. Point arrays keep the point order.
void add_cell_data(vtkUnstructuredGrid& grid, const PolyMesh& mesh, const MeshFields& fields,
                   const std::vector<Index>& order, const std::string& source) {
  vtkCellData& data = *grid.GetCellData();
  data.AddArray(int_array("region", mesh.cell_region, order));
  for (const IntField& field : fields.cell_ints) {
    check_field(source, "cell", field.name, field.values.size(), mesh.cell_region.size());
    if (field.name == kCellIdArray)
      throw InputError(source + ": cell field '" + field.name +
                       "': the name is reserved for the cells' order in the mesh");
    data.AddArray(int_array(field.name, field.values, order));
  }
  if (!order.empty()) data.AddArray(int_array(std::string(kCellIdArray), order));
  add_fields(data, fields.cell, mesh.num_cells(), order, "cell", source);
  add_fields(*grid.GetPointData(), fields.point, mesh.num_points(), {}, "point", source);
}

// One field-data array per boundary tag, in tag order, so that tags round-trip; faces
// rotated to their smallest vertex and sorted (vtu_boundary_tags.hpp).
void add_boundary_tags(vtkUnstructuredGrid& grid, const PolyMesh& mesh, const fs::path& path) {
  const auto by_tag = boundary_faces_by_tag(mesh, path);
  std::vector<std::vector<Index>> loops;
  std::vector<Index> flat;
  for (std::size_t t = 0; t < by_tag.size(); ++t) {
    loops.clear();
    for (Index f : by_tag[t]) {
      rotate_to_smallest(loops.emplace_back(mesh.face(f).begin(), mesh.face(f).end()));
    }
    std::sort(loops.begin(), loops.end());
    flat.clear();
    for (const auto& loop : loops) {
      flat.push_back(static_cast<Index>(loop.size()));
      flat.insert(flat.end(), loop.begin(), loop.end());
    }
    grid.GetFieldData()->AddArray(int_array(boundary_array_name(mesh.tag_names[t]), flat));
  }
}

}  // namespace

void write_vtu(const PolyMesh& mesh, const fs::path& path, const MeshFields& fields) {
  const std::string source = path.string();
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(make_points(mesh));
  const std::vector<Index> order = insert_cells(*grid, mesh);
  add_cell_data(*grid, mesh, fields, order, source);
  add_boundary_tags(*grid, mesh, path);

  AtomicOutput output(path);
  const VtkErrors errors;
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(output.temporary().c_str());
  writer->SetInputData(grid);
  // Appended binary, zlib-compressed, 64-bit headers and ids: exact and readable by ParaView
  // and meshio. Base64-encoded: meshio (7.0) re-encodes raw appended data and then looks
  // arrays up by offsets that can collide with the ones it has already rewritten, reading
  // one array's bytes as another's. zlib's fastest level: VTK's default (5) spent a fifth of
  // a whole cut-cell run compressing, for files only about 10% smaller.
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOn();
  writer->SetCompressorTypeToZLib();
  writer->SetCompressionLevel(1);
  writer->SetHeaderTypeToUInt64();
  writer->SetIdTypeToInt64();
  if (writer->Write() != 1 || !errors.first().empty())
    throw InputError(source + ": cannot write VTU file" +
                     (errors.first().empty() ? std::string() : " (" + errors.first() + ")"));
  output.commit();
}

}  // namespace volmesh
