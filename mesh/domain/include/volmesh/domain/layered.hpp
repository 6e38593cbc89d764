#pragma once
// Layered domains (geological layers): a box cut by triangulated sheets.
//
// The model, chosen so that every query is exact:
//  - Every sheet is the graph w = f(u, v) of a piecewise-linear function over the whole
//    rectangle the box projects to along one coordinate axis w ("axis"): horizons are graphs
//    over the x-y rectangle (w = z); a fault is a graph over the y-z or z-x rectangle (a
//    steep or tilted sheet crossing the box completely, e.g. a plane dipping at 60 degrees).
//    So the side of a point, sign(p_w - f(p_u, p_v)), is decided exactly: the triangle above
//    (p_u, p_v) is found with exact 2D orientation tests, then one exact 3D orientation test
//    (CGAL's filtered predicates) compares p with its plane.
//  - Faults (at most 4) split the box into blocks: block k is the part on the upper side
//    (larger w) of fault j where bit j of k is set. Each block has its own horizons, ordered
//    bottom to top, and one label per layer (horizons + 1 labels). A block's horizons span
//    the whole x-y rectangle; only their part inside the block is used, so horizons of a
//    faulted layer are given on both sides of the fault as two sheets, each extended through
//    the fault (which is how the layer interfaces "end on the fault").
//  - Within a block, horizon i must lie nowhere above horizon i + 1 over the rectangle:
//    touching (a layer pinching out: equal heights over part of the rectangle) is allowed;
//    crossing (a layer of negative thickness) is refused. Horizons may leave the box through
//    its top or bottom (a layer cut off by the box).
//  - region(p): 0 outside the closed box; otherwise the layer of p's block, counting the
//    horizons below p. Priority on interfaces: a point on sheets (including a fault, and the
//    several coinciding horizons of a pinch-out) gets the highest label among the layers
//    of every block whose closure holds it; the box faces belong to the box. Other orders
//    through prioritized() (prioritized.hpp).
//  - crossings(a, b): every sheet triangle the segment meets, found through a CGAL AABB tree
//    with exact predicates (t in double); the regions of the pieces between them are found
//    exactly, at each piece's middle. Crossings at t = 0 or 1 appear when an end point lies
//    on an interface; a segment touching an interface from its lower-priority side without
//    crossing it (the touching point having another region) gives a crossing with before ==
//    after, its normal pointing out of before. Normals: the face normal, or the
//    angle-weighted pseudo-normal of the edge or vertex met, oriented from before into after.
//  - normal(p): the pseudo-normal at the closest point of the nearest sheet of p's block
//    (its horizons, the faults and the box faces), pointing out of the higher label. The
//    nearest-point trees are built on the first call (about as long as the rest).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "volmesh/core/tri_surface.hpp"
#include "volmesh/domain/domain.hpp"

namespace volmesh {

namespace layers {
struct Model;  // layered_model.hpp
}

// A triangulated graph w = f(u, v) over the box's rectangle across axis w, (u, v) being the
// next two axes in cyclic order (x-y for w = z, y-z for w = x, z-x for w = y). Its triangles
// may be given either way round; vertices must lie in the closed rectangle (those within
// 1e-6 of its sides, relative to them, are moved onto its border, for float file formats),
// every triangle must project to a proper triangle, and the projections must tile the
// rectangle once.
struct Sheet {
  TriSurface surface;
  int axis = 2;                // w: 0 = x, 1 = y, 2 = z
  std::string name = "sheet";  // names it in error messages (e.g. its file)
};

// A plane {x : normal . (x - point) = 0} as a sheet across `axis`: two triangles over the
// box's rectangle. normal[axis] must not be 0.
Sheet plane_sheet(const Box3& box, int axis, const Vec3& point, const Vec3& normal,
                  std::string name);
// The graph w = f(u, v) sampled on an nu x nv grid of vertices spanning the box's rectangle
// across `axis` (nu, nv >= 2), each grid cell cut into two triangles along a diagonal.
Sheet graph_sheet(const Box3& box, int axis, Index nu, Index nv,
                  const std::function<double(double u, double v)>& f, std::string name);

struct LayerBlock {
  std::vector<Sheet> horizons;  // bottom to top, axis z
  std::vector<Index> labels;    // horizons.size() + 1 labels >= 1, bottom to top
};

struct LayeredModel {
  Box3 box;
  std::vector<Sheet> faults;       // at most 4
  std::vector<LayerBlock> blocks;  // 2^faults.size()
  std::string name = "layers";     // names the model in error messages
};

class LayeredDomain final : public Domain {
 public:
  // Throws InputError with one line naming the model and the sheet for an invalid box, a
  // sheet that is not a graph over its rectangle (a triangle folding over, a hole, a vertex
  // outside the rectangle, parts covering the rectangle twice), labels that do not match
  // the horizons, or two horizons of a block that cross (naming both and a point).
  explicit LayeredDomain(LayeredModel model);
  ~LayeredDomain() override;
  LayeredDomain(LayeredDomain&&) noexcept;
  LayeredDomain& operator=(LayeredDomain&&) noexcept;

  using Domain::crossings;
  using Domain::region;
  Index region(const Vec3& p) const override;
  std::vector<Crossing> crossings(const Vec3& a, const Vec3& b) const override;
  Vec3 normal(const Vec3& p) const override;
  Box3 bounds() const override;  // the box
  bool fills_bounds() const override { return true; }
  // The labels seen along a 32 x 32 grid of vertical lines through the box: a layer
  // thinner than box/32 everywhere could be missed.
  std::vector<Index> regions() const override;
  // The nearest sheet's name; box faces are "xmin", "xmax", ..., "zmax".
  std::string surface_name(const Vec3& p) const override;
  // The nearest box face's name: region 0 lies only outside the box. Unlike surface_name(),
  // it needs no nearest-point tree (which costs as much as the rest of the model).
  std::string boundary_name(const Vec3& p) const override;

 private:
  std::unique_ptr<layers::Model> model_;
};

}  // namespace volmesh
