#pragma once
// Validity and shape measures of one hexahedron of the dual-contouring mesh, its corners in
// VTK order (0-3 the bottom quad counter-clockwise seen from above, 4-7 above 0-3).
#include <array>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/types.hpp"

namespace volmesh {

// The paper's ten corner tetrahedra (after Azarenok, 2008), in 0-based VTK corners. The paper
// numbers the corners 1-8 as VTK's 0-7 (its tets T1245, T3427, … join each corner to its three
// edge neighbours, which fixes the numbering). They are the two splits of the hex into five
// tets about its two inscribed tetrahedra:
//   corners 0, 2, 5, 7 and the inner tet 1-3-4-6 (the paper's T1245, T3427, T6572, T8754, T2457),
//   corners 1, 3, 4, 6 and the inner tet 0-2-7-5 (T2316, T4138, T5861, T7683, T1386).
// Each is ordered so that its volume is positive in the unit cube.
// The corner tets are core's corner frames (kHexCornerFrames), grouped by split.
inline constexpr std::array<std::array<int, 4>, 10> kHexCornerTets{
    {kHexCornerFrames[0], kHexCornerFrames[2], kHexCornerFrames[5], kHexCornerFrames[7],
     {1, 3, 4, 6},
     kHexCornerFrames[1], kHexCornerFrames[3], kHexCornerFrames[4], kHexCornerFrames[6],
     {0, 2, 7, 5}}};

// Signed volumes of the ten tets of kHexCornerTets.
std::array<double, 10> hex_corner_tet_volumes(const std::array<Vec3, 8>& corners);

// The paper's non-degeneracy test: every one of the ten tets has a positive volume, each sign
// decided exactly (CGAL's orientation predicate on the corners as given).
bool hex_corner_tets_positive(const std::array<Vec3, 8>& corners);

// Interior angles of a quad, in degrees, in [0, 360): at corner k the angle from the edge to
// corner k+1 round to the edge to corner k-1, measured about the quad's vector area (half the
// cross product of its diagonals), so that the reflex corner of a dart measures above 180°.
// A non-planar quad's angles are those of its edges as they are, not projected.
std::array<double, 4> quad_interior_angles_deg(const std::array<Vec3, 4>& quad);

// What smoothing and projection judge a move by.
struct HexGrade {
  double scaled_jacobian = 0.0;       // hex_scaled_jacobian
  bool corner_tets_positive = false;  // hex_corner_tets_positive
};
HexGrade hex_grade(const std::array<Vec3, 8>& corners);

// What untangling judges a move by: the least of the scaled Jacobian and the normalised volumes
// of the two inner corner tets (6 V over the product of the tet's three edges at its first
// corner, scaled to 1 in a cube). Positive exactly when the hex passes the ten corner tets and
// its scaled Jacobian is positive.
double hex_shape_quality(const std::array<Vec3, 8>& corners);

struct HexQuality {
  bool corner_tets_positive = false;  // hex_corner_tets_positive
  double scaled_jacobian = 0.0;       // Verdict's, over the 8 corners and the centre
  // Over the six faces: the largest interior angle, and the largest deviation of an interior
  // angle from 90°. The paper's "maximum quad distortion angle" must be the deviation: its
  // tables list values below 90° (39.5°), which no largest angle of a quad can be, and above
  // 90° (130.2°, 172.8°), which only a reflex corner reaches.
  double max_quad_angle_deg = 0.0;
  double max_quad_distortion_deg = 0.0;
  double min_edge = 0.0, max_edge = 0.0;  // over the twelve edges
};

HexQuality hex_quality(const std::array<Vec3, 8>& corners);

}  // namespace volmesh
