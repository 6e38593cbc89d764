// PVTU input: the summary file's piece names, and the pieces stitched into one mesh by their
// global point and cell ids (the pieces themselves are read by vtu_reader.cpp).
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>

#include "cell_list_soup.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/partitioned_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

std::string xml_unescape(std::string_view text) {
  static const std::pair<std::string_view, char> kEntities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    bool replaced = false;
    for (const auto& [entity, ch] : kEntities)
      if (text.substr(i).starts_with(entity)) {
        out += ch;
        i += entity.size() - 1;
        replaced = true;
        break;
      }
    if (!replaced) out += text[i];
  }
  return out;
}

}  // namespace

std::vector<fs::path> pvtu_piece_files(const fs::path& pvtu) {
  const std::string source = pvtu.string();
  std::ifstream in(pvtu);
  if (!in) throw InputError(source + ": cannot open (no such file, or not readable)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (text.find("type=\"PUnstructuredGrid\"") == std::string::npos)
    throw InputError(source + ": not a PVTU file (no VTKFile of type PUnstructuredGrid)");
  std::vector<fs::path> files;
  constexpr std::string_view kPiece = "<Piece", kSource = "Source=\"";
  for (std::size_t at = text.find(kPiece); at != std::string::npos;
       at = text.find(kPiece, at + 1)) {
    const std::size_t end = text.find('>', at);
    const std::size_t name = text.find(kSource, at);
    if (end == std::string::npos || name == std::string::npos || name > end)
      throw InputError(source + ": piece " + std::to_string(files.size()) + " has no Source");
    const std::size_t first = name + kSource.size(), last = text.find('"', first);
    if (last == std::string::npos || last > end)
      throw InputError(source + ": piece " + std::to_string(files.size()) + " has no Source");
    const fs::path file = xml_unescape(std::string_view(text).substr(first, last - first));
    files.push_back(file.is_absolute() ? file : pvtu.parent_path() / file);
  }
  if (files.empty()) throw InputError(source + ": names no piece");
  return files;
}

PolyMesh stitch_pieces(std::span<const CellList> pieces, const std::string& source,
                       std::vector<Index>* cell_part) {
  const auto fail = [&source](const std::string& what) { throw InputError(source + ": " + what); };
  Index num_points = 0, num_cells = 0;
  for (const CellList& p : pieces) {
    for (Index id : p.point_ids) num_points = std::max(num_points, id + 1);
    num_cells += static_cast<Index>(p.cell_ids.size());
  }
  // Each point from the first piece holding it; the others must agree.
  std::vector<Vec3> points(num_points);
  std::vector<Index> point_piece(num_points, kNoIndex);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t p = 0; p < pieces[i].points.size(); ++p) {
      const Index id = pieces[i].point_ids[p];
      if (point_piece[id] == kNoIndex) {
        point_piece[id] = static_cast<Index>(i);
        points[id] = pieces[i].points[p];
      } else if (points[id] != pieces[i].points[p]) {
        fail("pieces " + std::to_string(point_piece[id]) + " and " + std::to_string(i) +
             " put point " + std::to_string(id) + " at different places (pieces of different meshes?)");
      }
    }
  for (Index id = 0; id < num_points; ++id)
    if (point_piece[id] == kNoIndex)
      fail("point id " + std::to_string(id) + " is in no piece (pieces missing, or of different meshes)");
  // Each cell id in exactly one piece.
  std::vector<std::pair<Index, Index>> cell_at(num_cells, {kNoIndex, kNoIndex});
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t c = 0; c < pieces[i].cell_ids.size(); ++c) {
      const Index id = pieces[i].cell_ids[c];
      if (id >= num_cells)
        fail("piece " + std::to_string(i) + " has cell id " + std::to_string(id) +
             ", and the pieces hold " + std::to_string(num_cells) + " cells (pieces missing, or of different meshes)");
      if (cell_at[id].first != kNoIndex)
        fail("cell id " + std::to_string(id) + " is in pieces " + std::to_string(cell_at[id].first) +
             " and " + std::to_string(i) + " (pieces of different partitions?)");
      cell_at[id] = {static_cast<Index>(i), static_cast<Index>(c)};
    }

  CellSoup soup(source);
  soup.points = std::move(points);
  std::map<std::string, Index> tag_of_name;
  std::vector<std::vector<Index>> piece_tags(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (const std::string& name : pieces[i].tag_names) {
      const auto [it, added] = tag_of_name.emplace(name, static_cast<Index>(soup.tag_names.size()));
      if (added) soup.tag_names.push_back(name);
      piece_tags[i].push_back(it->second);
    }
  if (cell_part) cell_part->resize(num_cells);
  for (Index id = 0; id < num_cells; ++id) {
    const auto [i, c] = cell_at[id];
    detail::add_cell(pieces[i], c, [&](Index p) { return pieces[i].point_ids[p]; }, soup);
    if (cell_part) (*cell_part)[id] = i;
  }
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t t = 0; t < pieces[i].tagged_tag.size(); ++t)
      detail::add_tagged_face(
          pieces[i], t, [&](Index p) { return pieces[i].point_ids[p]; },
          [&](Index tag) { return piece_tags[i][tag]; }, soup);
  PolyMesh mesh = cells_to_poly(std::move(soup));
  drop_unused_tags(mesh);  // the faces between parts are internal now
  return mesh;
}

PolyMesh read_pvtu(const fs::path& pvtu, std::vector<Index>* cell_part) {
  std::vector<CellList> pieces;
  for (const fs::path& file : pvtu_piece_files(pvtu)) pieces.push_back(read_vtu_piece(file));
  return stitch_pieces(pieces, pvtu.string(), cell_part);
}

}  // namespace volmesh
