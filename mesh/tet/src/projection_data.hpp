#pragma once
// The projection mesher's data between its stages (projection.hpp), over CGAL's lazy exact
// kernel: every number is an exact rational, every predicate exact and filtered.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <vector>

#include "volmesh/core/types.hpp"
#include "volmesh/tet/projection.hpp"

namespace volmesh::tet::detail {

// The plane triangulation's kernel: filtered exact predicates and exact intersections.
using K = CGAL::Epeck;
using Point2 = K::Point_2;
// Heights and points in plain GMP rationals: they are compared for equality all the time
// (surfaces meet along edges), which a lazy number only settles by evaluating exactly.
using Rational = mpq_class;

using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<Index, K>;
using FaceBase =
    CGAL::Constrained_triangulation_face_base_2<K,
                                               CGAL::Triangulation_face_base_with_info_2<Index, K>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Plane2 = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_intersections_tag>;
using VertexHandle = Plane2::Vertex_handle;
using FaceHandle = Plane2::Face_handle;

enum class Facing { top, bot, wall };


// The input, in the projection frame (the axis is z).
struct Surfaces {
  std::vector<RationalPoint> points;
  std::vector<Point2> projected;  // per point
  std::vector<std::array<Index, 3>> triangles;
  std::vector<Index> surface;  // per triangle
  std::vector<Index> label;    // per surface
  std::vector<Facing> facing;  // per triangle
  // Per non-WALL triangle, z = a x + b y + c over its plane.
  std::vector<std::array<Rational, 3>> plane;
};

// A gap between two consecutive surface triangles over a plane triangle, inside region
// `region`: the bottom and top triangles' planes bound it.
struct Prism {
  FaceHandle face;
  Index bottom = kNoIndex, top = kNoIndex;
  Index region = 0;
};

// A point on a vertical line over a plane vertex: its height and its mesh point.
struct Height {
  Rational z;
  Index point = kNoIndex;
};

// A triangle of a prism's boundary, oriented outward, with the surface triangle it lies on
// (kNoIndex inside the domain).
struct BoundaryTriangle {
  std::array<Index, 3> points;
  Index on = kNoIndex;
};

struct State {
  Surfaces input;
  Plane2 plane;
  std::vector<VertexHandle> vertices;        // by vertex info
  std::vector<std::array<Rational, 2>> xy;   // per vertex, exact
  std::vector<std::vector<Index>> at_vertex;  // input points projecting onto each vertex
  std::vector<FaceHandle> faces;             // the finite faces, by face info
  std::vector<std::vector<Index>> stack;     // per face: the triangles over it, upwards
  std::vector<Prism> prisms;                 // face by face
  std::vector<Index> face_prisms;            // face f's: [face_prisms[f], face_prisms[f + 1])
  std::vector<Index> walls;                  // the WALL triangles
  std::vector<std::vector<Height>> heights;  // per vertex, increasing, distinct
  std::vector<RationalPoint> points;         // the mesh's
  std::vector<std::vector<BoundaryTriangle>> prism_boundary;
};

// Stages (projection.hpp says what each does).
void classify(const std::vector<ProjectionSurface>& surfaces, Axis axis, int tilt, Surfaces& out);
// The shear of tilt k (0: none), (a, b).
std::array<Rational, 2> shear_of(int tilt);
Axis choose_axis(const std::vector<ProjectionSurface>& surfaces);
void project(State& state);
void build_prisms(State& state);
void stitch(State& state);
void fill(State& state, ProjectionMesh& mesh);

// Height of non-WALL triangle t over plane vertex v (the corner's own z when v is a corner).
Rational height_at(const State& state, Index t, Index v);
// The bounding rectangle of triangle t's projection, in doubles, for the plane caches.
std::array<double, 4> projected_box(const Surfaces& input, Index t);
// z of triangle t's plane over (x, y).
Rational height_at(const Surfaces& input, Index t, const Rational& x, const Rational& y);

}  // namespace volmesh::tet::detail
