#include "volmesh/runs/mesh_pieces.hpp"

#include <iostream>
#include <algorithm>
#include <numeric>
#include <set>
#include <utility>

#include "volmesh/runs/distributed.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/parallel.hpp"
#include "volmesh/meshers/cutcell_request.hpp"
#include "volmesh/meshers/grid.hpp"
#include "volmesh/meshers/octree_request.hpp"
#include "volmesh/octree_dist/cutcell_piece.hpp"
#include "volmesh/octree_dist/grid_piece.hpp"
#include "volmesh/octree_dist/staircase_piece.hpp"

namespace volmesh::cli {

std::string why_not_on_every_rank(const meshers::MesherInfo& method,
                                  const meshers::MethodOptions& given) {
  if (!p4est_built()) return "this volmesh was built without p4est";
  if (method.name == "staircase" || method.name == "cutcell") return "";
  if (method.name == "grid")
    return meshers::given<bool>(given, "tets").value_or(false) ? "grid --tets has no pieces" : "";
  return method.name + " does not mesh in pieces";
}

namespace {

// The methods whose meshes follow an octree, partitioned by it under mpirun unless
// --partition metis is given.
bool octree_partition_by_default(const std::string& method) {
  return method == "cutcell" || method == "staircase" || method == "grid";
}

}  // namespace

bool partition_in_pieces(const std::string& partition, const std::string& method,
                         const meshers::MethodOptions& given, const std::string& output) {
  if (!fem::distributed_run() || partition == "metis") return false;
  if (partition.empty() && (method.empty() || !octree_partition_by_default(method))) return false;
  std::string why = method.empty() ? "a mesh read from a file"
                                   : why_not_on_every_rank(meshers::find_mesher(method), given);
  if (why.empty() && !output.empty() && std::filesystem::path(output).extension() != ".pvtu")
    why = "the ranks write their pieces to a .pvtu, not " + output;
  if (why.empty()) return true;
  if (fem::rank() == 0) std::cerr << "note: " << why << ": rank 0 meshes, METIS partitions\n";
  return false;
}

std::vector<std::string> boundary_tags_over_ranks(const PolyMesh& piece) {
  std::vector<char> mine;
  for (const std::string& name : piece.tag_names)
    if (!name.starts_with(kPieceBoundaryPrefix)) {
      mine.insert(mine.end(), name.begin(), name.end());
      mine.push_back('\0');
    }
  std::set<std::string> names;
  for (const std::vector<char>& from : fem::gather_bytes_to_all(mine))
    for (auto at = from.begin(); at != from.end(); ++at) {
      const auto end = std::find(at, from.end(), '\0');
      names.emplace(at, end);
      at = end;
    }
  return {names.begin(), names.end()};
}

RankMesh mesh_on_every_rank(const meshers::MesherInfo& method, const Domain& domain,
                            const meshers::MeshRequest& request) {
  RankMesh out;
  fem::stage("mesh", [&] {
    if (method.name == "grid") {
      const Box3 box = meshers::grid_box(domain, request);
      out.piece = grid_piece(box, *request.level);
      out.h = box.size().maxCoeff() / static_cast<double>(std::int64_t{1} << *request.level);
      return;
    }
    const OctreeOptions options = meshers::octree_request(request);
    out.h = meshers::octree_cell_size(domain, options);
    if (method.name == "cutcell")
      out.piece = cutcell_piece(domain, meshers::cutcell_request(request));
    else
      out.piece = staircase_piece(build_distributed_octree(domain, options), domain);
  });
  require_cell_per_rank(out.piece.global_cell_count);
  return out;
}

MeshPiece pvtu_piece(RankPiece piece, MeshFields fields, int rank) {
  const Index cells = piece.mesh.num_cells();
  fields.cell_ints.insert(fields.cell_ints.begin(),
                          {{"GlobalCellIds", {piece.global_cells.begin(), piece.global_cells.end()}},
                           {"partition", std::vector<Index>(cells, rank)}});
  // MeshFields has no integer point arrays: doubles hold these ids exactly.
  fields.point.insert(fields.point.begin(),
                      {"GlobalPointIds", 1, {piece.global_points.begin(), piece.global_points.end()}});
  return {std::move(piece.mesh), std::move(fields)};
}

RankPiece whole_mesh_piece(PolyMesh mesh) {
  RankPiece out;
  out.global_cell_count = mesh.num_cells();
  out.global_point_count = mesh.num_points();
  out.global_cells.resize(out.global_cell_count);
  std::iota(out.global_cells.begin(), out.global_cells.end(), 0);
  out.global_points.resize(out.global_point_count);
  std::iota(out.global_points.begin(), out.global_points.end(), 0);
  out.point_owner.assign(out.global_point_count, 0);
  out.mesh = std::move(mesh);
  return out;
}

void write_rank_piece(RankPiece piece, MeshFields fields, const std::filesystem::path& path) {
  MeshPiece mine;
  fem::stage("write", [&] { mine = pvtu_piece(std::move(piece), std::move(fields), fem::rank()); });
  write_pieces(std::move(mine), path, fem::ranks());
}

}  // namespace volmesh::cli
