// Scalar grids from VTK XML image data (.vti): the only translation unit that sees VTK.
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>

#include <string>

#include "volmesh/io/voxel_grid_io.hpp"
#include "voxel_samples.hpp"

namespace volmesh {

namespace fs = std::filesystem;
using namespace voxel;

namespace {

// Keeps VTK's first error report (its last line, without the "Class (0x...): " prefix)
// instead of letting VTK print it.
class ErrorCapture : public vtkCommand {
 public:
  static ErrorCapture* New() { return new ErrorCapture; }
  void Execute(vtkObject*, unsigned long, void* call_data) override {
    if (!message.empty() || call_data == nullptr) return;
    message = static_cast<const char*>(call_data);
    if (auto prefix = message.find("): "); prefix != std::string::npos)
      message.erase(0, prefix + 3);
    if (auto eol = message.find_first_of("\r\n"); eol != std::string::npos) message.erase(eol);
  }
  std::string message;
};

}  // namespace

VoxelGrid read_vti(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) fail(path, "cannot open: no such file");
  vtkNew<vtkXMLImageDataReader> reader;
  vtkNew<ErrorCapture> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent,
                                      errors);  // "returned failure" reports
  reader->SetReaderErrorObserver(errors);
  reader->SetParserErrorObserver(errors);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (!errors->message.empty() || image == nullptr)
    fail(path, "not a readable VTK image data file (" +
                   (errors->message.empty() ? std::string("no image") : errors->message) + ")");

  vtkPointData* data = image->GetPointData();
  vtkDataArray* array = data->GetScalars();
  if (array == nullptr && data->GetNumberOfArrays() == 1) array = data->GetArray(0);
  if (array == nullptr)
    fail(path, "point data: no scalars (" + std::to_string(data->GetNumberOfArrays()) +
                   " arrays, none marked Scalars)");
  if (array->GetNumberOfComponents() != 1)
    fail(path, "point data '" + std::string(array->GetName() ? array->GetName() : "") +
                   "': " + std::to_string(array->GetNumberOfComponents()) +
                   " components (a scalar field has 1)");
  if (!image->GetDirectionMatrix()->IsIdentity())
    fail(path, "Direction: only axis-aligned grids are supported");

  int extent[6];
  image->GetExtent(extent);
  const Vec3 spacing(image->GetSpacing()), origin(image->GetOrigin());
  check_spacing(path, spacing, axis_fields("Spacing"));
  const std::array<std::int64_t, 3> dims{std::int64_t{extent[1]} - extent[0] + 1,
                                         std::int64_t{extent[3]} - extent[2] + 1,
                                         std::int64_t{extent[5]} - extent[4] + 1};
  const std::int64_t count = checked_count(path, dims, "WholeExtent");
  if (array->GetNumberOfTuples() != count)
    fail(path, "point data: " + std::to_string(array->GetNumberOfTuples()) + " values for " +
                   std::to_string(count) + " points");
  VoxelGrid grid;
  grid.dims = {static_cast<Index>(dims[0]), static_cast<Index>(dims[1]),
               static_cast<Index>(dims[2])};
  grid.spacing = spacing;
  // Extents may start off 0: sample (0, 0, 0) is the extent's first point.
  grid.origin = origin + spacing.cwiseProduct(Vec3(extent[0], extent[2], extent[4]));
  check_origin(path, grid.origin, axis_fields("Origin"));
  check_grid_dims(grid.dims, path, "WholeExtent");
  grid.values.resize(static_cast<std::size_t>(count));
  for (std::int64_t n = 0; n < count; ++n)
    grid.values[n] = checked_float(array->GetTuple1(n), grid.dims, n, path);
  return grid;
}

}  // namespace volmesh
