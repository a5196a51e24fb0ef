#include "view.h"

#include <cmath>
#include <numbers>

#include "shot.h"

namespace bsim {

ViewCamera scripted_view(const Shot& shot, double t) {
  // Without a script: the straight-down camera 1 m over the table's middle.
  const CameraPose pose = shot.camera ? shot.camera->pose(t) : straight_down_camera(Vec3(0, 0, 0), 1.0);
  ViewCamera view;
  view.eye = pose.location;
  view.target = pose.look_at;
  return view;
}

Vec3 view_up(const ViewCamera& camera) { return picture_up(view_direction(camera.eye, camera.target)); }

CameraView camera_view(const ViewCamera& camera, double aspect) {
  CameraPose pose;
  pose.location = camera.eye;
  pose.look_at = camera.target;
  return CameraView(pose, camera.hfov_deg, aspect);
}

double vertical_fov_deg(double hfov_deg, double aspect) {
  const double half = hfov_deg * std::numbers::pi / 360.0;
  return 2.0 * std::atan(std::tan(half) / aspect) * 180.0 / std::numbers::pi;
}

Eigen::Matrix4f view_matrix(const ViewCamera& camera) {
  const CameraView view = camera_view(camera, 1.0);
  const Vec3 &forward = view.forward(), &right = view.right(), &up = view.up();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = right.transpose();
  m.block<1, 3>(1, 0) = up.transpose();
  m.block<1, 3>(2, 0) = -forward.transpose();
  m(0, 3) = -right.dot(camera.eye);
  m(1, 3) = -up.dot(camera.eye);
  m(2, 3) = forward.dot(camera.eye);
  return m.cast<float>();
}

Eigen::Matrix4f projection_matrix(const ViewCamera& camera, double aspect) {
  const CameraView view = camera_view(camera, aspect);
  const double half_width = view.half_width(), half_height = view.half_height();
  const double n = kNearClip, f = kFarClip;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = 1.0 / half_width;
  p(1, 1) = 1.0 / half_height;
  p(2, 2) = -(f + n) / (f - n);
  p(2, 3) = -2.0 * f * n / (f - n);
  p(3, 2) = -1.0;
  return p.cast<float>();
}

bool project_to_pixels(const Eigen::Matrix4f& view_projection, const Vec3& point, double width, double height,
                       double& x, double& y) {
  const Eigen::Vector4f clip =
      view_projection * Eigen::Vector4f(float(point.x()), float(point.y()), float(point.z()), 1.f);
  if (clip.w() <= float(kNearClip)) return false;
  x = (clip.x() / clip.w() * 0.5 + 0.5) * width;
  y = (0.5 - clip.y() / clip.w() * 0.5) * height;
  return true;
}

}  // namespace bsim
