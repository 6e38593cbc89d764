#pragma once
// The dual-contouring hex mesher as one call: a sampled signed-distance field (positive
// inside) and the closest-point map of the surface it stands for in, a valid hex mesh out.
// The stages, in order:
//   contour (dual_contouring.hpp) at octree level `level`;
//   refine (refine.hpp) the marked nodes: the boundary layers and the box asked for, then
//   (refine_thin.hpp) where the field shows the solid thin or its surface curved, the final
//   mesh at most doubled;
//   pillow (pillow.hpp): the buffer layer, so that no hex keeps two boundary faces;
//   project (project.hpp) the boundary nodes onto the surface, as far as no valid hex folds;
//   optimise (optimise.hpp) every free node at once: untangle, then raise the worst scaled
//   Jacobian, the boundary nodes sliding on the surface.
// Every hex of the result passes the ten corner tets; a mesh with one failing is refused.
#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/feature_angle.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/core/voxel_grid.hpp"
#include "volmesh/hexdc/dual_contouring.hpp"
#include "volmesh/hexdc/features.hpp"
#include "volmesh/hexdc/hex_mesh_stats.hpp"
#include "volmesh/hexdc/optimise.hpp"
#include "volmesh/hexdc/pillow.hpp"
#include "volmesh/hexdc/project.hpp"
#include "volmesh/hexdc/refine.hpp"
#include "volmesh/hexdc/refine_thin.hpp"
#include "volmesh/hexdc/surface_projector.hpp"

namespace volmesh {

// The deepest boundary refinement: each layer multiplies the hexes near the surface by 27.
inline constexpr int kMaxRefineLayers = 4;

// Which nodes are refined before the buffer layer (either may be empty).
struct HexdcRefinement {
  int boundary_layers = 0;  // mark_boundary_layers, at most kMaxRefineLayers
  std::optional<Eigen::AlignedBox3d> box;  // mark_box
};

// The refinement of thin and curved parts (refine_thin.hpp): never, always, or automatic: the
// mesh is made without it and, when that mesh is refused or its worst scaled Jacobian is below
// 0.3, again with it, the better of the two kept (the refined one only if it is valid and its
// worst scaled Jacobian higher).
enum class ThinParts : std::uint8_t { off, on, automatic };

struct ThinChoice {
  bool tried = false;  // the automatic choice made the refined mesh too
  bool kept = false;   // and kept it
  // The worst scaled Jacobian of each, -1 for a mesh with a hex failing the ten corner tets.
  double min_scaled_jacobian_without = 0.0, min_scaled_jacobian_with = 0.0;
};

struct HexdcOptions {
  int level = 0;  // the octree level contoured, in [1, k] for a (2^k + 1)^3 field
  HexdcRefinement refinement;
  ThinParts thin_parts = ThinParts::automatic;  // refine_thin_parts after the asked refinement
  std::string source;  // names the field in messages (a file name, "builtin:ball")
  // The surface's sharp features (sharp_features at feature_angle_deg); empty when the domain
  // has no triangles. Their chains on the boundary are always found and their capture measured;
  // with crease_layer the buffer layer follows them (feature_layer.hpp), its chain and corner
  // nodes are moved onto them first in the projection, and the optimiser keeps them there
  // (OptimiseOptions::feature_layer): chain nodes on their creases, corner nodes on their
  // corners.
  SurfaceFeatures features;
  double feature_angle_deg = feature_angle_degrees();
  bool crease_layer = false;
  Progress progress;   // the stages, from the calling thread
};

struct HexdcResult {
  HexMesh mesh;
  HexdcStats contouring;
  RefineStats refinement;
  ThinRefineStats thin;  // of the refined mesh, kept or not; all zero when not made
  ThinChoice thin_choice;
  PillowStats pillow;
  ProjectStats projection;
  OptimiseStats optimisation;
  FeatureLayer feature_layer;  // its chains' nodes on the final mesh
  CaptureStats capture;        // of options.features by the final mesh
  CaptureStats capture_projected;  // the same after the projection, before the optimiser
  // The paper's Table 1 columns: the uniform mesh, the refined one (set when the refinement
  // changed the mesh) and the final one.
  HexMeshStats uniform, improved;
  std::optional<HexMeshStats> refined;
  double contour_seconds = 0.0, refine_seconds = 0.0;
  double pillow_seconds = 0.0, project_seconds = 0.0;  // optimisation.seconds has the rest
};

// Throws InputError (naming options.source) when no sample is >= 0, for a level outside
// [1, k] or boundary layers outside [0, kMaxRefineLayers], and when a hex of the final mesh
// fails the ten corner tets.
HexdcResult hexdc_mesh(const VoxelGrid& field, const SurfaceProjector& surface,
                       const HexdcOptions& options);

}  // namespace volmesh
