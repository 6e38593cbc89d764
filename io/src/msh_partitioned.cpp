// Gmsh MSH 4.1 with partitioned entities, laid out as Gmsh lays out a mesh it partitioned
// itself (gmsh -part K): the model entities in $Entities, the partitioned entities in
// $PartitionedEntities, nodes and elements classified on the partitioned entities. Gmsh's
// optional partition-boundary topology (-part_topo) is not written: readers need only the
// entities that hold elements.
#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "canonical_order.hpp"
#include "element_export.hpp"
#include "msh_elements.hpp"
#include "msh_format.hpp"
#include "text_format.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/partitioned_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

using msh::Element;
using msh::make_element;

struct Box {
  Vec3 lo = Vec3::Constant(0.0), hi = Vec3::Constant(0.0);
  bool empty = true;
  void add(const Vec3& x) {
    lo = empty ? x : Vec3(lo.cwiseMin(x));
    hi = empty ? x : Vec3(hi.cwiseMax(x));
    empty = false;
  }
  void add(const Box& b) {
    if (!b.empty) add(b.lo), add(b.hi);
  }
};

// A model entity (parent 0) or a partitioned one (parent: its model entity's tag).
struct Entity {
  Index tag = 0;
  Index physical = 0;  // the physical group: the model entity's tag
  std::string name;    // of the physical group, model entities only
  Index parent = 0;
  std::vector<Index> partitions;  // Gmsh's partition numbers, 1 .. parts
  std::vector<Element> elements;
  Box box;
};

void check_partition(const PolyMesh& mesh, std::span<const Index> cell_part, Index parts,
                     const fs::path& path) {
  if (parts < 1) throw InputError(path.string() + ": " + std::to_string(parts) + " parts");
  if (cell_part.size() != static_cast<std::size_t>(mesh.num_cells()))
    throw InputError(path.string() + ": " + std::to_string(cell_part.size()) + " cell parts for " +
                     std::to_string(mesh.num_cells()) + " cells");
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (cell_part[c] < 0 || cell_part[c] >= parts)
      throw InputError(path.string() + ": cell " + std::to_string(c) + ": part " +
                       std::to_string(cell_part[c]) + " not in 0.." + std::to_string(parts - 1));
    if (mesh.cell_region[c] < 1)
      throw InputError(path.string() + ": cell " + std::to_string(c) + ": region " +
                       std::to_string(mesh.cell_region[c]) + " (MSH needs regions >= 1)");
  }
}

// Collects partitioned entities by key, in key order, with tags from first_tag on.
template <typename Key>
class PartitionedEntities {
 public:
  Entity& at(const Key& key, Index parent, std::vector<Index> partitions) {
    auto [it, added] = by_key_.try_emplace(key);
    if (added) {
      it->second.parent = it->second.physical = parent;
      it->second.partitions = std::move(partitions);
    }
    return it->second;
  }
  std::vector<Entity> take(Index first_tag) {
    std::vector<Entity> out;
    for (auto& [key, entity] : by_key_) {
      entity.tag = first_tag++;
      out.push_back(std::move(entity));
    }
    return out;
  }

 private:
  std::map<Key, Entity> by_key_;
};

struct Entities {
  std::vector<Entity> volumes, surfaces;            // model
  std::vector<Entity> part_volumes, part_surfaces;  // partitioned
};

// Volumes: region r is model volume r; its cells in part p form the partitioned volume
// (p, r). Element tag c + 1 for cell c, cells in order within an entity.
void add_volumes(const PolyMesh& mesh, std::span<const Index> cell_part,
                 const std::vector<CellCorners>& cells, Entities& entities,
                 std::vector<Index>& cell_entity) {
  PartitionedEntities<std::pair<Index, Index>> parts;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Index r = mesh.cell_region[c];
    Entity& e = parts.at({cell_part[c], r}, r, {cell_part[c] + 1});
    if (cells[c].shape == CellShape::Tetrahedron)
      e.elements.push_back(make_element(c + 1, canonical_tet(cells[c].corners), 4));
    else
      e.elements.push_back(make_element(c + 1, canonical_hex(cells[c].corners), 8));
  }
  const std::vector<Index> regions = regions_of(mesh);
  for (Index r : regions) entities.volumes.push_back({r, r, msh::region_name(r), 0, {}, {}, {}});
  entities.part_volumes = parts.take(regions.empty() ? 1 : regions.back() + 1);
  // Which partitioned volume holds each cell, for the node classification.
  for (std::size_t i = 0; i < entities.part_volumes.size(); ++i)
    for (const Element& e : entities.part_volumes[i].elements)
      cell_entity[e.tag - 1] = static_cast<Index>(i);
}

