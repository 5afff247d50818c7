// Math types used everywhere in grainlab. All quantities are SI (m, kg, s, N, Pa)
// unless a name says otherwise.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>

namespace grainlab {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

using Index = std::int32_t;

}  // namespace grainlab
