#pragma once
// What a golden case stores: the mesh's counts, validity, region volumes and quality figures
// (the measures `volmesh check` reports), a hash of its canonical bytes, and the solve's
// figures; and the comparison that names every field that moved.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "golden_cases.hpp"
#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/fem/solution.hpp"

namespace volmesh::golden {

// 64-bit FNV-1a of the mesh's arrays in their own order, each preceded by its length:
// points (x, y, z as IEEE-754 bits), face offsets, face vertices, owner, neighbour, face
// tags, cell regions, tag names. Integers are fed as 64-bit little-endian words, so the
// hash does not depend on the host's byte order. As "0x" and 16 hex digits.
std::string canonical_hash(const PolyMesh& mesh);

nlohmann::json case_summary(const GoldenCase& c, const PolyMesh& mesh,
                            const fem::ScalarSolution* solution);

// Floating figures agree when |a - b| <= kRelativeTolerance * max(|a|, |b|) + kAbsoluteFloor:
// the same mesh gives the same figures to rounding (sums in another order), so a change
// beyond 1e-9 of a figure is a change of the output; the floor keeps figures that are zero up
// to rounding (the skewness of a cube's face) from failing on their last bits.
inline constexpr double kRelativeTolerance = 1e-9;
inline constexpr double kAbsoluteFloor = 1e-12;

// One line per field that differs ("mesh.cells: 1234 -> 1240"), missing or new fields
// included; empty when the summaries agree (integers, strings and booleans exactly, numbers
// with a fraction within the tolerance).
std::vector<std::string> moved_fields(const nlohmann::json& stored, const nlohmann::json& now);

}  // namespace volmesh::golden
