// Gmsh MSH 4.1 ASCII output: one volume entity and physical group per region, one surface
// entity and physical group per boundary tag and per pair of touching regions.
#include <algorithm>
#include <array>
#include <map>
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
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

using msh::Element;
using msh::make_element;

// A Gmsh entity with its physical group of the same tag, and the elements it holds.
struct Entity {
  Index tag = 0;
  std::string name;
  std::vector<Element> elements;
};

// Element tag c + 1 for cell c lets the reader restore the cell order.
std::vector<Entity> volume_entities(const PolyMesh& mesh, const std::vector<CellCorners>& cells,
                                    const fs::path& path) {
  std::map<Index, Entity> by_region;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_region[c] < 1)
      throw InputError(path.string() + ": cell " + std::to_string(c) + ": region " +
                       std::to_string(mesh.cell_region[c]) + " (MSH needs regions >= 1)");
    auto& elements = by_region[mesh.cell_region[c]].elements;
    if (cells[c].shape == CellShape::Tetrahedron)
      elements.push_back(make_element(c + 1, canonical_tet(cells[c].corners), 4));
    else
      elements.push_back(make_element(c + 1, canonical_hex(cells[c].corners), 8));
  }
  std::vector<Entity> entities;
  for (auto& [region, entity] : by_region) {
    entity.tag = region;
    entity.name = msh::region_name(region);
    entities.push_back(std::move(entity));
  }
  return entities;
}

// Boundary tag t becomes surface t + 1; interfaces follow in (a, b) order, oriented from
// region a to region b.
std::vector<Entity> surface_entities(const PolyMesh& mesh, const fs::path& path) {
  auto element = [&](Index f, bool reverse) {
    auto loop = mesh.face(f);
    Element e = make_element(0, loop, loop.size());
    const std::span<Index> vertices(e.vertices.data(), e.size);
    if (reverse) std::reverse(vertices.begin(), vertices.end());
    rotate_to_smallest(vertices);
    return e;
  };
  std::vector<Entity> entities;
  const auto by_tag = boundary_faces_by_tag(mesh, path);
  for (std::size_t t = 0; t < by_tag.size(); ++t) {
    if (by_tag[t].empty()) continue;
    Entity& entity =
        entities.emplace_back(Entity{static_cast<Index>(t) + 1, mesh.tag_names[t], {}});
    for (Index f : by_tag[t]) entity.elements.push_back(element(f, false));
  }
  Index next = static_cast<Index>(by_tag.size()) + 1;
  for (const RegionInterface& interface : region_interfaces(mesh)) {
    Entity& entity = entities.emplace_back(
        Entity{next++, msh::interface_name(interface.region_a, interface.region_b), {}});
    for (Index f : interface.faces)
      entity.elements.push_back(element(f, mesh.cell_region[mesh.owner[f]] != interface.region_a));
  }
  for (const Entity& entity : entities)
    if (entity.name.find_first_of("\"\n\r") != std::string::npos)
      throw InputError(path.string() + ": boundary tag '" + entity.name +
                       "': quotes and line breaks cannot be written to MSH");
  return entities;
}

void number_elements(std::vector<Entity>& entities, Index first_tag) {
  for (Entity& entity : entities)
    for (Element& e : entity.elements) e.tag = first_tag++;
}

void append_box(std::string& text, const PolyMesh& mesh, const Entity& entity) {
  Vec3 lo = Vec3::Constant(0.0), hi = Vec3::Constant(0.0);
  bool first = true;
  for (const Element& e : entity.elements)
    for (Index v : std::span(e.vertices.data(), e.size)) {
      lo = first ? mesh.points[v] : Vec3(lo.cwiseMin(mesh.points[v]));
      hi = first ? mesh.points[v] : Vec3(hi.cwiseMax(mesh.points[v]));
      first = false;
    }
  for (int i = 0; i < 3; ++i) text += ' ', append_number(text, lo[i]);
  for (int i = 0; i < 3; ++i) text += ' ', append_number(text, hi[i]);
}

void append_header(std::string& text, const PolyMesh& mesh, const std::vector<Entity>& volumes,
                   const std::vector<Entity>& surfaces) {
  text += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n";
  append_number(text, static_cast<long long>(volumes.size() + surfaces.size()));
  text += '\n';
  for (const auto* group : {&surfaces, &volumes})
    for (const Entity& entity : *group) {
      text += group == &surfaces ? "2 " : "3 ";
      append_number(text, entity.tag);
      text += " \"" + entity.name + "\"\n";
    }
  text += "$EndPhysicalNames\n$Entities\n0 0 ";
  append_number(text, static_cast<long long>(surfaces.size()));
  text += ' ';
  append_number(text, static_cast<long long>(volumes.size()));
  text += '\n';
  for (const auto* group : {&surfaces, &volumes})
    for (const Entity& entity : *group) {
      append_number(text, entity.tag);
      append_box(text, mesh, entity);
      text += " 1 ";  // one physical tag, equal to the entity tag; no bounding entities
      append_number(text, entity.tag);
      text += " 0\n";
    }
  text += "$EndEntities\n";
}

// All nodes in one block on the first volume entity (Gmsh accepts nodes classified on any
// entity). A mesh without cells has no entity to carry them and gets no nodes.
void append_nodes(std::string& text, const PolyMesh& mesh, const std::vector<Entity>& volumes) {
  const long long n = volumes.empty() ? 0 : mesh.num_points();
  text += "$Nodes\n";
  for (long long v : {n > 0 ? 1LL : 0LL, n, n > 0 ? 1LL : 0LL, n})
    append_number(text, v), text += ' ';
  text.back() = '\n';
  if (n > 0) {
    text += "3 ";
    append_number(text, volumes.front().tag);
    text += " 0 ";
    append_number(text, n);
    text += '\n';
    for (long long p = 1; p <= n; ++p) append_number(text, p), text += '\n';
    for (const Vec3& x : mesh.points) {
      for (int i = 0; i < 3; ++i) {
        if (i > 0) text += ' ';
        append_number(text, x[i]);
      }
      text += '\n';
    }
  }
  text += "$EndNodes\n";
}

}  // namespace

void write_msh(const PolyMesh& mesh, const fs::path& path) {
  const std::vector<CellCorners> cells =
      classify_elements(mesh, build_cell_faces(mesh), path, "MSH 4.1");
  std::vector<Entity> volumes = volume_entities(mesh, cells, path);
  std::vector<Entity> surfaces = surface_entities(mesh, path);
  for (Entity& entity : volumes) msh::sort_by_size(entity.elements);
  for (Entity& entity : surfaces) msh::sort_by_vertices(entity.elements);
  number_elements(surfaces, mesh.num_cells() + 1);

  std::string text;
  append_header(text, mesh, volumes, surfaces);
  append_nodes(text, mesh, volumes);
  std::vector<msh::ElementGroup> groups;
  for (const Entity& entity : surfaces) groups.push_back({2, entity.tag, entity.elements});
  for (const Entity& entity : volumes) groups.push_back({3, entity.tag, entity.elements});
  msh::append_elements(text, groups);
  write_text_file(path, text);
}

}  // namespace volmesh
