#include "golden_summary.hpp"

#include <bit>
#include <cmath>
#include <cstdio>
#include <map>
#include <span>
#include <variant>

#include "volmesh/core/validity.hpp"
#include "volmesh/quality/report.hpp"

namespace volmesh::golden {
namespace {

using nlohmann::json;

class Fnv1a64 {
 public:
  void word(std::uint64_t w) {
    for (int k = 0; k < 8; ++k) {
      hash_ ^= (w >> (8 * k)) & 0xffu;
      hash_ *= kPrime;
    }
  }
  template <class T>
  void integers(std::span<const T> values) {
    word(values.size());
    for (const T v : values) word(static_cast<std::uint64_t>(static_cast<std::int64_t>(v)));
  }
  void text(const std::string& s) {
    word(s.size());
    for (const char ch : s) word(static_cast<unsigned char>(ch));
  }
  std::string hex() const {
    char out[19];
    std::snprintf(out, sizeof out, "0x%016llx", static_cast<unsigned long long>(hash_));
    return out;
  }

 private:
  static constexpr std::uint64_t kPrime = 0x100000001b3u;
  std::uint64_t hash_ = 0xcbf29ce484222325u;  // the offset basis
};

json mesh_summary(const PolyMesh& mesh) {
  const ValidityReport v = check_validity(mesh);
  json volume = json::object(), cells = json::object();
  for (const auto& [region, x] : v.region_volume) volume[std::to_string(region)] = x;
  std::map<Index, Index> count;
  for (const Index r : mesh.cell_region) ++count[r];
  for (const auto& [region, n] : count) cells[std::to_string(region)] = n;
  return {{"cells", mesh.num_cells()},
          {"faces", mesh.num_faces()},
          {"points", mesh.num_points()},
          {"boundary_faces", v.boundary_faces},
          {"tags", mesh.tag_names},
          {"canonical_fnv1a64", canonical_hash(mesh)},
          {"valid", v.valid()},
          {"total_volume", v.total_volume},
          {"region_volume", volume},
          {"region_cells", cells}};
}

json quality_summary(const PolyMesh& mesh) {
  const QualityReport q = mesh_quality(mesh);
  json j = {{"hexes", q.hexes},
            {"tets", q.tets},
            {"polyhedra", q.polyhedra},
            {"non_positive_cells", q.non_positive_cells},
            {"severely_non_orthogonal_faces", q.severely_non_orthogonal_faces},
            {"highly_skewed_faces", q.highly_skewed_faces},
            {"non_orthogonality_errors", q.non_orthogonality_errors},
            {"inverted_face_pyramids", q.inverted_face_pyramids},
            {"min_cell_volume", q.min_volume},
            {"max_neighbour_volume_ratio", q.max_neighbour_volume_ratio}};
  for (const MetricSummary& m : q.metrics)
    if (m.count > 0) j[m.name] = {{"count", m.count}, {"min", m.min}, {"max", m.max}, {"mean", m.mean}};
  return j;
}

json solve_summary(const GoldenCase& c, const fem::ScalarSolution& s) {
  json j = {{"problem", c.problem},
            {"space", case_space(c)},
            {"dofs", s.dofs},
            {"unknowns", s.solve.unknowns},
            {"method", s.solve.method},
            {"iterations", s.solve.iterations}};
  if (s.errors) j["errors"] = {{"l2", s.errors->l2}, {"linf", s.errors->linf}, {"h1", s.errors->h1}};
  return j;
}

// Leaves of the summary by their dotted path.
void flatten(const json& j, const std::string& path, std::map<std::string, json>& out) {
  if (j.is_object() && !j.empty()) {
    for (const auto& [key, value] : j.items()) flatten(value, path.empty() ? key : path + "." + key, out);
  } else {
    out[path] = j;
  }
}

bool same(const json& a, const json& b) {
  if (a.is_number_float() || b.is_number_float()) {
    if (!a.is_number() || !b.is_number()) return false;
    const double x = a.get<double>(), y = b.get<double>();
    return std::abs(x - y) <= kRelativeTolerance * std::max(std::abs(x), std::abs(y)) + kAbsoluteFloor;
  }
  return a == b;
}

std::string shown(const json& j) {
  if (!j.is_number_float()) return j.dump();
  char out[32];
  std::snprintf(out, sizeof out, "%.17g", j.get<double>());
  return out;
}

std::string relative_change(double before, double after) {
  char out[32];
  std::snprintf(out, sizeof out, "%+.3e", after / before - 1.0);
  return out;
}

}  // namespace

std::string canonical_hash(const PolyMesh& mesh) {
  Fnv1a64 h;
  h.word(mesh.points.size());
  for (const Vec3& p : mesh.points)
    for (int a = 0; a < 3; ++a) h.word(std::bit_cast<std::uint64_t>(p[a]));
  for (const std::vector<Index>* a : {&mesh.face_offsets, &mesh.face_vertices, &mesh.owner, &mesh.neighbour,
                                      &mesh.face_tag, &mesh.cell_region})
    h.integers(std::span<const Index>(*a));
  h.word(mesh.tag_names.size());
  for (const std::string& name : mesh.tag_names) h.text(name);
  return h.hex();
}

json case_summary(const GoldenCase& c, const PolyMesh& mesh, const fem::ScalarSolution* solution) {
  json options = json::object();
  for (const auto& [name, value] : c.options)
    std::visit([&options, &name](const auto& v) { options[name] = v; }, value);
  json j = {{"case", c.name},
            {"method", c.method},
            {"domain", c.domain},
            {"options", options},
            {"mesh", mesh_summary(mesh)},
            {"quality", quality_summary(mesh)}};
  if (c.level) j["level"] = *c.level;
  if (c.size) j["size"] = *c.size;
  if (solution) j["solve"] = solve_summary(c, *solution);
  return j;
}

std::vector<std::string> moved_fields(const json& stored, const json& now) {
  std::map<std::string, json> before, after;
  flatten(stored, "", before);
  flatten(now, "", after);
  std::vector<std::string> moved;
  for (const auto& [path, value] : before) {
    const auto it = after.find(path);
    if (it == after.end()) moved.push_back(path + ": " + shown(value) + " -> (gone)");
    else if (!same(value, it->second)) {
      std::string line = path + ": " + shown(value) + " -> " + shown(it->second);
      if (value.is_number() && it->second.is_number() && value.get<double>() != 0.0)
        line += " (relative " + relative_change(value.get<double>(), it->second.get<double>()) + ")";
      moved.push_back(std::move(line));
    }
  }
  for (const auto& [path, value] : after)
    if (!before.contains(path)) moved.push_back(path + ": (new) -> " + shown(value));
  return moved;
}

}  // namespace volmesh::golden
