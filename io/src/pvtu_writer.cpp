// PVTU output: the pieces through write_vtu, the summary file by hand. VTK's own parallel
// writer would run a second VTU writer over a pipeline that hands it one piece at a time;
// the summary is a dozen lines naming the pieces and the arrays write_vtu writes.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "atomic_output.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/partitioned_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

std::string xml_attribute(std::string_view text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

std::string piece_name(const std::string& stem, std::size_t i) {
  return stem + "_" + std::to_string(i) + ".vtu";
}

// An earlier run's pieces: <stem>_<digits>.vtu.
bool is_piece_name(const std::string& name, const std::string& stem) {
  const std::string prefix = stem + "_", suffix = ".vtu";
  if (name.size() <= prefix.size() + suffix.size() || !name.starts_with(prefix) ||
      !name.ends_with(suffix))
    return false;
  const std::string_view digits(name.data() + prefix.size(),
                                name.size() - prefix.size() - suffix.size());
  return std::all_of(digits.begin(), digits.end(),
                     [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)) != 0; });
}

void check_replaceable(const fs::path& dir, const std::string& stem, const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (!fs::is_directory(dir, ec))
    throw InputError(path.string() + ": " + dir.string() +
                     " exists and is not a directory; cannot write the pieces there");
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (!is_piece_name(entry.path().filename().string(), stem))
      throw InputError(path.string() + ": " + dir.string() + " holds " +
                       entry.path().filename().string() +
                       ", not a piece of this file; remove it or choose another name");
  if (ec)
    throw InputError(path.string() + ": cannot list " + dir.string() + " (" + ec.message() + ")");
}

// Names and components of the arrays of a piece, as write_vtu writes them: "region" and the
// integer cell arrays as Int32, the others as Float64.
std::string array_list(const MeshFields& fields) {
  std::string cells = "      <PDataArray type=\"Int32\" Name=\"region\"/>\n", points;
  for (const IntField& f : fields.cell_ints)
    cells += "      <PDataArray type=\"Int32\" Name=\"" + xml_attribute(f.name) + "\"/>\n";
  auto add = [](std::string& out, const Field& f) {
    out += "      <PDataArray type=\"Float64\" Name=\"" + xml_attribute(f.name) +
           "\" NumberOfComponents=\"" + std::to_string(f.components) + "\"/>\n";
  };
  for (const Field& f : fields.cell) add(cells, f);
  for (const Field& f : fields.point) add(points, f);
  return "    <PPointData>\n" + points + "    </PPointData>\n    <PCellData>\n" + cells +
         "    </PCellData>\n";
}

// The same arrays, by name and components, in the same order.
bool same_arrays(const MeshFields& a, const MeshFields& b) {
  auto names = [](const auto& fields) {
    std::vector<std::pair<std::string, int>> out;
    for (const auto& f : fields) {
      if constexpr (requires { f.components; })
        out.emplace_back(f.name, f.components);
      else
        out.emplace_back(f.name, 1);
    }
    return out;
  };
  return names(a.cell_ints) == names(b.cell_ints) && names(a.cell) == names(b.cell) &&
         names(a.point) == names(b.point);
}

std::string summary(const MeshFields& arrays, std::size_t pieces, const std::string& stem) {
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <PUnstructuredGrid GhostLevel=\"0\">\n";
  text += array_list(arrays);
  text +=
      "    <PPoints>\n"
      "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
      "    </PPoints>\n";
  for (std::size_t i = 0; i < pieces; ++i)
    text += "    <Piece Source=\"" + xml_attribute(stem + "/" + piece_name(stem, i)) + "\"/>\n";
  text += "  </PUnstructuredGrid>\n</VTKFile>\n";
  return text;
}

}  // namespace

PvtuSet::PvtuSet(const fs::path& path)
    : path_(path), stem_(path.stem().string()) {
  const fs::path dir = path.parent_path() / stem_;
  check_replaceable(dir, stem_, path);
  pieces_ = std::make_unique<AtomicOutput>(dir);
  summary_ = std::make_unique<AtomicOutput>(path);
  std::error_code ec;
  fs::create_directory(pieces_->temporary(), ec);
  if (ec)
    throw InputError(path.string() + ": cannot create a directory for the pieces (" + ec.message() +
                     ")");
}

PvtuSet::~PvtuSet() = default;

const fs::path& PvtuSet::pieces_directory() const { return pieces_->temporary(); }

void PvtuSet::commit(const MeshFields& arrays, std::size_t pieces) {
  {
    std::ofstream stream = summary_->open_stream();
    stream << summary(arrays, pieces, stem_);
    stream.close();
    if (!stream) throw InputError(path_.string() + ": write failed");
  }
  pieces_->commit();
  try {
    summary_->commit();
  } catch (const InputError&) {
    std::error_code ec;
    fs::remove_all(path_.parent_path() / stem_, ec);  // pieces without their summary are no result
    throw;
  }
}

void write_pvtu_piece(const MeshPiece& piece, std::size_t i, const fs::path& pieces_directory,
                      const fs::path& path) {
  const std::string stem = path.stem().string();
  try {
    write_vtu(piece.mesh, pieces_directory / piece_name(stem, i), piece.fields);
  } catch (const InputError& e) {  // name the piece where it was meant to go
    std::string what = e.what();
    const std::string temporary = pieces_directory.string();
    if (const auto at = what.find(temporary); at != std::string::npos)
      what.replace(at, temporary.size(), (path.parent_path() / stem).string());
    throw InputError(what);
  }
}

void write_pvtu(std::span<const MeshPiece> pieces, const fs::path& path) {
  if (pieces.empty()) throw InputError(path.string() + ": no pieces to write");
  for (std::size_t i = 1; i < pieces.size(); ++i)
    if (!same_arrays(pieces.front().fields, pieces[i].fields))
      throw InputError(path.string() + ": piece " + std::to_string(i) +
                       " carries other arrays than piece 0");
  PvtuSet set(path);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    write_pvtu_piece(pieces[i], i, set.pieces_directory(), path);
  set.commit(pieces.front().fields, pieces.size());
}

}  // namespace volmesh
