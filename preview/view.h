#pragma once
// The camera the preview draws from: the scripted camera at time t (the same pose camera.csv and
// the POV-Ray frames use) or a free orbit camera, and the GL matrices for it.
#include <Eigen/Core>

#include "camera_view.h"
#include "vec.h"

namespace bsim {

struct Shot;

struct ViewCamera {
  Vec3 eye{0, 0, 1};
  Vec3 target{0, 0, 0};
  double hfov_deg = kCameraFovDeg;  ///< horizontal, as POV-Ray's `angle`
};

/// Near and far clip distances, m: balls a follow camera hugs stay in, the far end of a room stays in.
inline constexpr double kNearClip = 0.005;
inline constexpr double kFarClip = 40.0;

/// The scripted camera of `shot` at time t.
ViewCamera scripted_view(const Shot& shot, double t);

/// The up vector used for a view: the core's picture_up() (+z, or +y when looking straight down or up).
Vec3 view_up(const ViewCamera& camera);

/// The core's camera model for a view drawn `aspect` wide (width / height).
CameraView camera_view(const ViewCamera& camera, double aspect);

/// Vertical field of view in degrees for a horizontal one at the given width / height.
double vertical_fov_deg(double hfov_deg, double aspect);

Eigen::Matrix4f view_matrix(const ViewCamera& camera);
Eigen::Matrix4f projection_matrix(const ViewCamera& camera, double aspect);

/// A world point in pixels (origin top-left). False when it lies behind the camera.
bool project_to_pixels(const Eigen::Matrix4f& view_projection, const Vec3& point, double width, double height,
                       double& x, double& y);

}  // namespace bsim
