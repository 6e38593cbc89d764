#include "volmesh/core/validity.hpp"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>
#include <sstream>
#include <tuple>

#include "volmesh/core/geometry.hpp"

namespace volmesh {

namespace {

class Problems {
 public:
  Problems(ValidityReport& r, int max) : report_(r), max_(max) {}
  template <class... Args>
  void add(Index& counter, const Args&... parts) {
    ++counter;
    note(parts...);
  }
  template <class... Args>
  void note(const Args&... parts) {
    if (static_cast<int>(report_.problems.size()) >= max_) return;
    std::ostringstream os;
    (os << ... << parts);
    report_.problems.push_back(os.str());
  }

 private:
  ValidityReport& report_;
  int max_;
};

// Structural checks that must pass before any geometry is computed.
bool check_indices(const PolyMesh& m, ValidityReport& r, Problems& p) {
  const Index nf = m.num_faces(), nc = m.num_cells(), np = m.num_points();
  if (static_cast<Index>(m.face_offsets.size()) != nf + 1 ||
      static_cast<Index>(m.neighbour.size()) != nf ||
      static_cast<Index>(m.face_tag.size()) != nf || m.face_offsets.front() != 0 ||
      m.face_offsets.back() != static_cast<Index>(m.face_vertices.size())) {
    p.add(r.bad_indices, "face arrays have inconsistent sizes");
    return false;
  }
  for (Index f = 0; f < nf; ++f) {
    if (m.face_offsets[f + 1] < m.face_offsets[f]) {
      p.add(r.bad_indices, "face ", f, ": negative vertex count");
      return false;
    }
    for (Index v : m.face(f))
      if (v < 0 || v >= np) p.add(r.bad_indices, "face ", f, ": vertex ", v, " out of range");
    if (m.owner[f] < 0 || m.owner[f] >= nc)
      p.add(r.bad_indices, "face ", f, ": owner ", m.owner[f], " out of range");
    if (m.neighbour[f] < kNoIndex || m.neighbour[f] >= nc)
      p.add(r.bad_indices, "face ", f, ": neighbour ", m.neighbour[f], " out of range");
    if (m.neighbour[f] == m.owner[f])
      p.add(r.bad_face_order, "face ", f, ": owner and neighbour are both cell ", m.owner[f]);
    if (m.is_boundary(f) &&
        (m.face_tag[f] < 0 || m.face_tag[f] >= static_cast<Index>(m.tag_names.size())))
      p.add(r.bad_indices, "boundary face ", f, ": tag ", m.face_tag[f], " undefined");
  }
  return r.bad_indices == 0;
}

// Sum of +1 for a directed edge a->b with a<b, -1 for b->a; a closed oriented surface
// gives zero for every undirected edge.
struct EdgeUse {
  Index region, a, b;
  int dir;
  auto key() const { return std::tie(region, a, b); }
};

void add_loop_edges(std::span<const Index> loop, bool reversed, Index region,
                    std::vector<EdgeUse>& edges) {
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    Index a = loop[i], b = loop[(i + 1) % n];
    if (reversed) std::swap(a, b);
    edges.push_back(a < b ? EdgeUse{region, a, b, 1} : EdgeUse{region, b, a, -1});
  }
}

Index count_unmatched(std::vector<EdgeUse>& edges) {
  std::sort(edges.begin(), edges.end(),
            [](const EdgeUse& x, const EdgeUse& y) { return x.key() < y.key(); });
  Index unmatched = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    int sum = 0;
    while (j < edges.size() && edges[j].key() == edges[i].key()) sum += edges[j++].dir;
    if (sum != 0) ++unmatched;
    i = j;
  }
  return unmatched;
}

}  // namespace

