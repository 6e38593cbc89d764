#pragma once
// Shared by the VTU and MSH tests: small volume meshes, a mesh comparison, temporary
// directories and the calls to the third-party tools (meshio, gmsh).
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/shell.hpp"
#include "../support/temp_dir.hpp"
#include "volmesh/core/poly_mesh.hpp"

namespace volmesh::test {

// 2×2×2 Kuhn tets (48) of the unit cube; cells with centroid x > 0.5 are region 2.
PolyMesh two_region_tets();
// 2×2×2 hexes of the unit cube; the top layer (z > 0.5) is region 3.
PolyMesh two_region_hexes();
// A 2×2×2 block of hexes on [1,2]×[0,1]×[0,1] next to the unit cube as one polyhedron with 9
// faces and 13 vertices: its x = 1 side is split into the four small faces it shares.
PolyMesh split_face_mesh();

// Same points (exactly), same cells (each as its set of outward face loops up to rotation),
// same regions, same boundary faces with the same tag names.
void expect_same_mesh(const PolyMesh& expected, const PolyMesh& actual);

// Cell counts by meshio's type names: "tetra", "hexahedron", "polyhedron<N>" (N vertices),
// plus "points".
std::map<std::string, long> cell_type_counts(const PolyMesh& mesh);

std::string file_bytes(const std::filesystem::path& path);
void write_text(const std::filesystem::path& path, const std::string& text);
// read_mesh's InputError message, or "no error".
std::string read_mesh_error(const std::filesystem::path& path);

// Runs tests/io/external/<script> with Debian's python (which has meshio). Fails the test
// with a hint when meshio is missing; returns the script's stdout.
std::string run_meshio_script(const std::string& script, const std::string& args);

// What meshio finds in each file (tests/io/external/meshio_read.py, one Python start for
// all): {"points": n, "cells": {type: count}, "cell_data": [names], "point_data": [names]}.
// Empty objects, with a test failure, when meshio is missing or fails.
std::vector<nlohmann::json> meshio_read(const std::vector<std::filesystem::path>& files);

// What meshio finds in the 3D cells of each file (tests/io/external/meshio_region_volumes.py):
// {"cells": {type: count}, "volume": V, "regions": {"r": V_r}, "min_tet": v}; regions read
// from `region_array` when given. Empty objects, with a test failure, when meshio fails.
std::vector<nlohmann::json> meshio_region_volumes(const std::vector<std::filesystem::path>& files,
                                                  const std::string& region_array = "");

// Checks meshio's point and cell counts against `expected` (as from cell_type_counts).
void expect_meshio_counts(std::map<std::string, long> expected, const nlohmann::json& seen);

// Fails the test with a hint when /usr/bin/gmsh is missing.
bool have_gmsh();

}  // namespace volmesh::test
