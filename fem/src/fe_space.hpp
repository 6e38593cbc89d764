#pragma once
// A finite-element space as the assembly sees it: scalar nodes (each with the position where
// boundary data and nodal errors are taken), per cell its global nodes and quadrature points
// carrying shape values and gradients, per boundary face its nodes and quadrature points.
// Vector fields carry `components` unknowns per node, node-major.
#include <array>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/fem/fem.hpp"
#include "volmesh/fem/lagrange.hpp"
#include "volmesh/fem/quadrature.hpp"

namespace volmesh::fem::detail {

enum class Rule {
  stiffness,  // exact for the bilinear forms with constant coefficients on affine cells, and
              // for the cell means of u_h and σ(u_h)
  load,       // sources and body forces
  accurate,   // degree 5 per (sub-)element: error norms
};

// Quadrature points of one cell, grouped by the local nodes their shape functions involve
// (on the polyhedral space a sub-tetrahedron touches only its face's vertices and the cell
// node). Local nodes: 0 … outer-1 are FeSpace::cell_nodes(c), then the internal nodes.
struct CellPoints {
  struct Group {
    int node_begin, node_count;  // into `nodes`
    int point_begin, point_count;
  };
  std::vector<Group> groups;
  std::vector<int> nodes;
  std::vector<double> weight;            // per point, the Jacobian included
  std::vector<Vec3> x;                   // per point
  std::vector<std::size_t> shape_begin;  // per point, into value and gradient
  std::vector<double> value;             // node_count entries per point
  std::vector<Vec3> gradient;            // node_count entries per point
  // Stiffness terms beyond the points, scale·(r·u)(r·v) for each unknown per node: r a row
  // over all the cell's local nodes (the virtual-element stabilisation of
  // fe_space_polyhedral.cpp). The problem multiplies them by its modulus.
  std::vector<double> stabilization_scale;
  std::vector<double> stabilization_rows;  // one row per scale, every local node

  void clear();
  void begin_group(std::span<const int> local_nodes);
  // Appends a point to the last group, its shape data zeroed; returns the point's index,
  // whose shape data values() and gradients() then give.
  int add_point(double w, const Vec3& at);
  std::span<double> values(int point) {
    return {value.data() + shape_begin[point], static_cast<std::size_t>(groups.back().node_count)};
  }
  std::span<Vec3> gradients(int point) {
    return {gradient.data() + shape_begin[point],
            static_cast<std::size_t>(groups.back().node_count)};
  }
};

// A cell on which u_h is affine on each of a set of tetrahedra (the polyhedral space's
// sub-tetrahedra, a P1 tet): per piece its corners, volume and barycentric gradients, and u_h
// at each corner as a combination of local nodes. The integrals after a solve evaluate u_h
// from four corner values per piece and one gradient, not from shape data per point; the
// points are the pieces' images of `rule`, at the same positions and weights as
// FeSpace::cell_points gives.
struct CellPieces {
  struct Piece {
    std::array<Vec3, 4> corners;
    TetAffine affine;
  };
  std::span<const TetQuadraturePoint> rule;
  std::vector<Piece> pieces;
  // Corner k of piece i is Σ coefficient[j] · (local node node[j]) for j in
  // [term_begin[4i + k], term_begin[4i + k + 1]).
  std::vector<int> term_begin{0};
  std::vector<int> node;
  std::vector<double> coefficient;

  void clear();
  void add_piece(std::span<const Vec3, 4> corners, const TetAffine& affine);
  // Adds a term to the corner being described; end_corner closes it (four per piece, in
  // corner order).
  void add_term(int local_node, double c) {
    node.push_back(local_node);
    coefficient.push_back(c);
  }
  void end_corner() { term_begin.push_back(static_cast<int>(node.size())); }
};

// Quadrature points of a boundary face.
struct FacePoints {
  std::vector<Index> nodes;  // global nodes whose shape functions live on the face
  std::vector<double> weight;
  std::vector<Vec3> x;
  std::vector<double> value;  // nodes.size() entries per point

  void clear();
  // Appends a point, its values zeroed; returns a pointer to them.
  double* add_point(double w, const Vec3& at);
};

class FeSpace {
 public:
  virtual ~FeSpace() = default;

  Index num_nodes() const { return static_cast<Index>(node_point.size()); }
  Index num_cells() const { return static_cast<Index>(cell_node_offsets.size()) - 1; }
  std::span<const Index> cell_nodes(Index c) const {
    return {cell_node_list.data() + cell_node_offsets[c],
            static_cast<std::size_t>(cell_node_offsets[c + 1] - cell_node_offsets[c])};
  }
  // Nodes of each cell beyond cell_nodes (condensed statically): the same for every cell.
  virtual int internal_nodes() const { return 0; }
  virtual void cell_points(Index c, Rule rule, CellPoints& out) const = 0;
  // Cell c as affine pieces for `rule`, when u_h is affine piece by piece there; false (out
  // unspecified) when it is not, and cell_points must serve.
  virtual bool cell_pieces(Index, Rule, CellPieces&) const { return false; }
  // Whether cell c's load points are its stiffness points, so that one computation serves both.
  virtual bool load_is_stiffness(Index) const { return false; }
  // The nodes of boundary face f.
  virtual void face_nodes(Index f, std::vector<Index>& out) const = 0;
  virtual void face_points(Index f, FacePoints& out) const = 0;

  std::vector<Vec3> node_point;   // where each node's value is taken
  std::vector<Index> point_node;  // mesh point → node, kNoIndex for a point no cell uses
  std::vector<Index> cell_node_offsets{0};
  std::vector<Index> cell_node_list;
};

// Builds the space, checking that every cell suits it and has a positive Jacobian.
// to_true_boundary, when given, puts p2's boundary edge nodes on the true boundary
// (isoparametric P2, curved_tet.hpp); the other spaces ignore it.
std::unique_ptr<FeSpace> make_space(const PolyMesh& mesh, Space space,
                                    const PointMap& to_true_boundary = {});

// Builders behind make_space (one file each).
std::unique_ptr<FeSpace> make_tet_space(const PolyMesh& mesh, bool quadratic,
                                        const PointMap& to_true_boundary);
std::unique_ptr<FeSpace> make_q1_space(const PolyMesh& mesh);
std::unique_ptr<FeSpace> make_polyhedral_space(const PolyMesh& mesh);

// Numbers the points flagged as used, in point order; fills space.point_node and the vertex
// entries of space.node_point.
void number_used_points(const PolyMesh& mesh, const std::vector<char>& used, FeSpace& space);

// The corners (VTK order) of every cell, which must all have the given shape; throws
// InputError naming the first cell that does not, and the space that needs the shape.
std::vector<std::array<Index, 8>> element_corners(const PolyMesh& mesh, CellShape shape,
                                                  Space space);

// The smallest cell index c < num_cells with bad(c), or kNoIndex; tested in parallel, so that
// a message names the same cell for any thread count.
Index first_cell_where(Index num_cells, const std::function<bool(Index)>& bad);

// The largest value(i) over i in [0, count) (0 when count is 0), computed in parallel.
double largest_of(Index count, const std::function<double(Index)>& value);

}  // namespace volmesh::fem::detail
