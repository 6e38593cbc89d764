#pragma once
// Tet mesh improvement after Klingner and Shewchuk's Stellar: the worst tets, by the smallest
// sine of their dihedral angles, are improved by optimisation-based smoothing, topological
// changes (edge removal, multi-face removal, edge contraction) and vertex insertion. Every
// change is kept only if it raises the smallest quality of the tets it touches, and every new
// tet is positive by the exact orientation test on the doubles it is written with; so the
// worst tet never gets worse and the mesh stays valid.
//
// The boundary triangles and the triangles between regions stay faces of the mesh, their
// corners fixed; only where `slides` says so does a corner slide, within a flat triangle or
// along a straight edge of the surface it lies in, the surface staying the same point set.
#include <limits>
#include <string>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/improve/slides.hpp"

namespace volmesh::improve {

struct ImproveOptions {
  // Wall time after which no new pass starts.
  double max_seconds = std::numeric_limits<double>::infinity();
  // Per point of the mesh, where it may slide (empty: every boundary and interface point
  // stays put). slides_on_surface() (slides.hpp) finds them.
  std::vector<Slide> slides;
  Progress progress;
};

// Whole-mesh figures, before and after.
struct QualitySummary {
  Index tets = 0, points = 0;
  double min_dihedral_deg = 0.0, max_dihedral_deg = 0.0;
  double max_radius_edge = 0.0;
  Index below_10_degrees = 0;  // tets with a dihedral angle under 10°
  double min_quality = 0.0;    // the smallest sine of a dihedral angle
};

struct OperationCounts {
  long long smoothed = 0;       // nodes moved (sliding ones included)
  long long slid = 0;           // of which boundary points slid within their triangle or edge
  long long flips_3_2 = 0;      // edge removal with a ring of 3
  long long flips_4_4 = 0;      // ... of 4
  long long edge_removals = 0;  // ... of 5 to 7
  long long flips_2_3 = 0;      // multi-face removal of one face
  long long face_removals = 0;  // ... of two faces or more
  long long contractions = 0;
  long long insertions = 0;
};

struct ImproveStats {
  QualitySummary before, after;
  OperationCounts operations;
  int passes = 0;
  bool timed_out = false;
  double seconds = 0.0;
};

// Improves `mesh` in place: points may be added (after the others) and removed (the others
// keep their order); boundary and interface points stay where they are unless they slide;
// tets keep their regions; boundary faces and their tags stay (renumbered with the points).
// Throws InputError when a tet of the input is not positive by the exact test. Serial in its
// changes, so the result is the same for any thread count.
ImproveStats improve_tet_mesh(TetMesh& mesh, const ImproveOptions& options = {});

// Throws InputError "SOURCE: tet N is flat or inverted ..." for the first tet that is not
// positive by the exact orientation test.
void require_positive_tets(const TetMesh& mesh, const std::string& source);

// The whole-mesh figures of a tet mesh (parallel, deterministic).
QualitySummary summarize_quality(const TetMesh& mesh);

}  // namespace volmesh::improve
