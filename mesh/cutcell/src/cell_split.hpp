#pragma once
// M3C on one cell (the octree paper, §3.2-3.3 and Algorithm 5): the face contours joined
// into closed components per pair of regions, a cell interface point where more than two
// face interface points occur, the components triangulated, and the cell split into one
// polyhedral piece per connected part of each region.
#include <array>
#include <cstdint>
#include <vector>

#include "loop_triangulation.hpp"
#include "tangent_point.hpp"
#include "volmesh/quality/face_metrics.hpp"

namespace volmesh::cutcell {

enum class CellPointKind : std::uint8_t { grid, edge, face_feature, face_interface };

struct CellPoint {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::Zero();  // edge interface points: unit, from the lower into the higher
                               // label of the two regions the point separates; zero when
                               // unknown (left out of the least-squares fits)
  std::uint8_t faces = 0;      // bit k: the point lies on cell face k (x-, x+, y-, y+, z-, z+)
  CellPointKind kind = CellPointKind::grid;
  bool junction = false;  // an edge point on which a face interface point landed
  bool is_face_interface() const { return kind == CellPointKind::face_interface || junction; }
};

// A polygon of the cell's boundary, one region, oriented outward.
struct CellPolygon {
  Index region = 0;
  std::vector<int> points;
};

// A contour segment on the cell's boundary; left and right are seen from outside the cell.
struct CellSegment {
  int a = 0, b = 0;
  Index left = 0, right = 0;
  int left_polygon = -1, right_polygon = -1;
};

struct CellInput {
  std::array<Vec3, 8> corners;  // corner k at offset (k & 1, k >> 1 & 1, k >> 2 & 1)
  std::vector<CellPoint> points;
  std::vector<CellPolygon> polygons;
  std::vector<CellSegment> segments;
};

struct CellOptions {
  // false: M3C as published: the cell interface point at the cell centre, no feature points.
  bool exact_points = true;
  FeatureThresholds feature;
  // Points made inside the cell keep margin * size away from its faces. A least-squares
  // cell interface point found outside by less than reach * size is pushed in (a junction
  // next to a face), farther out the centroid of the face interface points is used; a
  // feature point farther out than feature_reach * size is not the cell's.
  double margin = 0.01;
  double reach = 0.25;
  double feature_reach = 0.1;
  // A feature point within snap * size of a face point of its component (the feature runs
  // along the face) is that face point.
  double snap = 0.15;
  // The cell interface point keeps junction_margin * size away from the faces: a junction
  // running just inside a face (sphere and cylinder meeting 0.01 h below a grid plane)
  // would otherwise leave slivers between it and the face that no merge repairs. The
  // vertex clearance does the same for interfaces near vertices.
  double junction_margin = 0.1;
  // Two face interface points are joined through the cell interface point instead of their
  // link when the least-squares junction point lies farther than bend * size from the link.
  double bend = 0.05;
  // Components without feature or cell point and with at least this many points are fanned
  // around their least-squares surface point; smaller ones use divide and conquer.
  int fan_points = 5;
  // Two triangles of a component whose points lie within flat * size of each other's plane
  // may swap their diagonal (the surface stays put) when that lowers their skewness.
  double flat = 1e-6;
  // When a triangle lies beyond these limits (checkmesh_badness above 1) or behind a
  // piece's centre, the other triangulations of each component are tried.
  CheckMeshLimits limits;
  // The last resort for a triangle still more skewed: merged with neighbouring triangles of
  // its interface whose normals differ by less than this angle (degrees) into one polygon
  // face (a sliver at any angle, except across a sharp edge its component keeps). 0 keeps
  // the trace a triangulation everywhere.
  double merge_angle = 60.0;
  // Given (exact points), feature and cell interface points take one Newton step onto the
  // true surfaces (planes_near_feature), looking newton_reach * size either way.
  SurfaceNear surface_near;
  double newton_reach = 0.25;
};

enum class LoopMethod : std::uint8_t {
  divide_and_conquer,
  feature_fan,    // around the EMC feature point of the component
  feature_split,  // along a sharp edge between the CMS feature points of two faces
  interface_fan,  // around the cell interface point
  surface_fan,    // around the least-squares surface point of a large component
  across_faces,   // §4.1's construction
  centroid_fan,   // around the centroid of the component's points
  degenerate,     // two points: a face segment that is also the link, no triangle
};

struct CellPiece {
  Index region = 0;
  std::vector<int> polygons;  // input polygons bounding it
};

// A triangle of the interface between two pieces (point indices as in CellInput, the new
// points after them); its right-hand normal points out of the piece of the higher region.
struct PieceTriangle {
  Triangle points{};
  int lower = -1, higher = -1;  // pieces
  int loop = -1;                // the component it triangulates (CellSplit::loops)
};
// Triangles of a component merged into one polygon because each alone was too skewed.
struct PiecePolygon {
  std::vector<int> points;
  int lower = -1, higher = -1;
  int loop = -1;
};

struct CellSplit {
  std::vector<Vec3> new_points;  // index points.size() + k: cell interface and feature points
  std::vector<CellPiece> pieces;
  std::vector<PieceTriangle> triangles;
  std::vector<PiecePolygon> polygons;  // rare: see CellOptions::merge_angle
  std::vector<int> polygon_piece;  // the piece of each input polygon
  std::vector<LoopMethod> loops;   // how each component was triangulated
  bool cell_point_left_cell = false;  // the least-squares cell point fell outside; centroid used
  // How far the worst interface face is from CellOptions::limits, from the pieces' centres
  // (checkmesh_badness, kInvertedFace for a face behind a centre); above 1: rejected. Boundary faces (region 0 below) as checkMesh
  // measures those.
  double max_badness = 0.0;
};

// Throws std::logic_error when the contour does not close (inconsistent input).
CellSplit split_cell(const CellInput& cell, const CellOptions& options = {});

// The union of two faces sharing exactly one edge (u -> v in a, v -> u in b), or empty when
// they share none or more, or the union would touch itself.
std::vector<int> merge_along_edge(const std::vector<int>& a, const std::vector<int>& b);

}  // namespace volmesh::cutcell
