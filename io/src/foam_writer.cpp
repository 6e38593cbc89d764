// OpenFOAM case: constant/polyMesh/{points,faces,owner,neighbour,boundary,cellZones} in ASCII,
// a minimal system/{controlDict,fvSchemes,fvSolution} so that the OpenFOAM utilities run, and
// an empty <case>.foam marker that ParaView opens.
//
// Faces: internal faces first in upper-triangular order (owner < neighbour, sorted by owner,
// then neighbour), a face being reversed where its owner and neighbour swap so that it still
// points from owner to neighbour; then the boundary faces, one patch per boundary tag that
// has faces (type patch, named by export_names()). cellZones: one zone "region_<r>" per region.
// Coordinates are written in the shortest form that reads back to the same double.
//
// A new case directory is written whole under a temporary name and renamed at the end. In an
// existing directory only constant/polyMesh is replaced (the same way), and the system files
// and the marker are added where missing, so that a user's fields and settings survive.
#include <algorithm>
#include <system_error>
#include <tuple>

#include "atomic_output.hpp"
#include "element_export.hpp"
#include "text_format.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;

namespace {

std::string foam_header(const char* cls, const char* location, const char* object,
                        const std::string& note = {}) {
  std::string h =
      "/*--------------------------------*- C++ -*----------------------------------*\\\n"
      "  Written by volmesh\n"
      "\\*---------------------------------------------------------------------------*/\n"
      "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       ";
  h += cls;
  h += ";\n";
  if (!note.empty()) h += "    note        \"" + note + "\";\n";
  h += "    location    \"";
  h += location;
  h += "\";\n    object      ";
  h += object;
  h += ";\n}\n// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n";
  return h;
}

constexpr const char* kPolyMesh = "constant/polyMesh";

// The faces in OpenFOAM order, each with the owner and neighbour it gets there.
struct FoamFaces {
  std::vector<Index> face;
  std::vector<Index> owner, neighbour;  // neighbour only for the internal faces
  std::vector<Index> patch_tag, patch_size;
};

FoamFaces foam_faces(const PolyMesh& mesh, const std::vector<std::vector<Index>>& by_tag) {
  FoamFaces out;
  std::vector<Index> internal;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (!mesh.is_boundary(f)) internal.push_back(f);
  const auto low = [&](Index f) { return std::min(mesh.owner[f], mesh.neighbour[f]); };
  const auto high = [&](Index f) { return std::max(mesh.owner[f], mesh.neighbour[f]); };
  std::sort(internal.begin(), internal.end(), [&](Index a, Index b) {
    return std::tuple(low(a), high(a), a) < std::tuple(low(b), high(b), b);
  });
  for (Index f : internal) {
    out.face.push_back(f);
    out.owner.push_back(low(f));
    out.neighbour.push_back(high(f));
  }
  for (std::size_t t = 0; t < by_tag.size(); ++t) {
    if (by_tag[t].empty()) continue;
    out.patch_tag.push_back(static_cast<Index>(t));
    out.patch_size.push_back(static_cast<Index>(by_tag[t].size()));
    for (Index f : by_tag[t]) {
      out.face.push_back(f);
      out.owner.push_back(mesh.owner[f]);
    }
  }
  return out;
}

std::string points_file(const PolyMesh& mesh) {
  std::string s = foam_header("vectorField", kPolyMesh, "points");
  s.reserve(s.size() + mesh.points.size() * 64);
  append_number(s, mesh.num_points());
  s += "\n(\n";
  for (const Vec3& p : mesh.points) {
    s += '(';
    for (int k = 0; k < 3; ++k) {
      if (k) s += ' ';
      append_number(s, p[k]);
    }
    s += ")\n";
  }
  s += ")\n";
  return s;
}

std::string faces_file(const PolyMesh& mesh, const FoamFaces& ff) {
  std::string s = foam_header("faceList", kPolyMesh, "faces");
  s.reserve(s.size() + mesh.face_vertices.size() * 8 + ff.face.size() * 4);
  append_number(s, static_cast<long long>(ff.face.size()));
  s += "\n(\n";
  for (std::size_t i = 0; i < ff.face.size(); ++i) {
    const auto loop = mesh.face(ff.face[i]);
    // Reversed (first vertex kept) when the face's owner changed.
    const bool flip = mesh.owner[ff.face[i]] != ff.owner[i];
    const std::size_t n = loop.size();
    append_number(s, static_cast<long long>(n));
    s += '(';
    for (std::size_t k = 0; k < n; ++k) {
      if (k) s += ' ';
      append_number(s, loop[flip ? (n - k) % n : k]);
    }
    s += ")\n";
  }
  s += ")\n";
  return s;
}

std::string label_list_file(const char* object, const std::vector<Index>& labels,
                            const std::string& note) {
  std::string s = foam_header("labelList", kPolyMesh, object, note);
  s.reserve(s.size() + labels.size() * 8);
  append_number(s, static_cast<long long>(labels.size()));
  s += "\n(\n";
  for (Index l : labels) {
    append_number(s, l);
    s += '\n';
  }
  s += ")\n";
  return s;
}

std::string boundary_file(const PolyMesh& mesh, const FoamFaces& ff) {
  const auto names = export_names(mesh.tag_names);
  std::string s = foam_header("polyBoundaryMesh", kPolyMesh, "boundary");
  append_number(s, static_cast<long long>(ff.patch_tag.size()));
  s += "\n(\n";
  Index start = static_cast<Index>(ff.neighbour.size());
  for (std::size_t p = 0; p < ff.patch_tag.size(); ++p) {
    s += "    " + names[ff.patch_tag[p]] + "\n    {\n        type            patch;\n";
    s += "        nFaces          " + std::to_string(ff.patch_size[p]) + ";\n";
    s += "        startFace       " + std::to_string(start) + ";\n    }\n";
    start += ff.patch_size[p];
  }
  s += ")\n";
  return s;
}

std::string cell_zones_file(const PolyMesh& mesh) {
  const auto zones = cells_by_region(mesh);
  std::string s = foam_header("regIOobject", kPolyMesh, "cellZones");
  s.reserve(s.size() + mesh.cell_region.size() * 8);
  append_number(s, static_cast<long long>(zones.size()));
  s += "\n(\n";
  for (const auto& [region, cells] : zones) {
    s += "region_" + std::to_string(region) +
         "\n{\n    type cellZone;\n    cellLabels List<label>\n";
    append_number(s, static_cast<long long>(cells.size()));
    s += "\n(\n";
    for (Index c : cells) {
      append_number(s, c);
      s += '\n';
    }
    s += ")\n;\n}\n";
  }
  s += ")\n";
  return s;
}

void write_poly_mesh(const PolyMesh& mesh, const fs::path& case_dir, const fs::path& dir) {
  const FoamFaces ff = foam_faces(mesh, boundary_faces_by_tag(mesh, case_dir));
  const std::string note = "nPoints:" + std::to_string(mesh.num_points()) +
                           "  nCells:" + std::to_string(mesh.num_cells()) +
                           "  nFaces:" + std::to_string(ff.face.size()) +
                           "  nInternalFaces:" + std::to_string(ff.neighbour.size());
  write_text_file(dir / "points", points_file(mesh));
  write_text_file(dir / "faces", faces_file(mesh, ff));
  write_text_file(dir / "owner", label_list_file("owner", ff.owner, note));
  write_text_file(dir / "neighbour", label_list_file("neighbour", ff.neighbour, note));
  write_text_file(dir / "boundary", boundary_file(mesh, ff));
  write_text_file(dir / "cellZones", cell_zones_file(mesh));
}

void make_directory(const fs::path& dir, const fs::path& case_dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw InputError(case_dir.string() + ": cannot create " + dir.string() + " (" + ec.message() +
                     ")");
}

constexpr const char* kControlDict = R"(application     laplacianFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         1;
deltaT          1;
writeControl    timeStep;
writeInterval   1;
purgeWrite      0;
writeFormat     ascii;
writePrecision  17;
writeCompression off;
timeFormat      general;
timePrecision   6;
runTimeModifiable false;
)";

