#pragma once
// Basic scalar, index and vector types shared by every module.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cstdint>
#include <limits>

namespace volmesh {

using Vec3 = Eigen::Vector3d;

// 32-bit signed indices: METIS and PETSc on Debian are built with 32-bit idx_t / PetscInt.
using Index = std::int32_t;
inline constexpr Index kNoIndex = -1;
inline constexpr std::int64_t kMaxIndex = std::numeric_limits<Index>::max();

}  // namespace volmesh
