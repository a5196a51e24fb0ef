#include "camera_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "camera_interpolation.h"

namespace bsim {

namespace {
/// Horizontal over total length of a view direction below which it counts as vertical: about 0.06
/// degrees, where a z-up picture frame degenerates (and POV-Ray's look_at would too).
constexpr double kVerticalView = 1e-3;
/// m ahead of the eye below which a point has no place in the picture.
constexpr double kNearest = 1e-6;
}  // namespace

Vec3 straight_down() { return Vec3(0, 0, -1); }

CameraPose straight_down_camera(const Vec3& look_at, double height) {
  CameraPose pose;
  pose.look_at = look_at;
  pose.location = look_at - height * straight_down();
  return pose;
}

Vec3 view_direction(const Vec3& location, const Vec3& look_at) { return unit_or(location, look_at, straight_down()); }

Vec3 picture_up(const Vec3& direction) {
  if (std::hypot(direction.x(), direction.y()) <= kVerticalView * direction.norm()) return Vec3::UnitY();
  return Vec3::UnitZ();
}

CameraView::CameraView(const CameraPose& pose, double hfov_deg, double aspect)
    : eye_(pose.location),
      forward_(view_direction(pose.location, pose.look_at)),
      right_(forward_.cross(picture_up(forward_)).normalized()),  // forward x up points to the picture's right
      up_(right_.cross(forward_)),
      hfov_deg_(hfov_deg),
      aspect_(aspect),
      half_width_(std::tan(0.5 * hfov_deg * kDegToRad)) {}

CameraView::CameraView(const CameraPose& pose, HalfWidth half_width, double aspect)
    : eye_(pose.location),
      forward_(view_direction(pose.location, pose.look_at)),
      right_(forward_.cross(picture_up(forward_)).normalized()),
      up_(right_.cross(forward_)),
      hfov_deg_(2 * std::atan(half_width.tangent) / kDegToRad),  // for pan() alone
      aspect_(aspect),
      half_width_(half_width.tangent) {}

std::optional<PicturePoint> CameraView::project(const Vec3& p) const {
  const Vec3 d = p - eye_;
  const double ahead = d.dot(forward_);
  if (ahead <= kNearest) return std::nullopt;
  return PicturePoint{d.dot(right_) / ahead / half_width_, d.dot(up_) / ahead / half_height()};
}

Vec3 CameraView::ray(const PicturePoint& at) const {
  return (forward_ + at.x * half_width_ * right_ + at.y * half_height() * up_).normalized();
}

bool CameraView::contains(const Vec3& p, double margin) const {
  const std::optional<PicturePoint> at = project(p);
  const double limit = 1.0 - 2.0 * margin;
  return at && std::abs(at->x) <= limit && std::abs(at->y) <= limit;
}

double CameraView::pan(const Vec3& p) const {
  const Vec3 d = p - eye_;
  const double across = d.dot(right_), ahead = d.dot(forward_);
  const double half = hfov_deg_ * std::numbers::pi / 360.0;
  const double angle = std::atan2(across, std::max(ahead, 0.0));
  return std::clamp(angle / half, -1.0, 1.0);
}

double CameraView::cone_half_angle_deg() const {
  // The picture's corner for a square aspect: horizontal half-angle widened by sqrt(2).
  return std::atan(half_width_ * std::numbers::sqrt2) / kDegToRad;
}

bool CameraView::in_cone(const Vec3& p, double half_angle_deg) const {
  const Vec3 w = p - eye_;
  const double ahead = w.dot(forward_);
  if (ahead <= 0) return false;
  const double off_axis = std::atan2(w.cross(forward_).norm(), ahead);
  return off_axis < half_angle_deg * kDegToRad;
}

PicturePoint picture_point(double x, double y, double width, double height) {
  return {2 * x / width - 1, 1 - 2 * y / height};
}

}  // namespace bsim
