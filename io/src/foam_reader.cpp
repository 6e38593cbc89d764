// OpenFOAM polyMesh reader (ASCII, plain or .gz): constant/polyMesh/{points, faces, owner,
// neighbour, boundary} and, when present, cellZones. Cells in a zone "region_<r>" (as
// write_foam names them) get region r, other zones the next free labels in file order, and
// cells in no zone one more label. One patch becomes one boundary tag.
//
// Binary files are refused with the command that converts them: their layout depends on the
// label and scalar sizes OpenFOAM was built with, which the file does not always say.
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <string_view>

#include "text_format.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

std::string read_maybe_gzipped(const fs::path& path) {
  gzFile in = gzopen(path.c_str(), "rb");  // reads plain files as they are
  if (!in) throw InputError(path.string() + ": cannot open");
  std::string text;
  char buffer[1 << 16];
  int n;
  while ((n = gzread(in, buffer, sizeof buffer)) > 0) text.append(buffer, static_cast<std::size_t>(n));
  const bool failed = n < 0;
  gzclose(in);
  if (failed) throw InputError(path.string() + ": cannot read (corrupt gzip data)");
  return text;
}

// Tokens of an OpenFOAM dictionary file: words and the punctuation ( ) { } ; as tokens of
// their own, comments skipped, with the line for error messages.
class FoamTokens {
 public:
  FoamTokens(std::string source, std::string text)
      : source_(std::move(source)), text_(std::move(text)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_ + ": line " + std::to_string(line_) + ": " + what);
  }

  std::string_view peek() {
    const std::size_t saved = pos_;
    const long saved_line = line_;
    const std::string_view t = next();
    pos_ = saved;
    line_ = saved_line;
    return t;
  }

  std::string_view next() {
    skip_space_and_comments();
    if (pos_ == text_.size()) return {};
    const std::size_t begin = pos_;
    if (is_punct(text_[pos_])) {
      ++pos_;
    } else {
      while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])) &&
             !is_punct(text_[pos_]) && text_[pos_] != '/')
        ++pos_;
      if (pos_ == begin) ++pos_;  // a lone '/' that starts no comment
    }
    return std::string_view(text_).substr(begin, pos_ - begin);
  }

  void expect(std::string_view token) {
    const std::string_view t = next();
    if (t != token)
      fail("expected '" + std::string(token) + "', found '" + shown(t) + "'");
  }

  long long integer(const char* what) {
    const std::string_view t = next();
    long long v = 0;
    if (t.empty() || !parse_number(t, v)) fail(std::string("expected ") + what + ", found '" + shown(t) + "'");
    return v;
  }

  double real() {
    const std::string_view t = next();
    double v = 0;
    if (t.empty() || !parse_number(t, v)) fail("expected a number, found '" + shown(t) + "'");
    return v;
  }

  // A list size, checked against the text left so that a corrupt count fails here.
  Index count(const char* what, std::size_t min_bytes) {
    const long long n = integer(what);
    if (n < 0 || n > kMaxIndex || static_cast<unsigned long long>(n) * min_bytes > text_.size() - pos_)
      fail(std::string("implausible ") + what + " " + std::to_string(n));
    return static_cast<Index>(n);
  }

  // Skips a value up to its ';' at nesting depth 0 (dictionary entries we do not need).
  void skip_value() {
    int depth = 0;
    for (std::string_view t = next();; t = next()) {
      if (t.empty()) fail("unexpected end of file");
      if (t == "(" || t == "{") ++depth;
      if (t == ")" || t == "}") --depth;
      if (depth == 0 && t == ";") return;
      if (depth < 0) fail("unbalanced brackets");
    }
  }

  // The FoamFile header; returns its entries.
  std::map<std::string, std::string, std::less<>> header() {
    std::map<std::string, std::string, std::less<>> entries;
    if (next() != "FoamFile") fail("no FoamFile header");
    expect("{");
    for (std::string_view key = next(); key != "}"; key = next()) {
      if (key.empty()) fail("unterminated FoamFile header");
      std::string value;
      for (std::string_view t = next(); t != ";"; t = next()) {
        if (t.empty() || t == "}") fail("unterminated entry '" + std::string(key) + "'");
        value += std::string(t);
      }
      entries[std::string(key)] = value;
    }
    return entries;
  }

 private:
  static bool is_punct(char c) { return c == '(' || c == ')' || c == '{' || c == '}' || c == ';'; }
  static std::string shown(std::string_view t) { return std::string(t.substr(0, 40)); }

  void skip_space_and_comments() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else if (text_.compare(pos_, 2, "//") == 0) {
        pos_ = std::min(text_.find('\n', pos_), text_.size());
      } else if (text_.compare(pos_, 2, "/*") == 0) {
        const std::size_t end = text_.find("*/", pos_ + 2);
        if (end == std::string::npos) fail("unterminated comment");
        line_ += std::count(text_.begin() + static_cast<std::ptrdiff_t>(pos_),
                            text_.begin() + static_cast<std::ptrdiff_t>(end), '\n');
        pos_ = end + 2;
      } else {
        return;
      }
    }
  }

  std::string source_, text_;
  std::size_t pos_ = 0;
  long line_ = 1;
};

