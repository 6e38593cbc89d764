#pragma once
// The cut-cell octree mesher: MMCMS, the multiple-material cubical marching squares of the
// octree paper (Chernyshenko; docs/methods.md, "cutcell"). An octree refined toward the boundaries and
// interfaces, each leaf whose vertices lie in more than one region cut into polyhedral
// pieces along a triangulated approximation of the interfaces, the outside (region 0)
// dropped. The mesh approximates boundaries and interfaces to second order while staying
// mostly cubes; its trace on every boundary and interface is a triangulation.
#include <functional>
#include <string>

#include "volmesh/core/feature_angle.hpp"
#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/octree/octree.hpp"
#include "volmesh/quality/face_metrics.hpp"

namespace volmesh {

// Where the edge interface points lie: the exact crossings with their normals (MMCMS), or
// the edge midpoints with the face and cell interface points at face and cell centres and
// no feature points (M3C as Wu & Sullivan published it: first order, for comparison).
enum class InterfacePoints { exact, midpoint };

struct CutcellOptions {
  OctreeOptions octree;  // octree.level: the depth at boundaries and interfaces
  InterfacePoints interface_points = InterfacePoints::exact;
  // Leaves with an edge crossed more than once are split down to octree.level + this.
  int crossing_levels = 2;
  // The paper's k: a face interface point that leaves its face splits the leaves around
  // it, down to octree.level + this; past it the centroid of the edge points is used.
  int face_point_levels = 1;
  // The limits every stage holds the faces to (OpenFOAM's skewness and non-orthogonality):
  // a cut face beyond them makes its cell try its other triangulations, then merge the
  // face with its neighbours; a cell with such a face is split at a reflex edge or merged.
  CheckMeshLimits limits;
  // Tiny cut cells: a grid vertex whose nearest crossing along an edge lies closer than
  // this fraction of the edge is moved off the interface (exact mode only).
  double vertex_clearance = 0.1;
  // An edge still crossed twice at the deepest level, from its ends' regions into a third
  // between, keeps both crossings (a vertex of the third region splits it) when they lie at
  // least this fraction of the edge apart (exact mode only); nearer, one crossing stands for
  // both, off by less than the gap. Where a thin wedge of the third region pinches out, a
  // larger gap moves the junction lines farther off, a smaller one keeps thinner wedge tips:
  // tiny cells that no merge can take.
  double split_gap = 0.05;
  // Cells that checkMesh would reject (a face beyond `limits`, an inverted face pyramid) or
  // smaller than merge_volume_ratio * h^3 are merged with one or two neighbours of their
  // region, and a rejected face may be joined with a face beside it between the same
  // cells, in at most merge_rounds passes (0: never). No point moves.
  int merge_rounds = 16;
  double merge_volume_ratio = 1e-3;
  double feature_theta = kFeatureCosine;  // Kobbelt's sharp-feature thresholds
  double feature_phi = 0.7;
  // Called with a stage name and the fraction of the run done, from the calling thread.
  std::function<void(const std::string& stage, double fraction)> progress;
};

// The paper's table columns and what the robustness rules did.
struct CutcellStats {
  int level = 0;             // octree.level
  int max_leaf_level = 0;    // deepest leaf after the extra refinement
  Index leaves = 0, cells = 0, cut_cells = 0, faces = 0, vertices = 0;
  Index refinement_passes = 0;   // passes of the paper's extra rules that split leaves
  Index moved_vertices = 0;      // grid vertices moved off an interface
  Index unresolved_vertices = 0; // vertices left within the clearance (no valid move)
  Index relabelled_vertices = 0; // midpoints of leaf edges still crossed twice at the deepest
                                 // level, given their edge's region (a thinner layer is lost)
  Index split_edges = 0;         // edges crossed twice kept so, split between the crossings
  Index face_point_fallbacks = 0, cell_point_fallbacks = 0;
  Index feature_points = 0;      // fans around EMC feature points
  Index feature_splits = 0;      // components split along a sharp edge
  Index surface_fans = 0;        // fans around the surface point of a large component
  Index cell_points = 0;         // cell interface points
  Index centroid_fans = 0, across_face_triangulations = 0;
  double min_cell_volume_ratio = 0.0;  // smallest cell volume / h^3, h its leaf's edge
  double max_skewness = 0.0;           // of all faces of the mesh (OpenFOAM's measure)
  double max_non_orthogonality = 0.0;  // degrees, internal faces (checkMesh's measure)
  Index merged_faces = 0;  // polygons made of interface triangles too skewed on their own
  Index split_cells = 0;   // cells split in two at a reflex edge of the surface, before merging
  Index merged_cells = 0;  // merges of a cell into neighbours (CutcellOptions::merge_rounds)
  Index joined_faces = 0;  // faces joined with a neighbouring face between the same cells
  Index bad_faces = 0;     // faces still beyond checkMesh's limits after the merging
  double octree_seconds = 0.0, cut_seconds = 0.0, total_seconds = 0.0;
};

// Throws InputError for octree limits (a level beyond the maximum, a domain smaller than one
// cell at the level, an index overflow) or when no cell lies inside the domain.
PolyMesh cutcell_mesh(const Domain& domain, const CutcellOptions& options,
                      CutcellStats* stats = nullptr);

}  // namespace volmesh
