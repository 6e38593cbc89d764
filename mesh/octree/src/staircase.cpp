// Staircase mesh of an octree: cubes kept by their centre's region.
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/octree/staircase.hpp"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <sstream>

#include "vertex_table.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {

namespace {

// One face a kept cell emits: its loop is a leaf face (of `leaf`, side `face`), reversed
// when the owner is on the other side.
struct FaceSpec {
  Index leaf;
  std::int8_t face;
  bool reversed;
  Index owner, neighbour;  // cells; neighbour kNoIndex on the boundary
};

// The faces leaf i emits: shared faces once (same size: from the lower cell; big/small:
// from the small side), boundary faces from the kept side.
void faces_of(const Octree& tree, const std::vector<Index>& cell_of, Index i,
              std::vector<FaceSpec>& out) {
  const Index c = cell_of[i];
  for (int f = 0; f < 6; ++f) {
    const FaceNeighbours nb = tree.face_neighbours(i, f);
    switch (nb.kind) {
      case FaceKind::Boundary:
        out.push_back({i, static_cast<std::int8_t>(f), false, c, kNoIndex});
        break;
      case FaceKind::Same:
      case FaceKind::Coarser: {
        const Index d = cell_of[nb.leaves[0]];
        if (d == kNoIndex)
          out.push_back({i, static_cast<std::int8_t>(f), false, c, kNoIndex});
        else if (nb.kind == FaceKind::Coarser || c < d)
          out.push_back({i, static_cast<std::int8_t>(f), d < c, std::min(c, d), std::max(c, d)});
        break;
      }
      case FaceKind::Finer:
        // Kept small neighbours emit their side; a dropped one leaves a boundary quarter.
        for (const Index s : nb.leaves)
          if (cell_of[s] == kNoIndex)
            out.push_back({s, static_cast<std::int8_t>(opposite_face(f)), true, c, kNoIndex});
        break;
    }
  }
}

}  // namespace

PolyMesh staircase_cells(const Octree& tree, const Domain& domain, std::vector<Index>* cell_leaf) {
  const OctreeVertices vertices = octree_vertex_geometry(tree);

  const Index n = tree.num_leaves();
  std::vector<Vec3> centres(n);
  tbb::parallel_for(Index{0}, n, [&](Index i) { centres[i] = tree.world(tree.leaf(i).centre()); });
  std::vector<Index> region(n);
  domain.region(centres, region);
  std::vector<Index> cell_of(n, kNoIndex);
  PolyMesh mesh;
  if (cell_leaf) cell_leaf->clear();
  for (Index i = 0; i < n; ++i)
    if (region[i] != 0) {
      cell_of[i] = mesh.num_cells();
      mesh.cell_region.push_back(region[i]);
      if (cell_leaf) cell_leaf->push_back(i);
    }
  if (mesh.num_cells() == 0) return mesh;

  // Faces per chunk of leaves, concatenated in chunk order: the same order for any thread
  // count.
  constexpr Index kChunk = 4096;
  std::vector<std::vector<FaceSpec>> chunks((n + kChunk - 1) / kChunk);
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t k) {
    const Index end = std::min<Index>(n, static_cast<Index>((k + 1) * kChunk));
    for (Index i = static_cast<Index>(k * kChunk); i < end; ++i)
      if (cell_of[i] != kNoIndex) faces_of(tree, cell_of, i, chunks[k]);
  });
  std::size_t face_count = 0;
  for (const auto& c : chunks) face_count += c.size();
  if (face_count > static_cast<std::size_t>(kMaxIndex))
    throw InputError("staircase: " + std::to_string(face_count) +
                     " faces exceed the index limit; lower the level");

  // Face loops, then the used vertices renumbered in Morton order.
  std::vector<Index> point_of(vertices.num_vertices(), kNoIndex);
  std::vector<Index> loop;
  std::vector<FaceSpec> specs;
  specs.reserve(face_count);
  for (const auto& c : chunks) specs.insert(specs.end(), c.begin(), c.end());
  chunks.clear();
  mesh.owner.reserve(specs.size());
  mesh.neighbour.reserve(specs.size());
  mesh.face_tag.reserve(specs.size());
  mesh.face_offsets.reserve(specs.size() + 1);
  for (const FaceSpec& s : specs) {
    loop.clear();
    leaf_face_loop(vertices, s.leaf, s.face, loop);
    if (s.reversed) std::reverse(loop.begin(), loop.end());
    mesh.face_vertices.insert(mesh.face_vertices.end(), loop.begin(), loop.end());
    mesh.face_offsets.push_back(static_cast<Index>(mesh.face_vertices.size()));
    mesh.owner.push_back(s.owner);
    mesh.neighbour.push_back(s.neighbour);
    mesh.face_tag.push_back(kNoIndex);
    for (const Index v : loop) point_of[v] = 0;
  }
  for (Index v = 0; v < vertices.num_vertices(); ++v)
    if (point_of[v] == 0) {
      point_of[v] = static_cast<Index>(mesh.points.size());
      mesh.points.push_back(vertices.points[v]);
    }
  for (Index& v : mesh.face_vertices) v = point_of[v];

  // Boundary tags: the name of the interface nearest to the face centre.
  std::vector<std::string> names(specs.size());
  tbb::parallel_for(std::size_t{0}, specs.size(), [&](std::size_t k) {
    if (specs[k].neighbour != kNoIndex) return;
    const OctreeLeaf& leaf = tree.leaf(specs[k].leaf);
    const int f = specs[k].face;
    GridPoint centre = leaf.centre();
    centre[f / 2] = leaf.anchor[f / 2] + (f & 1) * leaf.size();
    names[k] = domain.boundary_name(tree.world(centre));
    if (names[k].empty()) names[k] = "boundary";
  });
  for (std::size_t k = 0; k < specs.size(); ++k)
    if (specs[k].neighbour == kNoIndex) mesh.face_tag[k] = mesh.tag_index(names[k]);

  return mesh;
}

PolyMesh staircase_mesh(const Domain& domain, const StaircaseOptions& options,
                        StaircaseStats* stats) {
  const Clock::time_point start = Clock::now();
  auto progress = [&](const char* stage, double fraction) {
    if (options.progress) options.progress(stage, fraction);
  };
  progress("octree", 0.0);
  const Octree tree = build_octree(domain, options.octree);
  const double octree_seconds = seconds_since(start);
  const Clock::time_point meshing = Clock::now();
  progress("cells", 0.5);
  PolyMesh mesh = staircase_cells(tree, domain);
  if (mesh.num_cells() == 0) {
    std::ostringstream msg;
    msg << "domain: no cell centre lies inside the domain at --level " << options.octree.level
        << " (cell edge " << tree.cell_size(options.octree.level)
        << "): the domain is thinner than one cell; raise the level";
    throw InputError(msg.str());
  }
  progress("done", 1.0);
  if (stats) {
    stats->level = options.octree.level;
    stats->leaves = tree.num_leaves();
    stats->cells = mesh.num_cells();
    stats->faces = mesh.num_faces();
    stats->vertices = mesh.num_points();
    stats->octree_seconds = octree_seconds;
    stats->mesh_seconds = seconds_since(meshing);
    stats->total_seconds = seconds_since(start);
  }
  return mesh;
}

}  // namespace volmesh
