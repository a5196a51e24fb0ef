#include "camera_interpolation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bsim {

namespace {
/// rad; below this two directions count as the same (or as opposite).
constexpr double kParallelAngle = 1e-9;
}  // namespace

double smooth(double u) {
  u = std::clamp(u, 0.0, 1.0);
  if (u < 0.5) return 2.0 * u * u;
  const double w = u - 1.0;
  return 1.0 - 2.0 * w * w;
}

Vec3 bezier(const Vec3& p0, const Vec3& p_mid, const Vec3& p1, double u) {
  const double v = 1.0 - u;
  return v * v * p0 + 2.0 * u * v * p_mid + u * u * p1;
}

Vec3 slerp_unit(const Vec3& a, const Vec3& b, double u) {
  const Vec3 cross = a.cross(b);
  const double sine = cross.norm();
  const double angle = std::atan2(sine, a.dot(b));
  if (angle < kParallelAngle) return a;
  Vec3 axis;
  if (sine > kParallelAngle) {
    axis = cross / sine;
  } else {
    // Opposite directions: any perpendicular axis works; turning about the vertical pans the view,
    // which looks more natural than rolling over, unless the view itself is vertical.
    const Vec3 up(0, 0, 1);
    axis = up - up.dot(a) * a;
    if (axis.norm() < 1e-6) axis = Vec3(1, 0, 0) - a.x() * a;
    axis.normalize();
  }
  return (Eigen::AngleAxisd(u * angle, axis) * a).normalized();
}

Vec3 unit_or(const Vec3& from, const Vec3& to, const Vec3& fallback) {
  const Vec3 d = to - from;
  const double n = d.norm();
  // 1e-12 m: far below anything visible, far above rounding noise of table-sized coordinates.
  if (!(n > 1e-12)) return fallback;
  return d / n;
}

}  // namespace bsim