// Surfaces: boundary tag t is model surface t + 1 and the interfaces between regions follow,
// oriented from region a to region b, as write_msh numbers them. A face lies in the
// partitioned surface of (its cells' parts, model surface).
void add_surfaces(const PolyMesh& mesh, std::span<const Index> cell_part, const fs::path& path,
                  Entities& entities) {
  PartitionedEntities<std::pair<std::vector<Index>, Index>> parts;
  auto add_face = [&](Index f, Index surface, bool reverse) {
    std::vector<Index> partitions{cell_part[mesh.owner[f]] + 1};
    if (!mesh.is_boundary(f)) partitions.push_back(cell_part[mesh.neighbour[f]] + 1);
    std::sort(partitions.begin(), partitions.end());
    partitions.erase(std::unique(partitions.begin(), partitions.end()), partitions.end());
    const auto loop = mesh.face(f);
    Element e = make_element(0, loop, loop.size());
    const std::span<Index> vertices(e.vertices.data(), e.size);
    if (reverse) std::reverse(vertices.begin(), vertices.end());
    rotate_to_smallest(vertices);
    parts.at({partitions, surface}, surface, partitions).elements.push_back(e);
  };
  const auto by_tag = boundary_faces_by_tag(mesh, path);
  for (std::size_t t = 0; t < by_tag.size(); ++t) {
    if (by_tag[t].empty()) continue;
    const Index tag = static_cast<Index>(t) + 1;
    entities.surfaces.push_back({tag, tag, mesh.tag_names[t], 0, {}, {}, {}});
    for (Index f : by_tag[t]) add_face(f, tag, false);
  }
  Index next = static_cast<Index>(by_tag.size()) + 1;
  for (const RegionInterface& interface : region_interfaces(mesh)) {
    const Index tag = next++;
    entities.surfaces.push_back(
        {tag, tag, msh::interface_name(interface.region_a, interface.region_b), 0, {}, {}, {}});
    for (Index f : interface.faces)
      add_face(f, tag, mesh.cell_region[mesh.owner[f]] != interface.region_a);
  }
  for (const Entity& entity : entities.surfaces)
    if (entity.name.find_first_of("\"\n\r") != std::string::npos)
      throw InputError(path.string() + ": boundary tag '" + entity.name +
                       "': quotes and line breaks cannot be written to MSH");
  entities.part_surfaces = parts.take(next);
}

// Cells keep their order within an element type; faces are sorted by vertices and numbered
// after the cells. Boxes from the elements; a model entity's box holds its parts' boxes.
void finish(const PolyMesh& mesh, Entities& entities) {
  for (Entity& entity : entities.part_volumes) msh::sort_by_size(entity.elements);
  Index next = mesh.num_cells() + 1;
  for (Entity& entity : entities.part_surfaces) {
    msh::sort_by_vertices(entity.elements);
    for (Element& e : entity.elements) e.tag = next++;
  }
  for (auto [model, parts] : {std::pair{&entities.volumes, &entities.part_volumes},
                              std::pair{&entities.surfaces, &entities.part_surfaces}})
    for (Entity& part : *parts) {
      for (const Element& e : part.elements)
        for (Index v : e.corners()) part.box.add(mesh.points[v]);
      std::find_if(model->begin(), model->end(), [&](const Entity& m) {
        return m.tag == part.parent;
      })->box.add(part.box);
    }
}

void append_box(std::string& text, const Box& box) {
  for (const Vec3* corner : {&box.lo, &box.hi})
    for (int i = 0; i < 3; ++i) text += ' ', append_number(text, (*corner)[i]);
}

// "tag [dim parent #partitions partitions...] box 1 physical 0": one physical group, no
// bounding entities.
void append_entity(std::string& text, const Entity& entity, int dim) {
  append_number(text, entity.tag);
  if (entity.parent != 0) {
    for (long long v : {static_cast<long long>(dim), static_cast<long long>(entity.parent),
                        static_cast<long long>(entity.partitions.size())})
      text += ' ', append_number(text, v);
    for (Index p : entity.partitions) text += ' ', append_number(text, p);
  }
  append_box(text, entity.box);
  text += " 1 ";
  append_number(text, entity.physical);
  text += " 0\n";
}

