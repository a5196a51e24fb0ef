#pragma once
// Vector and rotation types used everywhere: Eigen's, under short names.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace bsim {
using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;  // written w x y z in scene files; Eigen stores x y z w
}  // namespace bsim
