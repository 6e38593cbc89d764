#pragma once
// Small polyhedral meshes written by hand for the tests of the cut-cell mesher's late stages
// (the reflex splits, the merging): cells given as outward loops of points, joined where
// they share a face, and the checks those stages promise (validity, volumes, checkMesh's
// verdicts).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/quality/report.hpp"

namespace volmesh::test {

// A 2D point of a prism's profile.
using Xy = std::array<double, 2>;

class HandMesh {
 public:
  // The point at p, made on first use.
  Index point(const Vec3& p) {
    for (Index i = 0; i < static_cast<Index>(points_.size()); ++i)
      if (points_[i] == p) return i;
    points_.push_back(p);
    return static_cast<Index>(points_.size()) - 1;
  }
  // A cell from its faces as outward loops of positions; returns its index.
  Index cell(const std::vector<std::vector<Vec3>>& faces, Index region) {
    std::vector<std::vector<Index>> loops;
    for (const auto& f : faces) {
      std::vector<Index> loop;
      for (const Vec3& p : f) loop.push_back(point(p));
      loops.push_back(std::move(loop));
    }
    cells_.push_back(std::move(loops));
    regions_.push_back(region);
    return static_cast<Index>(cells_.size()) - 1;
  }
  // The prism over a counter-clockwise profile in (x, y), from z0 to z1.
  Index prism(const std::vector<Xy>& profile, double z0, double z1, Index region) {
    std::vector<std::vector<Vec3>> faces(2);
    for (auto it = profile.rbegin(); it != profile.rend(); ++it) faces[0].emplace_back((*it)[0], (*it)[1], z0);
    for (const Xy& p : profile) faces[1].emplace_back(p[0], p[1], z1);
    for (std::size_t i = 0; i < profile.size(); ++i) {
      const Xy& a = profile[i];
      const Xy& b = profile[(i + 1) % profile.size()];
      faces.push_back({{a[0], a[1], z0}, {b[0], b[1], z0}, {b[0], b[1], z1}, {a[0], a[1], z1}});
    }
    return cell(faces, region);
  }
  // The boundary face with these corners gets its own tag (the others: "wall").
  void name_face(const std::vector<Vec3>& corners, const std::string& tag) {
    std::vector<Index> loop;
    for (const Vec3& p : corners) loop.push_back(point(p));
    named_.emplace_back(loop, tag);
  }
  // The box [lo, hi].
  Index box(const Vec3& lo, const Vec3& hi, Index region) {
    return prism({{lo.x(), lo.y()}, {hi.x(), lo.y()}, {hi.x(), hi.y()}, {lo.x(), hi.y()}}, lo.z(), hi.z(), region);
  }

  // The mesh: a loop listed by two cells is one internal face (owned by the first), the
  // others boundary faces tagged "wall". Every point lying inside a side of a loop is put
  // into the loop there, so that the faces around it conform.
  PolyMesh build() const {
    PolyMesh m;
    m.points = points_;
    const Index wall = m.tag_index("wall");
    std::map<std::vector<Index>, Index> face_of;  // sorted loop -> face
    for (Index c = 0; c < static_cast<Index>(cells_.size()); ++c)
      for (const std::vector<Index>& corners : cells_[c]) {
        const std::vector<Index> loop = with_points_on_sides(corners);
        std::vector<Index> key = loop;
        std::sort(key.begin(), key.end());
        if (const auto it = face_of.find(key); it != face_of.end()) {
          m.neighbour[it->second] = c;
          m.face_tag[it->second] = kNoIndex;
        } else {
          face_of.emplace(key, m.add_face(loop, c, kNoIndex, wall));
        }
      }
    for (const auto& [corners, tag] : named_) {
      std::vector<Index> key = with_points_on_sides(corners);
      std::sort(key.begin(), key.end());
      const Index f = face_of.at(key);
      if (m.is_boundary(f)) m.face_tag[f] = m.tag_index(tag);
    }
    m.cell_region = regions_;
    return m;
  }

 private:
  std::vector<Index> with_points_on_sides(const std::vector<Index>& corners) const {
    std::vector<Index> out;
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const Vec3& a = points_[corners[k]];
      const Vec3& b = points_[corners[(k + 1) % corners.size()]];
      out.push_back(corners[k]);
      std::vector<std::pair<double, Index>> on_side;
      for (Index i = 0; i < static_cast<Index>(points_.size()); ++i) {
        const double t = (points_[i] - a).dot(b - a) / (b - a).squaredNorm();
        if (t > 0.0 && t < 1.0 && (a + t * (b - a) - points_[i]).norm() < 1e-14) on_side.emplace_back(t, i);
      }
      std::sort(on_side.begin(), on_side.end());
      for (const auto& [t, i] : on_side) out.push_back(i);
    }
    return out;
  }

  std::vector<Vec3> points_;
  std::vector<std::vector<std::vector<Index>>> cells_;
  std::vector<Index> regions_;
  std::vector<std::pair<std::vector<Index>, std::string>> named_;
};

// What the late stages keep: a valid mesh with the same total and per-region volumes (to
// 1e-12; no point moves, cells are only cut or joined).
inline void expect_valid_with_volumes(const PolyMesh& mesh, const ValidityReport& before) {
  const ValidityReport after = check_validity(mesh);
  EXPECT_TRUE(after.valid()) << (after.problems.empty() ? "" : after.problems.front());
  EXPECT_NEAR(after.total_volume, before.total_volume, 1e-12);
  ASSERT_EQ(after.region_volume.size(), before.region_volume.size());
  for (const auto& [region, volume] : before.region_volume)
    EXPECT_NEAR(after.region_volume.at(region), volume, 1e-12) << "region " << region;
}

// checkMesh's verdict on the mesh: faces it would flag (an inverted face pyramid, skewness
// above 4, non-orthogonality of 90° or more).
inline Index checkmesh_failures(const PolyMesh& mesh) {
  const QualityReport q = mesh_quality(mesh);
  return q.inverted_face_pyramids + q.highly_skewed_faces + q.non_orthogonality_errors;
}

}  // namespace volmesh::test