void append_header(std::string& text, const Entities& entities, Index parts) {
  text += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n";
  append_number(text, static_cast<long long>(entities.volumes.size() + entities.surfaces.size()));
  text += '\n';
  for (int dim : {2, 3})
    for (const Entity& entity : dim == 2 ? entities.surfaces : entities.volumes) {
      append_number(text, dim);
      text += ' ';
      append_number(text, entity.tag);
      text += " \"" + entity.name + "\"\n";
    }
  text += "$EndPhysicalNames\n$Entities\n0 0 ";
  append_number(text, static_cast<long long>(entities.surfaces.size()));
  text += ' ';
  append_number(text, static_cast<long long>(entities.volumes.size()));
  text += '\n';
  for (const Entity& entity : entities.surfaces) append_entity(text, entity, 2);
  for (const Entity& entity : entities.volumes) append_entity(text, entity, 3);
  text += "$EndEntities\n$PartitionedEntities\n";
  append_number(text, parts);
  text += "\n0\n0 0 ";  // no ghost entities, no partitioned points or curves
  append_number(text, static_cast<long long>(entities.part_surfaces.size()));
  text += ' ';
  append_number(text, static_cast<long long>(entities.part_volumes.size()));
  text += '\n';
  for (const Entity& entity : entities.part_surfaces) append_entity(text, entity, 2);
  for (const Entity& entity : entities.part_volumes) append_entity(text, entity, 3);
  text += "$EndPartitionedEntities\n";
}

// Node v lies on the partitioned volume of the first cell, in (part, cell) order, that uses
// it; a point no cell uses goes with the first partitioned volume.
std::vector<std::vector<Index>> classify_nodes(const PolyMesh& mesh,
                                               std::span<const Index> cell_part,
                                               const std::vector<CellCorners>& cells,
                                               const std::vector<Index>& cell_entity,
                                               std::size_t num_entities) {
  std::vector<Index> order(mesh.num_cells());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](Index a, Index b) { return cell_part[a] < cell_part[b]; });
  std::vector<Index> node_entity(mesh.num_points(), kNoIndex);
  for (Index c : order) {
    const int corners = cells[c].shape == CellShape::Tetrahedron ? 4 : 8;
    for (int k = 0; k < corners; ++k) {
      Index& e = node_entity[cells[c].corners[k]];
      if (e == kNoIndex) e = cell_entity[c];
    }
  }
  std::vector<std::vector<Index>> nodes(num_entities);
  if (num_entities == 0) return nodes;
  for (Index v = 0; v < mesh.num_points(); ++v)
    nodes[node_entity[v] == kNoIndex ? 0 : node_entity[v]].push_back(v);
  return nodes;
}

void append_nodes(std::string& text, const PolyMesh& mesh, const Entities& entities,
                  const std::vector<std::vector<Index>>& nodes) {
  long long blocks = 0, count = 0;
  for (const auto& block : nodes) {
    blocks += block.empty() ? 0 : 1;
    count += static_cast<long long>(block.size());
  }
  text += "$Nodes\n";
  for (long long v : {blocks, count, count > 0 ? 1LL : 0LL, count})
    append_number(text, v), text += ' ';
  text.back() = '\n';
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].empty()) continue;
    text += "3 ";
    append_number(text, entities.part_volumes[i].tag);
    text += " 0 ";
    append_number(text, static_cast<long long>(nodes[i].size()));
    text += '\n';
    for (Index v : nodes[i]) append_number(text, v + 1), text += '\n';
    for (Index v : nodes[i]) {
      for (int k = 0; k < 3; ++k) {
        if (k > 0) text += ' ';
        append_number(text, mesh.points[v][k]);
      }
      text += '\n';
    }
  }
  text += "$EndNodes\n";
}

}  // namespace

void write_msh_partitioned(const PolyMesh& mesh, std::span<const Index> cell_part, Index parts,
                           const fs::path& path) {
  check_partition(mesh, cell_part, parts, path);
  const std::vector<CellCorners> cells =
      classify_elements(mesh, build_cell_faces(mesh), path, "MSH 4.1");
  Entities entities;
  std::vector<Index> cell_entity(mesh.num_cells(), kNoIndex);
  add_volumes(mesh, cell_part, cells, entities, cell_entity);
  add_surfaces(mesh, cell_part, path, entities);
  finish(mesh, entities);

  std::string text;
  append_header(text, entities, parts);
  append_nodes(text, mesh, entities,
               classify_nodes(mesh, cell_part, cells, cell_entity, entities.part_volumes.size()));
  std::vector<msh::ElementGroup> groups;
  for (const Entity& entity : entities.part_surfaces) groups.push_back({2, entity.tag, entity.elements});
  for (const Entity& entity : entities.part_volumes) groups.push_back({3, entity.tag, entity.elements});
  msh::append_elements(text, groups);
  write_text_file(path, text);
}

}  // namespace volmesh
