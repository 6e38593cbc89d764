#pragma once
// The validity checker behind `volmesh check`: the invariants every PolyMesh must hold
// (docs/verification.md, "Validity").
#include <map>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

struct ValidityOptions {
  double closed_tolerance = 1e-8;  // |sum of oriented face areas| / sum of |face areas|
  // |face area| / (longest edge)^2 at or below this: zero area, the vertices in a line up to
  // rounding (no normal to orient the face by).
  double zero_area_tolerance = 1e-12;
  int max_messages = 20;           // detailed problems kept in the report
};

struct ValidityReport {
  Index cells = 0, faces = 0, points = 0, boundary_faces = 0;
  Index bad_indices = 0;            // face vertex / owner / neighbour out of range
  Index degenerate_faces = 0;       // fewer than 3 distinct vertices, or zero area
  Index open_cells = 0;             // oriented face areas do not sum to zero
  Index unmatched_cell_edges = 0;   // cells whose faces do not close up edge by edge
  Index non_positive_cells = 0;     // volume <= 0
  Index duplicate_faces = 0;        // the same vertex set used by more than one face
  Index bad_face_order = 0;         // internal face with owner >= neighbour is fine; this
                                    // counts owner == neighbour
  Index open_region_boundary_edges = 0;  // directed edges of a region's boundary unmatched
  Index unused_points = 0;          // reported, not an error
  double total_volume = 0.0;
  double min_cell_volume = 0.0, max_cell_volume = 0.0;
  double max_closedness = 0.0;      // worst relative closedness over all cells
  std::map<Index, double> region_volume;
  std::vector<std::string> problems;  // first few, human readable

  bool valid() const {
    return bad_indices == 0 && degenerate_faces == 0 && open_cells == 0 &&
           unmatched_cell_edges == 0 && non_positive_cells == 0 && duplicate_faces == 0 &&
           bad_face_order == 0 && open_region_boundary_edges == 0;
  }
};

ValidityReport check_validity(const PolyMesh& mesh, const ValidityOptions& options = {});

}  // namespace volmesh