constexpr const char* kFvSchemes = R"(ddtSchemes           { default steadyState; }
gradSchemes          { default Gauss linear; }
divSchemes           { default none; }
laplacianSchemes     { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes        { default corrected; }
)";

constexpr const char* kFvSolution = R"(solvers
{
}
)";

// The system dictionaries and the ParaView marker `marker`, each only where missing.
void write_missing_case_files(const fs::path& dir, const fs::path& case_dir,
                              const fs::path& marker) {
  make_directory(dir / "system", case_dir);
  const std::pair<const char*, const char*> dicts[] = {
      {"controlDict", kControlDict}, {"fvSchemes", kFvSchemes}, {"fvSolution", kFvSolution}};
  for (const auto& [name, body] : dicts)
    if (!fs::exists(dir / "system" / name))
      write_text_file(dir / "system" / name, foam_header("dictionary", "system", name) + body);
  if (!fs::exists(dir / marker)) write_text_file(dir / marker, "");
}

}  // namespace

void write_foam(const PolyMesh& mesh, const fs::path& case_dir) {
  // "out.foam/" names the directory "out.foam".
  fs::path dir = case_dir.lexically_normal();
  if (!dir.has_filename()) dir = dir.parent_path();
  // The marker is "<case>.foam" for a directory "<case>.foam" or "<case>".
  std::error_code ec;
  fs::path marker = fs::weakly_canonical(fs::absolute(dir), ec).filename();
  if (marker.extension() == ".foam") marker = marker.stem();
  marker += ".foam";

  if (!fs::exists(dir)) {
    AtomicOutput output(dir);
    make_directory(output.temporary() / kPolyMesh, dir);
    write_poly_mesh(mesh, dir, output.temporary() / kPolyMesh);
    write_missing_case_files(output.temporary(), dir, marker);
    output.commit();
    return;
  }
  if (!fs::is_directory(dir)) throw InputError(dir.string() + ": exists and is not a directory");
  make_directory(dir / "constant", dir);
  AtomicOutput output(dir / kPolyMesh);
  make_directory(output.temporary(), dir);
  write_poly_mesh(mesh, dir, output.temporary());
  output.commit();
  write_missing_case_files(dir, dir, marker);
}

}  // namespace volmesh
