#pragma once
// The staircase mesher (docs/methods.md, "staircase"): the octree refined toward the boundaries
// and interfaces, each leaf kept as a cube when its centre lies in a region (region 0 dropped).
// The first-order baseline the cut-cell convergence studies compare against.
#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/octree/octree.hpp"

namespace volmesh {

struct StaircaseOptions {
  OctreeOptions octree;
  // Called from the calling thread as each stage starts ("octree", "cells", then "done"),
  // with a rough fraction of the run done.
  Progress progress;
};

struct StaircaseStats {
  int level = 0;
  Index leaves = 0, cells = 0, faces = 0, vertices = 0;
  double octree_seconds = 0.0, mesh_seconds = 0.0, total_seconds = 0.0;
};

// A cell per kept leaf, in Morton order, region = the region at its centre. A face per
// same-size pair, per small side of a big/small pair (a big leaf next to four small ones has
// four faces there), and per leaf side facing a dropped leaf or the root boundary. Every
// face lists every mesh vertex on its edges, so each cell closes edge by edge. Boundary
// faces are tagged domain.boundary_name(face centre), or "boundary" when unnamed; faces
// between two regions stay internal. Throws InputError (octree limits, or no cell centre
// inside the domain: the domain is thinner than a cell at this level).
PolyMesh staircase_mesh(const Domain& domain, const StaircaseOptions& options,
                        StaircaseStats* stats = nullptr);

// The same cells for a given balanced tree (leaves kept by the region at their centre);
// cell_leaf (optional): each cell's leaf.
PolyMesh staircase_cells(const Octree& tree, const Domain& domain, std::vector<Index>* cell_leaf = nullptr);

}  // namespace volmesh