ValidityReport check_validity(const PolyMesh& m, const ValidityOptions& opt) {
  ValidityReport r;
  Problems p(r, opt.max_messages);
  r.cells = m.num_cells();
  r.faces = m.num_faces();
  r.points = m.num_points();
  if (!check_indices(m, r, p)) return r;

  // Each face's vertices sorted, in one array laid out as the faces' (in parallel).
  std::vector<Index> sorted(m.face_vertices);
  tbb::parallel_for(Index{0}, m.num_faces(), [&](Index f) {
    std::sort(sorted.begin() + m.face_offsets[f], sorted.begin() + m.face_offsets[f + 1]);
  });
  const auto sorted_of = [&](Index f) {
    return std::span<const Index>(sorted.data() + m.face_offsets[f], sorted.data() + m.face_offsets[f + 1]);
  };
  std::vector<char> used(m.num_points(), 0);
  for (Index f = 0; f < m.num_faces(); ++f) {
    if (m.is_boundary(f)) ++r.boundary_faces;
    for (Index v : m.face(f)) used[v] = 1;
    const auto key = sorted_of(f);
    if (key.size() < 3 || std::adjacent_find(key.begin(), key.end()) != key.end())
      p.add(r.degenerate_faces, "face ", f, ": repeated vertex or fewer than 3 vertices");
  }
  r.unused_points = static_cast<Index>(std::count(used.begin(), used.end(), 0));

  // Duplicate faces: the same vertex set twice means a face shared by more than two cells.
  {
    std::vector<Index> order(m.num_faces());
    std::iota(order.begin(), order.end(), Index{0});
    tbb::parallel_sort(order.begin(), order.end(), [&](Index a, Index b) {
      const auto ka = sorted_of(a), kb = sorted_of(b);
      const auto c = std::lexicographical_compare_three_way(ka.begin(), ka.end(), kb.begin(), kb.end());
      return c != 0 ? c < 0 : a < b;
    });
    for (std::size_t i = 1; i < order.size(); ++i)
      if (std::ranges::equal(sorted_of(order[i]), sorted_of(order[i - 1])))
        p.add(r.duplicate_faces, "faces ", order[i - 1], " and ", order[i], " have the same vertices");
  }

  const CellFaces cf = build_cell_faces(m);
  const MeshGeometry g = mesh_geometry(m, cf);
  for (Index f = 0; f < m.num_faces(); ++f)
    if (flatness(m.points, m.face(f), g.faces[f].area_vector.norm()) <= opt.zero_area_tolerance)
      p.add(r.degenerate_faces, "face ", f, ": zero area (its vertices lie in a line)");

  r.min_cell_volume = m.num_cells() ? g.cells[0].volume : 0.0;
  r.max_cell_volume = r.min_cell_volume;
  // Per cell in parallel, reported in order.
  std::vector<double> closedness(m.num_cells());
  std::vector<Index> unmatched(m.num_cells());
  tbb::parallel_for(Index{0}, m.num_cells(), [&](Index c) {
    thread_local std::vector<EdgeUse> edges;
    Vec3 sum = Vec3::Zero();
    double total = 0.0;
    edges.clear();
    for (Index f : cf.of(c)) {
      const int s = face_sign(m, f, c);
      sum += s * g.faces[f].area_vector;
      total += g.faces[f].area_vector.norm();
      add_loop_edges(m.face(f), s < 0, 0, edges);
    }
    closedness[c] = total > 0.0 ? sum.norm() / total : 1.0;
    unmatched[c] = count_unmatched(edges);
  });
  for (Index c = 0; c < m.num_cells(); ++c) {
    const std::size_t faces = cf.of(c).size();
    r.max_closedness = std::max(r.max_closedness, closedness[c]);
    if (faces < 4 || closedness[c] > opt.closed_tolerance)
      p.add(r.open_cells, "cell ", c, ": not closed (", faces,
            " faces, |sum of face area vectors| / sum of areas = ", closedness[c], ")");
    if (const Index n = unmatched[c])
      p.add(r.unmatched_cell_edges, "cell ", c, ": ", n,
            " edges not matched by an opposite edge (a T-junction or a missing face)");
    const double v = g.cells[c].volume;
    if (!(v > 0.0)) p.add(r.non_positive_cells, "cell ", c, ": volume ", v);
    r.min_cell_volume = std::min(r.min_cell_volume, v);
    r.max_cell_volume = std::max(r.max_cell_volume, v);
    r.total_volume += v;
    r.region_volume[m.cell_region[c]] += v;
  }

  // Each region's boundary (outer boundary and interfaces) must be a closed surface.
  std::vector<EdgeUse> edges;
  for (Index f = 0; f < m.num_faces(); ++f) {
    const Index ro = m.cell_region[m.owner[f]];
    const Index rn = m.is_boundary(f) ? 0 : m.cell_region[m.neighbour[f]];
    if (ro == rn) continue;
    add_loop_edges(m.face(f), false, ro, edges);
    if (rn != 0) add_loop_edges(m.face(f), true, rn, edges);
  }
  r.open_region_boundary_edges = count_unmatched(edges);
  if (r.open_region_boundary_edges > 0)
    p.note(r.open_region_boundary_edges, " edges of region boundaries are not closed");
  return r;
}

}  // namespace volmesh
