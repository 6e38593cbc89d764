#pragma once
// The paper's buffer layer ("pillowing"): one layer of hexes between the boundary and the rest of
// the mesh, so that no hex keeps two or more faces on the boundary, where smoothing alone cannot
// open up the flat or reflex angle between them.
//
// Every boundary node gets an inner copy, offset inward from it by offset_fraction of the node's
// shortest edge: along the unit sum of its boundary quads' vector areas, or, on a crease or corner
// (quad normals spread beyond the feature angle), along the mean of their unit normals, which
// points into the cell angle. Every existing hex takes the inner copies instead of the boundary
// nodes, and each boundary quad gets one hex joining it to its inner quad (the outward quad as
// corners 4-7, the inner one as 0-3: positive in VTK order). The boundary keeps the same quads on
// the same nodes; every hex touching it is a pillow hex with exactly one boundary face.
//
// An inner copy in a hex failing the ten corner tets after insertion has its offset halved, up to
// `halvings` times, as long as that lowers the failures among its hexes (a thinner pillow hex on a
// curved quad fails sooner); what still fails is counted in invalid_hexes_after. Hexes failing
// before are not unfolded by the layer alone: smoothing after it can, now that they are off the
// boundary.
//
// Given the input's sharp features, the layer can follow them (feature_layer.hpp): chains of
// boundary edges along the creases and nodes on the corners before the copies are made, and the
// patches between chains pillowed once more after.
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/hexdc/feature_layer.hpp"

namespace volmesh {

struct PillowOptions {
  // Of the shortest edge at the node: deep enough to open the angle between two boundary faces of
  // one hex, shallow enough to leave the old hex most of its thickness.
  double offset_fraction = 0.3;
  int halvings = 4;  // an offset making a hex fail is halved at most this many times
  // Boundary nodes whose quad normals leave their mean by more than this are creases or corners: as
  // SmoothingOptions' feature angle.
  double feature_angle_deg = 40.0;
  // The input's creases and corners, if known: their chains (feature_layer.hpp) are found before
  // the copies are made, and with follow_features the patches between them pillowed again.
  const SurfaceFeatures* features = nullptr;
  bool follow_features = false;
};

struct PillowStats {
  Index boundary_nodes = 0;  // inner copies made
  Index pillow_hexes = 0;    // one per boundary quad
  Index shrunk_copies = 0;   // inner copies whose offset was halved at least once
  // Hexes with >= 2 boundary faces; after is 0 for a closed boundary.
  Index multi_boundary_hexes_before = 0, multi_boundary_hexes_after = 0;
  // Hexes failing the ten corner tets.
  Index invalid_hexes_before = 0, invalid_hexes_after = 0;
  double min_scaled_jacobian_before = 0.0, min_scaled_jacobian_after = 0.0;
};

// Adds the layer in place; mesh.boundary_faces and their tags are kept, the new hexes take the
// region of the hex behind their quad. An empty mesh is left as it is. Throws InputError for an
// offset fraction outside (0, 1), negative halvings or a feature angle outside [0, 180] degrees.
// With options.features, `layer` (if given) receives the chains and the pinned nodes.
PillowStats pillow_boundary(HexMesh& mesh, const PillowOptions& options = {},
                            FeatureLayer* layer = nullptr);

}  // namespace volmesh
