// Algorithm 5 of the octree paper: the octree, the extra refinement rules until none
// applies, the vertices moved off the interfaces, M3S per face, M3C per cut leaf, the mesh.
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "agglomerate.hpp"
#include "assemble.hpp"
#include "cut_grid.hpp"
#include "reflex_split.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/cutcell/cutcell_tree.hpp"
#include "volmesh/quality/face_metrics.hpp"

namespace volmesh {
namespace {

// The largest vertex clearance accepted: the clear stretches at an edge's two ends then
// leave at least half of the edge to its crossings.
constexpr double kMaxVertexClearance = 0.25;

// Splits the listed leaves (those not at the deepest level, each once) and rebalances around
// them; returns the leaves made or touched.
std::vector<OctreeLeaf> split_leaves(Octree& tree, std::vector<Index> leaves) {
  std::erase_if(leaves, [&tree](Index i) { return tree.leaf(i).level >= kOctreeMaxLevel; });
  std::sort(leaves.begin(), leaves.end());
  leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
  return cutcell::split_touching(tree, std::move(leaves));
}

void check_options(const CutcellOptions& o) {
  if (o.crossing_levels < 0 || o.face_point_levels < 0)
    throw InputError("cutcell: the extra refinement levels must not be negative");
  if (!(o.vertex_clearance >= 0.0 && o.vertex_clearance <= kMaxVertexClearance))
    throw InputError("cutcell: the vertex clearance must lie in [0, 0.25]");  // kMaxVertexClearance
  if (!(o.split_gap > 0.0 && o.split_gap <= 1.0))
    throw InputError("cutcell: the split gap must lie in (0, 1]");
}

}  // namespace

namespace cutcell {

// The paper's extra rules until none applies: split the leaves they select (through the
// octree's refinement hook), recompute; then the grid of the final tree.
Grid refined_grid(Octree& tree, const Domain& domain, const CutcellOptions& options,
                  CutcellStats& st) {
  st.moved_vertices = st.unresolved_vertices = st.relabelled_vertices = st.split_edges = 0;
  const auto progress = [&options](const char* stage, double fraction) {
    if (options.progress) options.progress(stage, fraction);
  };
  GridSettings settings;
  settings.exact = options.interface_points == InterfacePoints::exact;
  settings.face.exact_points = settings.cell.exact_points = settings.exact;
  settings.face.feature_theta = settings.cell.feature.theta = options.feature_theta;
  settings.cell.feature.phi = options.feature_phi;
  settings.cell.limits = options.limits;
  if (settings.exact)
    settings.face.surface_near = settings.cell.surface_near = [&domain](const Vec3& x, const Vec3& d) {
      std::optional<std::pair<Vec3, Vec3>> best;
      double nearest = 1.0;
      for (const Crossing& c : domain.crossings(x - d, x + d))
        if (c.before != c.after && c.normal.dot(d) > kSameSurfaceCosine * d.norm() && std::abs(c.t - 0.5) < nearest) {
          nearest = std::abs(c.t - 0.5);
          best = {c.point, c.normal};
        }
      return best;
    };
  const int level = options.octree.level;
  const int crossing_level = std::min(kOctreeMaxLevel, level + options.crossing_levels);
  const int face_level = std::min(kOctreeMaxLevel, level + options.face_point_levels);

  Grid grid;
  EdgeMemo memo;
  std::optional<std::vector<OctreeLeaf>> touched;  // by the splits since the last grid
  for (;;) {
    progress("interface points", 0.2);
    grid = make_grid(tree, domain, settings, grid.vertices);
    find_edge_points(grid, memo);
    // The rules on the whole first grid, on later ones where the splits since the last
    // changed something; then the first two on the leaves their splits touch, until none
    // applies, and a grid of the new tree to check (the hidden-feature rule needs the edge
    // points of a grid).
    const LeafMask among = touched ? leaves_among(tree, *touched) : LeafMask{};
    const double clearance = settings.exact ? options.vertex_clearance : 0.0;
    std::vector<Index> split = leaves_by_extra_rules(grid, crossing_level, clearance, among);
    if (settings.exact) {
      const std::vector<Index> hiding = leaves_hiding_features(grid, crossing_level, options.feature_theta, among);
      split.insert(split.end(), hiding.begin(), hiding.end());
    }
    if (!split.empty()) {
      ExtraRuleSplits splits =
          split_by_extra_rules(tree, domain, grid.vertices, memo, std::move(split), crossing_level, clearance);
      st.refinement_passes += splits.rounds;
      touched = std::move(splits.touched);
      continue;
    }
    st.relabelled_vertices = relabel_midpoints(grid);
    if (settings.exact && options.vertex_clearance > 0.0) {
      const auto [moved, unresolved] = move_vertices(grid, options.vertex_clearance);
      st.moved_vertices = moved;
      st.unresolved_vertices = unresolved;
    }
    if (st.relabelled_vertices > 0 || st.moved_vertices > 0) {
      classify_leaves(grid);
      find_edge_points(grid, memo);
    }
    if (settings.exact) split_doubly_crossed_edges(grid, options.split_gap);
    progress("face contours", 0.4);
    contour_faces(grid);
    st.split_edges = static_cast<Index>(
        std::count_if(grid.split_vertex.begin(), grid.split_vertex.end(), [](Index x) { return x != kNoIndex; }));
    if (const std::vector<Index> split = leaves_for_face_points(grid, face_level); !split.empty()) {
      touched = split_leaves(tree, split);
      ++st.refinement_passes;
      continue;
    }
    return grid;
  }
}

}  // namespace cutcell

PolyMesh cutcell_mesh(const Domain& domain, const CutcellOptions& options, CutcellStats* stats) {
  const Clock::time_point start = Clock::now();
  check_options(options);
  if (options.progress) options.progress("octree", 0.0);
  Octree tree = build_octree(domain, options.octree);
  const double octree_seconds = seconds_since(start);
  CutcellStats st;
  PolyMesh mesh = cutcell_mesh_of_tree(std::move(tree), domain, options, &st);
  st.octree_seconds = octree_seconds;
  st.total_seconds = seconds_since(start);
  if (stats) *stats = st;
  return mesh;
}

PolyMesh cutcell_mesh_of_tree(Octree tree, const Domain& domain, const CutcellOptions& options,
                              CutcellStats* stats) {
  using namespace cutcell;
  const Clock::time_point start = Clock::now();
  check_options(options);
  const auto progress = [&options](const char* stage, double fraction) {
    if (options.progress) options.progress(stage, fraction);
  };
  CutcellStats st;
  st.level = options.octree.level;

  const Clock::time_point cutting = Clock::now();
  const Grid grid = refined_grid(tree, domain, options, st);
  progress("cut cells", 0.6);
  std::vector<Index> cut_of(tree.num_leaves(), kNoIndex), cut_leaves;
  for (Index i = 0; i < tree.num_leaves(); ++i)
    if (grid.cut[i]) {
      cut_of[i] = static_cast<Index>(cut_leaves.size());
      cut_leaves.push_back(i);
    }
  std::vector<LeafCut> cuts(cut_leaves.size());
  tbb::parallel_for(std::size_t{0}, cut_leaves.size(),
                    [&](std::size_t k) { cuts[k] = cut_leaf(grid, cut_leaves[k]); });
  for (const FaceResult& r : grid.results) st.face_point_fallbacks += r.contour.point_left_face;
  for (const LeafCut& c : cuts) {
    st.cell_point_fallbacks += c.split.cell_point_left_cell;
    st.merged_faces += static_cast<Index>(c.split.polygons.size());
    for (LoopMethod m : c.split.loops) {
      st.feature_points += m == LoopMethod::feature_fan;
      st.feature_splits += m == LoopMethod::feature_split;
      st.surface_fans += m == LoopMethod::surface_fan;
      st.cell_points += m == LoopMethod::interface_fan;
      st.centroid_fans += m == LoopMethod::centroid_fan;
      st.across_face_triangulations += m == LoopMethod::across_faces;
    }
  }

  progress("mesh", 0.8);
  AssemblyStats assembly;
  PolyMesh mesh = assemble(grid, cuts, cut_of, assembly);
  if (mesh.num_cells() == 0)
    throw InputError("cutcell: no cell lies inside the domain at level " + std::to_string(st.level) +
                     " (the domain is thinner than a cell); raise the level");

  std::vector<double> cell_size(mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) cell_size[c] = tree.cell_size(tree.leaf(assembly.cell_leaf[c]).level);
  std::vector<FaceGeometry> face_geometry;  // the merging's, for the figures below
  if (options.merge_rounds > 0) {
    progress("merging", 0.9);
    AgglomerationOptions merging;
    merging.limits = options.limits;
    merging.min_volume_ratio = options.merge_volume_ratio;
    merging.rounds = options.merge_rounds;
    st.split_cells = split_reflex_cells(mesh, cell_size, options.limits);
    const AgglomerationStats merged = agglomerate(mesh, cell_size, merging, face_geometry);
    st.merged_cells = merged.merged;
    st.joined_faces = merged.joined;
    st.bad_faces = merged.bad_faces;
  }

  // Smallest cell relative to its leaf, and checkMesh's measures.
  const CellFaces cell_faces = build_cell_faces(mesh);
  const MeshGeometry geometry = face_geometry.empty() ? mesh_geometry(mesh, cell_faces)
                                                      : mesh_geometry(mesh, cell_faces, std::move(face_geometry));
  double ratio = std::numeric_limits<double>::infinity();
  for (Index c = 0; c < mesh.num_cells(); ++c)
    ratio = std::min(ratio, geometry.cells[c].volume / std::pow(cell_size[c], 3));
  st.min_cell_volume_ratio = ratio;
  for (const double s : face_skewness(mesh, geometry)) st.max_skewness = std::max(st.max_skewness, s);
  const std::vector<double> angle = face_non_orthogonality(mesh, geometry);
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (!mesh.is_boundary(f)) st.max_non_orthogonality = std::max(st.max_non_orthogonality, angle[f]);
  st.max_leaf_level = tree.max_leaf_level();
  st.leaves = tree.num_leaves();
  st.cells = mesh.num_cells();
  st.cut_cells = assembly.cut_cells;
  st.faces = mesh.num_faces();
  st.vertices = mesh.num_points();
  st.cut_seconds = seconds_since(cutting);
  st.total_seconds = seconds_since(start);
  progress("done", 1.0);
  if (stats) *stats = st;
  return mesh;
}

}  // namespace volmesh
