#include "volmesh/core/cell_soup.hpp"

#include <algorithm>
#include <array>
#include <compare>
#include <cstdint>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh {

namespace {

// Outward faces of VTK's wedge and pyramid in local corner numbers.
constexpr std::array<std::array<int, 4>, 5> kWedgeFaces{
    {{0, 1, 2, -1}, {3, 5, 4, -1}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}}};
constexpr std::array<std::array<int, 4>, 5> kPyramidFaces{
    {{0, 3, 2, 1}, {0, 1, 4, -1}, {1, 2, 4, -1}, {2, 3, 4, -1}, {3, 0, 4, -1}}};

// Signed volume of a cell whose faces are given as local loops (-1 ends a short loop).
template <typename Faces>
double local_volume(const std::vector<Vec3>& points, std::span<const Index> corners,
                    const Faces& faces) {
  const Vec3& apex = points[corners[0]];
  double volume = 0.0;
  for (const auto& face : faces) {
    const int n =
        face.back() < 0 ? static_cast<int>(face.size()) - 1 : static_cast<int>(face.size());
    for (int i = 1; i + 1 < n; ++i)
      volume += tet_volume(apex, points[corners[face[0]]], points[corners[face[i]]],
                           points[corners[face[i + 1]]]);
  }
  return volume;
}

template <typename Faces>
void add_local_faces(CellSoup& soup, std::span<const Index> corners, const Faces& faces,
                     bool reverse) {
  for (const auto& face : faces) {
    std::array<Index, 4> loop{};
    std::size_t n = 0;
    for (int local : face)
      if (local >= 0) loop[n++] = corners[local];
    if (reverse) std::reverse(loop.begin(), loop.begin() + n);
    soup.add_face({loop.data(), n});
  }
}

void append_loop(std::vector<Index>& offsets, std::vector<Index>& vertices,
                 std::span<const Index> loop, const std::string& source) {
  if (vertices.size() + loop.size() > static_cast<std::size_t>(kMaxIndex))
    throw InputError(source + ": mesh too large: more than 2^31-1 face vertices (32-bit indices)");
  vertices.insert(vertices.end(), loop.begin(), loop.end());
  offsets.push_back(static_cast<Index>(vertices.size()));
}

}  // namespace

void CellSoup::add_face(std::span<const Index> loop) {
  append_loop(face_offsets_, face_vertices_, loop, source_);
}

void CellSoup::end_cell(Index region) {
  cell_region_.push_back(region);
  cell_faces_.push_back(static_cast<Index>(face_offsets_.size()) - 1);
}

void CellSoup::add_cell(LinearCell kind, std::span<const Index> corners, Index region) {
  switch (kind) {
    case LinearCell::Tetrahedron: add_local_faces(*this, corners, kTetFaces, false); break;
    case LinearCell::Hexahedron: add_local_faces(*this, corners, kHexFaces, false); break;
    case LinearCell::Wedge:
      // VTK documents (0,1,2) as pointing away from (3,4,5), Gmsh's reference prism the
      // other way, and files in the wild use both: wedges are oriented by their volume.
      add_local_faces(*this, corners, kWedgeFaces,
                      local_volume(points, corners, kWedgeFaces) < 0.0);
      break;
    case LinearCell::Pyramid: add_local_faces(*this, corners, kPyramidFaces, false); break;
  }
  end_cell(region);
}

void CellSoup::add_tagged_face(std::span<const Index> loop, Index tag) {
  append_loop(tagged_offsets_, tagged_vertices_, loop, source_);
  tagged_tag_.push_back(tag);
}

namespace {

// True when b runs through a's vertices in the opposite cyclic direction.
bool opposite_loops(std::span<const Index> a, std::span<const Index> b) {
  const std::size_t n = a.size();
  if (b.size() != n) return false;
  const std::size_t start = std::find(b.begin(), b.end(), a[0]) - b.begin();
  for (std::size_t k = 0; k < n; ++k)
    if (b[(start + n - k) % n] != a[k]) return false;
  return true;
}

// Face loops in CSR form with, for each, its vertex set (sorted loop) as matching key.
struct FaceKeys {
  const std::vector<Index>& offsets;
  std::vector<Index> keys;

  std::span<const Index> key(Index f) const {
    return {keys.data() + offsets[f], static_cast<std::size_t>(offsets[f + 1] - offsets[f])};
  }
  // Orders by size, then vertices; equal for faces with the same vertex set.
  std::strong_ordering compare(Index a, Index b) const {
    const auto ka = key(a), kb = key(b);
    if (ka.size() != kb.size()) return ka.size() <=> kb.size();
    return std::lexicographical_compare_three_way(ka.begin(), ka.end(), kb.begin(), kb.end());
  }
};

// Face indices sorted by vertex set, ties by index: each group of equal faces lists the cell
// faces in cell order, then the tagged faces. The sort runs on the three smallest vertices
// and the size packed in two words, comparing whole keys only when those agree.
std::vector<Index> sorted_by_vertex_set(const FaceKeys& faces) {
  struct Record {
    std::uint64_t first, second;
    Index face;
  };
  std::vector<Record> records(faces.offsets.size() - 1);
  for (std::size_t f = 0; f < records.size(); ++f) {
    const auto k = faces.key(static_cast<Index>(f));
    records[f] = {std::uint64_t(std::uint32_t(k[0])) << 32 | std::uint32_t(k[1]),
                  std::uint64_t(std::uint32_t(k[2])) << 32 | k.size(), static_cast<Index>(f)};
  }
  std::sort(records.begin(), records.end(), [&](const Record& a, const Record& b) {
    if (a.first != b.first) return a.first < b.first;
    if (a.second != b.second) return a.second < b.second;
    const auto c = faces.compare(a.face, b.face);
    return c != 0 ? c < 0 : a.face < b.face;
  });
  std::vector<Index> order(records.size());
  for (std::size_t i = 0; i < records.size(); ++i) order[i] = records[i].face;
  return order;
}

}  // namespace