// One polyMesh file (or its .gz) opened past its header.
struct FoamFile {
  FoamTokens tokens;
  std::string cls;
};

FoamFile open_foam_file(const fs::path& dir, const std::string& name) {
  fs::path path = dir / name;
  if (!fs::exists(path) && fs::exists(dir / (name + ".gz"))) path = dir / (name + ".gz");
  if (!fs::is_regular_file(path)) throw InputError(path.string() + ": no such file");
  FoamTokens tokens(path.string(), read_maybe_gzipped(path));
  const auto header = tokens.header();
  const auto format = header.find("format");
  if (format != header.end() && format->second != "ascii")
    tokens.fail("format " + format->second +
                " is not supported; convert the case with `foamFormatConvert` after setting "
                "writeFormat ascii in system/controlDict");
  const auto cls = header.find("class");
  return {std::move(tokens), cls == header.end() ? std::string() : cls->second};
}

std::vector<Index> read_labels(FoamTokens& t, const char* what, Index limit) {
  const Index n = t.count(what, 1);
  std::vector<Index> labels(static_cast<std::size_t>(n));
  if (t.peek() == "{") {  // uniform list: N{value}
    t.next();
    const long long v = t.integer("a label");
    t.expect("}");
    std::fill(labels.begin(), labels.end(), static_cast<Index>(v));
  } else {
    t.expect("(");
    for (auto& l : labels) l = static_cast<Index>(t.integer("a label"));
    t.expect(")");
  }
  for (const Index l : labels)
    if (l < 0 || l >= limit)
      t.fail(std::string(what) + " holds " + std::to_string(l) + ", out of range [0, " +
             std::to_string(limit) + ")");
  return labels;
}

std::vector<Vec3> read_points(const fs::path& dir) {
  auto file = open_foam_file(dir, "points");
  FoamTokens& t = file.tokens;
  std::vector<Vec3> points(static_cast<std::size_t>(t.count("point count", 7)));
  t.expect("(");
  for (auto& p : points) {
    t.expect("(");
    for (int k = 0; k < 3; ++k) p[k] = t.real();
    t.expect(")");
  }
  t.expect(")");
  return points;
}

void read_faces(const fs::path& dir, Index num_points, PolyMesh& mesh) {
  auto file = open_foam_file(dir, "faces");
  FoamTokens& t = file.tokens;
  if (file.cls == "faceCompactList") {
    const std::vector<Index> offsets = read_labels(t, "face offset", kMaxIndex);
    mesh.face_vertices = read_labels(t, "face vertex", num_points);
    if (offsets.empty() || offsets.front() != 0 ||
        offsets.back() != static_cast<Index>(mesh.face_vertices.size()) ||
        !std::is_sorted(offsets.begin(), offsets.end()))
      t.fail("face offsets do not match the face vertices");
    mesh.face_offsets = offsets;
  } else {
    const Index n = t.count("face count", 4);
    t.expect("(");
    mesh.face_offsets.assign(1, 0);
    mesh.face_offsets.reserve(static_cast<std::size_t>(n) + 1);
    for (Index f = 0; f < n; ++f) {
      const std::vector<Index> face = read_labels(t, "face vertex", num_points);
      mesh.face_vertices.insert(mesh.face_vertices.end(), face.begin(), face.end());
      mesh.face_offsets.push_back(static_cast<Index>(mesh.face_vertices.size()));
    }
    t.expect(")");
  }
  for (std::size_t f = 0; f + 1 < mesh.face_offsets.size(); ++f)
    if (mesh.face_offsets[f + 1] - mesh.face_offsets[f] < 3)
      t.fail("face " + std::to_string(f) + " has fewer than 3 vertices");
}

struct Patch {
  std::string name;
  Index size = -1, start = -1;
};

std::vector<Patch> read_boundary(const fs::path& dir) {
  auto file = open_foam_file(dir, "boundary");
  FoamTokens& t = file.tokens;
  std::vector<Patch> patches(static_cast<std::size_t>(t.count("patch count", 8)));
  t.expect("(");
  for (auto& patch : patches) {
    patch.name = std::string(t.next());
    t.expect("{");
    for (std::string_view key = t.next(); key != "}"; key = t.next()) {
      if (key.empty()) t.fail("unterminated patch '" + patch.name + "'");
      if (key == "nFaces" || key == "startFace") {
        (key == "nFaces" ? patch.size : patch.start) = static_cast<Index>(t.integer("a face count"));
        t.expect(";");
      } else {
        t.skip_value();
      }
    }
    if (patch.size < 0 || patch.start < 0) t.fail("patch '" + patch.name + "' lacks nFaces or startFace");
  }
  t.expect(")");
  return patches;
}

