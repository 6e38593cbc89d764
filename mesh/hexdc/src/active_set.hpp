#pragma once
// The global optimiser's problem (optimise.hpp): how each node may move, the active sets a
// descent moves, and the energies over them with their gradients, summed in a fixed order so
// that the result is the same for any thread count.
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "hex_energy.hpp"
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/hexdc/surface_projector.hpp"

namespace volmesh::hexdc_detail {

// Hexes (quads, nodes) per parallel task: a few thousand, so that a small mesh runs on one
// thread and a large one wakes the others a few times per evaluation, not for every block.
constexpr std::size_t kGrain = 512;
// An optimisation pass moves the nodes of the terms within kActiveSpan / β of the least (the
// others weigh below e^-16 of it in the soft minimum's gradient), grown by kActiveRings hex
// rings.
constexpr double kActiveSpan = 16.0;
constexpr int kActiveRings = 1;

enum class NodeKind : std::uint8_t { fixed, free, surface, crease };

struct Problem {
  HexMesh& mesh;
  const SurfaceProjector& surface;
  std::vector<std::vector<Index>> hexes;  // hexes of each node
  std::vector<std::vector<Index>> quads;  // boundary quads of each node
  std::vector<NodeKind> kind;
  std::vector<Vec3> crease;               // a crease node's direction
  std::vector<double> reach;              // shortest edge at the node, at the start
  std::vector<double> size;               // a hex's mean edge, at the start
};

// The nodes a descent moves and the hexes and quads it evaluates (those with a moving node);
// every other term stays as it is: the optimisation sums them once into `frozen`, the untangling
// leaves them out.
struct Active {
  std::vector<Index> nodes;         // moving, in node order
  std::vector<Index> hexes, quads;  // in order
  std::vector<Eigen::Index> place;  // per node its coordinates' offset in x, or -1
  struct Frozen {
    double least = std::numeric_limits<double>::infinity();  // their least term
    double sum = 0.0;  // optimisation: Σ exp(−β (q − least)) over their terms
    double tet = std::numeric_limits<double>::infinity();    // their least tet measure
    double other = std::numeric_limits<double>::infinity();  // least centre measure or quad sine
    double edge = std::numeric_limits<double>::infinity();   // least edge over its hex's size
  } frozen;
};

// The nodes within `rings` hexes of the marked ones that may move, and the hexes and quads at
// them.
Active grow_active(const Problem& p, std::vector<char> marked, int rings);

// Every node that may move, and every hex and quad.
Active everything(const Problem& p);

inline std::array<Vec3, 4> quad_corners(const HexMesh& mesh, std::size_t q) {
  std::array<Vec3, 4> corners;
  for (std::size_t c = 0; c < 4; ++c)
    corners[c] = mesh.points[static_cast<std::size_t>(mesh.boundary_faces[q][c])];
  return corners;
}

// The energy at mesh.points with its gradient over the active nodes, and the least measures
// there (the optimisation's frozen terms included).
struct Evaluation {
  double energy = 0.0;
  double least = 0.0;  // the least det J (untangling) or tet measure (optimisation)
  // Optimisation: the least centre measure or boundary quad corner sine, the measures that may
  // start below zero without a folded tet.
  double least_other = 1.0;
  // Optimisation: the least hex edge over its hex's mean edge at the start, which the scaled
  // measures, ratios of lengths, do not see shrink.
  double least_edge = 1.0;
  Eigen::VectorXd gradient;
};

// The barrier energy of the active hexes, computed in parallel into per-hex slots summed in
// hex order; the others are left out.
Evaluation barrier_energy(const Problem& p, const Active& a, const Barrier& barrier);

// −(1/β) log Σ exp(−β q) over every hex's ten tet measures and centre measure and every boundary
// quad's corner sines, negated: minimising it raises the soft minimum. `least` is the least tet
// measure.
Evaluation softmin_energy(const Problem& p, const Active& a, double beta);

// The active set of an optimisation pass: the nodes of every hex and quad with a term within
// kActiveSpan / β of the least, grown by kActiveRings; the other terms frozen. Returns it with
// the least term now in `least`.
Active select_softmin(const Problem& p, double beta, double& least);

}  // namespace volmesh::hexdc_detail
