#pragma once
// Vector and rotation types used everywhere: Eigen's, under short names; degrees to radians; a
// point seen from above.
#include <numbers>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace bsim {
using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;  // written w x y z in scene files; Eigen stores x y z w

/// rad per degree: `deg * kDegToRad`, the form of the camera, the director and the cue stick.
inline constexpr double kDegToRad = std::numbers::pi / 180.0;
/// `deg` in rad as pi * deg / 180, one rounding fewer than deg * kDegToRad: the form the table's
/// pockets and the preview's orbit were written in, kept so that their numbers stay as they are.
constexpr double radians(double deg) { return deg * std::numbers::pi / 180.0; }

/// `p` on the bed's plane (z = 0): where a point lies on the table seen from above.
inline Vec3 flat(const Vec3& p) { return Vec3(p.x(), p.y(), 0); }
}  // namespace bsim