// Region per cell from the cellZones file, if any.
std::vector<Index> read_regions(const fs::path& dir, Index num_cells) {
  std::vector<Index> region(static_cast<std::size_t>(num_cells), 0);
  if (!fs::exists(dir / "cellZones") && !fs::exists(dir / "cellZones.gz")) {
    std::fill(region.begin(), region.end(), 1);
    return region;
  }
  auto file = open_foam_file(dir, "cellZones");
  FoamTokens& t = file.tokens;
  const Index zones = t.count("zone count", 8);
  t.expect("(");
  std::vector<std::pair<Index, std::vector<Index>>> labelled;  // label (0: not yet), cells
  for (Index z = 0; z < zones; ++z) {
    const std::string name(t.next());
    Index label = 0;
    if (name.starts_with("region_") && name.size() > 7 &&
        std::all_of(name.begin() + 7, name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }) &&
        name.size() < 16)
      label = static_cast<Index>(std::stol(name.substr(7)));
    std::vector<Index> cells;
    t.expect("{");
    for (std::string_view key = t.next(); key != "}"; key = t.next()) {
      if (key.empty()) t.fail("unterminated cell zone '" + name + "'");
      if (key == "cellLabels") {
        if (t.peek() == "List<label>") t.next();
        cells = read_labels(t, "cell label", num_cells);
        t.expect(";");
      } else {
        t.skip_value();
      }
    }
    labelled.emplace_back(label, std::move(cells));
  }
  t.expect(")");
  Index next = 1;
  for (const auto& [label, cells] : labelled) next = std::max(next, label + 1);
  for (auto& [label, cells] : labelled) {
    if (label == 0) label = next++;
    for (const Index c : cells) region[c] = label;
  }
  for (auto& r : region)
    if (r == 0) r = next;
  return region;
}

fs::path foam_case_dir(const fs::path& path) {
  fs::path p = path;
  if (p.filename().empty()) p = p.parent_path();
  return fs::is_regular_file(p) ? p.parent_path() : p;  // ParaView's case/case.foam marker
}

}  // namespace

PolyMesh read_foam(const fs::path& path) {
  const fs::path dir = foam_case_dir(path) / "constant" / "polyMesh";
  if (!fs::is_directory(dir)) throw InputError(path.string() + ": no constant/polyMesh directory");
  PolyMesh mesh;
  mesh.points = read_points(dir);
  read_faces(dir, mesh.num_points(), mesh);
  const Index num_faces = static_cast<Index>(mesh.face_offsets.size()) - 1;

  auto owner_file = open_foam_file(dir, "owner");
  mesh.owner = read_labels(owner_file.tokens, "owner", kMaxIndex);
  if (static_cast<Index>(mesh.owner.size()) != num_faces)
    owner_file.tokens.fail("has " + std::to_string(mesh.owner.size()) + " owners for " +
                           std::to_string(num_faces) + " faces");
  auto neighbour_file = open_foam_file(dir, "neighbour");
  std::vector<Index> neighbour = read_labels(neighbour_file.tokens, "neighbour", kMaxIndex);
  const Index internal = static_cast<Index>(neighbour.size());
  if (internal > num_faces) neighbour_file.tokens.fail("more neighbours than faces");

  Index num_cells = 0;
  for (const Index c : mesh.owner) num_cells = std::max(num_cells, c + 1);
  for (const Index c : neighbour) num_cells = std::max(num_cells, c + 1);

  const std::vector<Patch> patches = read_boundary(dir);
  mesh.face_tag.assign(static_cast<std::size_t>(num_faces), kNoIndex);
  Index expected_start = internal;
  for (const Patch& patch : patches) {
    if (patch.start != expected_start || patch.start + patch.size > num_faces)
      throw InputError((dir / "boundary").string() + ": patch '" + patch.name +
                       "' does not continue the faces where the previous one ends (startFace " +
                       std::to_string(patch.start) + ", expected " + std::to_string(expected_start) + ")");
    const Index tag = mesh.tag_index(patch.name);
    std::fill(mesh.face_tag.begin() + patch.start, mesh.face_tag.begin() + patch.start + patch.size, tag);
    expected_start += patch.size;
  }
  if (expected_start != num_faces)
    throw InputError((dir / "boundary").string() + ": the patches cover faces up to " +
                     std::to_string(expected_start) + " of " + std::to_string(num_faces));

  std::vector<Index> faces_per_cell(static_cast<std::size_t>(num_cells), 0);
  for (const Index c : mesh.owner) ++faces_per_cell[c];
  for (const Index c : neighbour) ++faces_per_cell[c];
  for (Index c = 0; c < num_cells; ++c)
    if (faces_per_cell[c] < 4)
      throw InputError(dir.string() + ": cell " + std::to_string(c) + " has fewer than 4 faces");

  neighbour.resize(static_cast<std::size_t>(num_faces), kNoIndex);
  mesh.neighbour = std::move(neighbour);
  mesh.cell_region = read_regions(dir, num_cells);
  return mesh;
}

}  // namespace volmesh
