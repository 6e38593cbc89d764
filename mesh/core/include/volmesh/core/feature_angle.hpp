#pragma once
// The sharp-feature threshold the meshers share by default (cutcell's feature points, hexdc's
// creases): a bend of the surface is a sharp edge where the cosine between its two sides'
// normals falls below it. 0.9 is Kobbelt et al.'s θ (about 25.8 degrees).
#include <cmath>
#include <numbers>

namespace volmesh {

inline constexpr double kFeatureCosine = 0.9;

// kFeatureCosine as an angle, for options given in degrees.
inline double feature_angle_degrees() { return std::acos(kFeatureCosine) * 180.0 / std::numbers::pi; }

}  // namespace volmesh