PolyMesh cells_to_poly(CellSoup soup) {
  const std::string& source = soup.source_;
  const Index num_cell_faces = soup.cell_faces_.back();
  for (std::size_t t = 0; t < soup.tagged_tag_.size(); ++t)
    append_loop(soup.face_offsets_, soup.face_vertices_,
                std::span(soup.tagged_vertices_)
                    .subspan(soup.tagged_offsets_[t],
                             soup.tagged_offsets_[t + 1] - soup.tagged_offsets_[t]),
                source);
  const std::vector<Index>& offsets = soup.face_offsets_;
  const auto loop = [&](Index f) {
    return std::span<const Index>(soup.face_vertices_).subspan(offsets[f], offsets[f + 1] - offsets[f]);
  };

  std::vector<Index> cell_of(num_cell_faces);  // the cell of each cell face
  for (Index c = 0; c < soup.num_cells(); ++c)
    std::fill(cell_of.begin() + soup.cell_faces_[c], cell_of.begin() + soup.cell_faces_[c + 1], c);

  FaceKeys faces{offsets, soup.face_vertices_};
  for (std::size_t f = 0; f + 1 < offsets.size(); ++f) {
    if (offsets[f + 1] - offsets[f] < 3) {
      const Index i = static_cast<Index>(f);
      throw InputError(source + ": " +
                       (i < num_cell_faces
                            ? "cell " + std::to_string(cell_of[i])
                            : "boundary face " + std::to_string(i - num_cell_faces)) +
                       ": face with fewer than 3 vertices");
    }
    std::sort(faces.keys.begin() + offsets[f], faces.keys.begin() + offsets[f + 1]);
  }
  const std::vector<Index> order = sorted_by_vertex_set(faces);

  // For the first cell face of each group: the other cell and the boundary tag.
  std::vector<Index> first(num_cell_faces, kNoIndex), other(num_cell_faces, kNoIndex),
      tag(num_cell_faces, kNoIndex);
  std::pair<Index, Index> inverted_pair{kNoIndex, kNoIndex};
  PolyMesh mesh;
  mesh.tag_names = std::move(soup.tag_names);
  for (std::size_t begin = 0, end; begin < order.size(); begin = end) {
    end = begin + 1;
    while (end < order.size() && faces.compare(order[begin], order[end]) == 0) ++end;
    const Index head = order[begin];
    if (head >= num_cell_faces) continue;  // a tagged face that bounds no cell
    std::size_t cells = begin + 1;
    while (cells < end && order[cells] < num_cell_faces) ++cells;
    if (cells - begin > 2)
      throw InputError(source + ": cell " + std::to_string(cell_of[order[begin + 2]]) +
                       ": face shared with cells " + std::to_string(cell_of[head]) + " and " +
                       std::to_string(cell_of[order[begin + 1]]) +
                       " (a face bounds at most two cells)");
    for (std::size_t i = begin; i < cells; ++i) first[order[i]] = head;
    if (cells - begin == 2) {
      const Index second = order[begin + 1];
      other[head] = cell_of[second];
      if (other[head] == cell_of[head])
        throw InputError(source + ": cell " + std::to_string(cell_of[head]) +
                         ": the same face appears twice");
      // Two cells that see their shared face with the same orientation cannot both be
      // outward: one of them is inside out (a reversed element order). Reported after the
      // structural errors, which say more.
      if (inverted_pair.first == kNoIndex && !opposite_loops(loop(head), loop(second)))
        inverted_pair = {cell_of[head], other[head]};
    } else {
      tag[head] = cells < end ? soup.tagged_tag_[order[cells] - num_cell_faces]
                              : mesh.tag_index("boundary");
    }
  }

  if (inverted_pair.first != kNoIndex)
    throw InputError(source + ": cells " + std::to_string(inverted_pair.first) + " and " +
                     std::to_string(inverted_pair.second) +
                     " orient their shared face alike: one of them is inverted");

  // Faces in order of first use, oriented as their first cell has them.
  mesh.points = std::move(soup.points);
  mesh.cell_region = std::move(soup.cell_region_);
  mesh.face_vertices.reserve(offsets[num_cell_faces]);
  for (Index f = 0; f < num_cell_faces; ++f)
    if (first[f] == f)
      mesh.add_face(loop(f), cell_of[f], other[f], tag[f]);
  return mesh;
}

void drop_unused_tags(PolyMesh& mesh) {
  std::vector<Index> renumber(mesh.tag_names.size(), kNoIndex);
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.face_tag[f] >= 0) renumber[mesh.face_tag[f]] = 0;
  std::vector<std::string> kept;
  for (std::size_t t = 0; t < renumber.size(); ++t) {
    if (renumber[t] == kNoIndex) continue;
    renumber[t] = static_cast<Index>(kept.size());
    kept.push_back(std::move(mesh.tag_names[t]));
  }
  for (Index& t : mesh.face_tag)
    if (t >= 0) t = renumber[t];
  mesh.tag_names = std::move(kept);
}

}  // namespace volmesh
