#pragma once
// MMCMS on the unit cube alone: M3S on its six faces (from a domain's exact crossings on its
// twelve edges, each computed once) joined into the input of M3C, and checks on the pieces.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

#include "cell_split.hpp"
#include "face_contour.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/octree/octree.hpp"

namespace volmesh::test {

struct UnitCube {
  cutcell::CellInput input;
  std::vector<cutcell::FaceContour> faces;
};

inline Vec3 cube_corner(int k) { return Vec3(k & 1, k >> 1 & 1, k >> 2 & 1); }

inline std::uint8_t corner_faces(int k) {
  std::uint8_t bits = 0;
  for (int axis = 0; axis < 3; ++axis) bits |= 1 << (2 * axis + (k >> axis & 1));
  return bits;
}

inline UnitCube unit_cube(const Domain& domain, const cutcell::FaceContourOptions& options = {}) {
  using namespace cutcell;
  UnitCube cube;
  CellInput& in = cube.input;
  std::array<Index, 8> region{};
  for (int k = 0; k < 8; ++k) {
    in.corners[k] = cube_corner(k);
    region[k] = domain.region(in.corners[k]);
    in.points.push_back({in.corners[k], Vec3::Zero(), corner_faces(k), CellPointKind::grid});
  }
  // The edge points, once per edge: point index, normal from the lower corner's region.
  std::map<std::pair<int, int>, int> edge_point;
  for (const auto& [a, b] : kEdgeCorners) {
    if (region[a] == region[b]) continue;
    for (const Crossing& c : domain.crossings(in.corners[a], in.corners[b]))
      if (c.before != c.after) {
        const Vec3 n = region[a] < region[b] ? c.normal : Vec3(-c.normal);
        edge_point[{a, b}] = static_cast<int>(in.points.size());
        in.points.push_back({c.point, n, static_cast<std::uint8_t>(corner_faces(a) & corner_faces(b)),
                             CellPointKind::edge});
        break;
      }
  }
  for (int f = 0; f < 6; ++f) {
    FaceInput face;
    std::vector<int> local;  // boundary index -> cell point
    for (int i = 0; i < 4; ++i) {
      const int a = kFaceCorners[f][i], b = kFaceCorners[f][(i + 1) % 4];
      face.corners[i] = static_cast<int>(face.boundary.size());
      face.boundary.push_back({in.corners[a], region[a], Vec3::Zero()});
      local.push_back(a);
      if (region[a] == region[b]) continue;
      const int p = edge_point.at({std::min(a, b), std::max(a, b)});
      // The normal from the region before the point (a) into the one after it (b).
      const Vec3& n = in.points[p].normal;
      face.boundary.push_back({in.points[p].position, kNoIndex, region[a] < region[b] ? n : Vec3(-n)});
      local.push_back(p);
    }
    FaceContour contour = contour_face(face, options);
    if (contour.kind != FacePointKind::none && contour.centre < 0) {
      local.push_back(static_cast<int>(in.points.size()));
      in.points.push_back({contour.point, Vec3::Zero(), static_cast<std::uint8_t>(1 << f),
                           contour.kind == FacePointKind::interface_point ? CellPointKind::face_interface
                                                                          : CellPointKind::face_feature});
    } else if (contour.centre >= 0) {
      in.points[local[contour.centre]].junction = true;
    }
    const int first = static_cast<int>(in.polygons.size());
    for (const FacePolygon& p : contour.polygons) {
      CellPolygon poly{p.region, {}};
      for (int i : p.points) poly.points.push_back(local[i]);
      in.polygons.push_back(std::move(poly));
    }
    for (const ContourSegment& s : contour.segments)
      in.segments.push_back({local[s.a], local[s.b], s.left, s.right, first + s.left_polygon,
                             first + s.right_polygon});
    cube.faces.push_back(std::move(contour));
  }
  return cube;
}

// The outward faces of each piece (polygons, then triangles and merged polygons).
inline std::vector<std::vector<std::vector<int>>> piece_faces(const cutcell::CellInput& in,
                                                              const cutcell::CellSplit& split) {
  std::vector<std::vector<std::vector<int>>> faces(split.pieces.size());
  for (std::size_t p = 0; p < split.pieces.size(); ++p)
    for (int poly : split.pieces[p].polygons) faces[p].push_back(in.polygons[poly].points);
  for (const cutcell::PieceTriangle& t : split.triangles) {
    faces[t.higher].push_back({t.points[0], t.points[1], t.points[2]});
    faces[t.lower].push_back({t.points[0], t.points[2], t.points[1]});
  }
  for (const cutcell::PiecePolygon& p : split.polygons) {
    faces[p.higher].push_back(p.points);
    faces[p.lower].push_back(std::vector<int>(p.points.rbegin(), p.points.rend()));
  }
  return faces;
}

inline std::vector<Vec3> all_points(const cutcell::CellInput& in, const cutcell::CellSplit& split) {
  std::vector<Vec3> out;
  for (const cutcell::CellPoint& p : in.points) out.push_back(p.position);
  out.insert(out.end(), split.new_points.begin(), split.new_points.end());
  return out;
}

// Volume of a closed piece; asserts it closes edge by edge (every directed edge once, its
// reverse once) and its oriented areas sum to zero.
inline double closed_piece_volume(const std::vector<Vec3>& points, const std::vector<std::vector<int>>& faces) {
  std::map<std::pair<int, int>, int> edges;
  Vec3 area = Vec3::Zero();
  double volume = 0.0;
  for (const std::vector<int>& f : faces) {
    const FaceGeometry g = polygon_geometry(points, std::vector<Index>(f.begin(), f.end()));
    area += g.area_vector;
    for (std::size_t i = 0; i < f.size(); ++i) {
      ++edges[{f[i], f[(i + 1) % f.size()]}];
      const Vec3& a = points[f[i]];
      const Vec3& b = points[f[(i + 1) % f.size()]];
      volume += tet_volume(Vec3::Zero(), a, b, g.centre);
    }
  }
  for (const auto& [e, n] : edges) {
    EXPECT_EQ(n, 1) << "edge " << e.first << "-" << e.second << " used " << n << " times";
    const auto back = edges.find({e.second, e.first});
    EXPECT_TRUE(back != edges.end() && back->second == 1)
        << "edge " << e.first << "-" << e.second << " has no opposite";
  }
  EXPECT_LT(area.norm(), 1e-12);
  return volume;
}

}  // namespace volmesh::test
