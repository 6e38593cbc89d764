#include "volmesh/quality/measurements.hpp"

namespace volmesh {

std::vector<NamedArray> cell_quality_arrays(CellQuality cells) {
  std::vector<NamedArray> out;
  out.reserve(10);
  const auto add = [&](const char* name, std::vector<double>& values) {
    out.push_back({name, std::move(values)});
  };
  add("volume", cells.volume);
  add("scaled_jacobian", cells.scaled_jacobian);
  add("min_dihedral", cells.min_dihedral);
  add("max_dihedral", cells.max_dihedral);
  add("radius_edge_ratio", cells.radius_edge_ratio);
  add("aspect_ratio", cells.aspect_ratio);
  add("non_orthogonality", cells.non_orthogonality);
  add("boundary_non_orthogonality", cells.boundary_non_orthogonality);
  add("skewness", cells.skewness);
  add("volume_ratio", cells.volume_ratio);
  return out;
}

std::vector<NamedArray> cell_quality_arrays(const PolyMesh& mesh) {
  return cell_quality_arrays(std::move(measure_quality(mesh).cells));
}

}  // namespace volmesh
