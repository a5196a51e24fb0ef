#include "camera_interpolation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bsim {

namespace {
/// rad; below this two directions count as the same (or as opposite).
constexpr double kParallelAngle = 1e-9;
/// deg added to the view cone so that a stick half inside the border still counts as seen.
constexpr double kViewMarginDeg = 3.0;
constexpr double kDegToRad = std::numbers::pi / 180.0;
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

double view_cone_half_angle_deg() {
  // The picture's corner for a square aspect: horizontal half-angle widened by sqrt(2).
  const double corner = std::atan(std::tan(0.5 * kCameraFovDeg * kDegToRad) * std::numbers::sqrt2);
  return corner / kDegToRad + kViewMarginDeg;
}

bool in_view(const Vec3& location, const Vec3& look_at, const Vec3& point) {
  const Vec3 view = unit_or(location, look_at, Vec3(1, 0, 0));
  const Vec3 w = point - location;
  const double ahead = w.dot(view);
  if (ahead <= 0) return false;
  const double off_axis = std::atan2(w.cross(view).norm(), ahead);
  return off_axis < view_cone_half_angle_deg() * kDegToRad;
}

}  // namespace bsim
