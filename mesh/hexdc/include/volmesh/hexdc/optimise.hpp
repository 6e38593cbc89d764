#pragma once
// Untangling and optimisation of a hex mesh over all its free nodes at once.
//
// Each hex counts its ten corner tets (hex_quality.hpp's kHexCornerTets: the eight corner
// Jacobians and the ten-tet test's two inner tets).
//  1. Untangling, when a tet is not positive: L-BFGS on the barrier energy of Garanzha et al.
//     ("Foldover-free maps in 50 lines of code", 2021) over the tets, each against its shape in
//     a cube of its hex's mean edge, with the regulariser ε lowered as the least determinant
//     rises (their rule, and never above 0.2 of it), until a round leaves every tet positive.
//     Each round moves the nodes within three hex rings of the hexes folded at its start (the
//     rest of the mesh stays), each node's step past the first shortened on its own to 0.3 of
//     its shortest edge. Boundary nodes slide in their tangent planes; once every tet is
//     positive, one more round over every node the rounds moved, no tet allowed to fold, and
//     they go back onto the surface. A mesh already untangled skips it: the barrier trades the
//     worst measures for less total distortion, and the optimisation raises the worst. If tets
//     are still folded (or four rounds in a row neither lowered their count nor raised the
//     least determinant), the crease and corner nodes of their hexes are released (they slide
//     on the surface as the others do) and the untangling runs once more, ending alike.
//  2. Optimisation: L-BFGS on a soft minimum (log-sum-exp) of every term of Verdict's scaled
//     Jacobian (the eight corners and the centre's principal axes), the two inner tets (scaled
//     to 1 in a cube) and the sines of the boundary quads' angles (below 180°), raising the
//     worst of them, in rounds of a sharper soft minimum (β doubled each round). Each round runs
//     in passes over the nodes of the terms within 16/β of the least (whose weight in the
//     gradient is above e^-16 of the least's) and one hex ring around them, the other terms held
//     as they are; a new pass starts when the least has risen by half that span, and the round
//     ends when the soft minimum rises by less than 1e-4 in 20 iterations. Its line search
//     never accepts a point with a tet that is not positive, nor one where a centre or a
//     boundary quad corner folds (or a folded one gets worse), nor one where a hex edge falls
//     below 1e-3 of its hex's mean edge (the scaled measures, ratios of lengths, let two nodes
//     meet).
// Boundary nodes slide on the surface: they step in their tangent planes (crease nodes along
// their crease, corner nodes not at all) and, after the untangling and each optimisation round,
// go back onto the surface's closest point unless that would fold a tet or lower the worst
// measure (held_off_surface counts those). A node is a crease or corner node when the
// surface's normals just beside it (surface_normals_at, probed at a twentieth of its shortest
// edge) spread beyond the feature angle: a smooth part stays smooth however coarse the mesh.
// Given the buffer layer's chains (OptimiseOptions::feature_layer), the crease and corner nodes
// are the chains' instead, kept on the input's creases and corners. Without a surface the
// boundary nodes stay. The energies and gradients are summed over the hexes in parallel (TBB) into
// per-hex slots added in hex order, so the result is the same for any thread count.
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/hexdc/feature_layer.hpp"
#include "volmesh/hexdc/features.hpp"
#include "volmesh/hexdc/surface_projector.hpp"

namespace volmesh {

struct OptimiseOptions {
  int untangle_rounds = 40;         // ε updates per attempt, each an L-BFGS run
  int untangle_iterations = 50;     // L-BFGS iterations per round
  int quality_iterations = 150;     // L-BFGS iterations of the soft minimum, at most, per round
  double theta = 1.0 / 128.0;       // the barrier's volume weight (Garanzha et al.'s)
  double softmin_sharpness = 40.0;  // β of the first round: weights fall by e per 1/β
  int sharpening_rounds = 4;        // rounds of the soft minimum, β doubled each
  // Boundary nodes whose surface normals under their quads leave their mean by more than this
  // are crease or corner nodes (as the other stages').
  double feature_angle_deg = 40.0;
  Progress progress;
  // The input's sharp features and the buffer layer's chains and corner nodes on them, or null:
  // with both, each chain node slides along its crease only (its tangent at the node's closest
  // point) and goes back onto the crease's closest point, each corner node stays on its corner,
  // and neither is ever released. A chain or corner node the projection left off its feature
  // slides on the surface until the step back onto the feature passes the guard. The other
  // boundary nodes are smooth: the creases their normals would find fight the chains.
  const SurfaceFeatures* features = nullptr;
  const FeatureLayer* feature_layer = nullptr;
};

struct OptimiseStats {
  int untangle_rounds = 0, untangle_iterations = 0, quality_iterations = 0;
  Index invalid_tets_before = 0, invalid_tets_after = 0;  // by the doubles' determinants
  double untangle_energy_before = 0.0, untangle_energy_after = 0.0;
  double quality_energy_before = 0.0, quality_energy_after = 0.0;
  double min_quality_before = 0.0, min_quality_after = 0.0;  // the least tet measure
  double min_scaled_jacobian_before = 0.0, min_scaled_jacobian_after = 0.0;  // Verdict's
  // A mesh given with every tet positive whose worst scaled Jacobian the optimisation lowered
  // (the soft minimum also weighs the inner tets and the quad angles) is given back as it was.
  bool reverted = false;
  Index boundary_nodes = 0, crease_nodes = 0, corner_nodes = 0;
  Index features_released = 0;  // crease and corner nodes of hexes the first untangling left folded
  Index held_off_surface = 0;  // boundary nodes whose last step back onto the surface would fold a tet
  double seconds = 0.0;
  Index pinned_nodes = 0;  // chain and corner nodes kept on their features (of those above)
  Index pinned_off_features = 0;  // of those, left off their crease or corner at the end
};

// Moves mesh.points in place; connectivity and boundary faces are unchanged. An empty mesh is
// left as it is. Throws InputError for iteration counts below 0, θ outside [0, 1), a
// sharpness not above 0 or a feature angle outside [0, 180] degrees.
OptimiseStats optimise_hexes(HexMesh& mesh, const SurfaceProjector& surface,
                             const OptimiseOptions& options = {});

}  // namespace volmesh
