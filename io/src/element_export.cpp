#include "element_export.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <utility>

#include "atomic_output.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {

void write_text_file(const std::filesystem::path& path, std::string_view text) {
  AtomicOutput output(path);
  {
    std::ofstream stream = output.open_stream();
    stream.write(text.data(), static_cast<std::streamsize>(text.size()));
    stream.close();
    if (!stream) throw InputError(path.string() + ": write failed");
  }
  output.commit();
}

std::vector<CellCorners> classify_elements(const PolyMesh& mesh, const CellFaces& cell_faces,
                                           const std::filesystem::path& file,
                                           std::string_view format) {
  std::vector<CellCorners> cells(mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    cells[c] = classify_cell(mesh, cell_faces, c);
    if (cells[c].shape == CellShape::Polyhedron)
      throw InputError(file.string() + ": cell " + std::to_string(c) + " is a polyhedron with " +
                       std::to_string(cell_faces.of(c).size()) + " faces; " + std::string(format) +
                       " output takes tetrahedra and hexahedra only (write it with --decompose "
                       "tets)");
  }
  return cells;
}

std::vector<std::vector<Index>> boundary_faces_by_tag(const PolyMesh& mesh,
                                                      const std::filesystem::path& file) {
  const auto tags = static_cast<Index>(mesh.tag_names.size());
  std::vector<std::vector<Index>> by_tag(tags);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f)) continue;
    const Index t = mesh.face_tag[f];
    if (t < 0 || t >= tags)
      throw InputError(file.string() + ": boundary face " + std::to_string(f) + " has tag " +
                       std::to_string(t) + ", out of range (" + std::to_string(tags) + " tags)");
    by_tag[t].push_back(f);
  }
  return by_tag;
}

std::map<Index, std::vector<Index>> cells_by_region(const PolyMesh& mesh) {
  std::map<Index, std::vector<Index>> cells;
  for (Index c = 0; c < mesh.num_cells(); ++c) cells[mesh.cell_region[c]].push_back(c);
  return cells;
}

std::vector<RegionInterface> region_interfaces(const PolyMesh& mesh) {
  std::map<std::pair<Index, Index>, std::vector<Index>> faces;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.is_boundary(f)) continue;
    const Index a = mesh.cell_region[mesh.owner[f]], b = mesh.cell_region[mesh.neighbour[f]];
    if (a != b) faces[std::minmax(a, b)].push_back(f);
  }
  std::vector<RegionInterface> out;
  for (auto& [pair, list] : faces) out.push_back({pair.first, pair.second, std::move(list)});
  return out;
}

std::vector<std::string> export_names(const std::vector<std::string>& names) {
  // Plain ASCII tests: <cctype> depends on the locale.
  const auto letter = [](char ch) { return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z'); };
  const auto lower = [](std::string s) {
    for (char& ch : s)
      if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
    return s;
  };
  std::set<std::string> used;  // lower case
  std::vector<std::string> out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::string name;
    for (char ch : names[i]) name += letter(ch) || (ch >= '0' && ch <= '9') ? ch : '_';
    if (name.empty() || !letter(name[0])) name = "tag_" + name;
    name.resize(std::min<std::size_t>(name.size(), 64));
    while (!used.insert(lower(name)).second) name += "_" + std::to_string(i);
    out.push_back(std::move(name));
  }
  return out;
}

}  // namespace volmesh
