#pragma once
// The one camera model of every picture (POV-Ray's frames, the preview), the sound's pan, the
// director's framing and the cue stick's leaving the picture: a pose, the horizontal field of view
// and the picture's aspect; where a point lands in the picture, which way a point of the picture
// looks, and whether a point is in it.
#include <optional>

#include "vec.h"

namespace bsim {

/// Horizontal field of view of the scene camera in degrees, the same for POV-Ray and the GL preview.
inline constexpr double kCameraFovDeg = 55.0;
/// The picture's width over its height: 16:9, as the movie and the preview.
inline constexpr double kPictureAspect = 16.0 / 9.0;

struct CameraPose {
  Vec3 location{0, 0, 0};  ///< m
  Vec3 look_at{0, 0, 0};   ///< m, the point at the centre of the view
  bool interpolating = false;
};

// The straight-down camera: the one fallback for every camera that has no direction of its own (no
// script to ask, a camera sitting on its look point) and the one orientation of every view too near
// vertical for z to be its picture's up. It looks straight down at the bed with the table's +y at
// the top of its picture and +x to the right, in the preview, the POV-Ray frames and the sound's pan.

/// The straight-down view direction, -z.
Vec3 straight_down();
/// The straight-down camera `height` m above `look_at`.
CameraPose straight_down_camera(const Vec3& look_at, double height);
/// The unit direction a camera at `location` looks in: towards `look_at`, or straight down where
/// the two (nearly) coincide.
Vec3 view_direction(const Vec3& location, const Vec3& look_at);
/// The picture's up for a view along `direction`: +z, or the straight-down camera's +y within about
/// 0.06 degrees of vertical (looking down or up), where z cannot serve.
Vec3 picture_up(const Vec3& direction);

/// A place in the picture: x to the right, y up, each -1 at one edge and 1 at the other (0 0 is
/// the centre).
struct PicturePoint {
  double x = 0, y = 0;
};

/// A camera pose with its lens: the picture's frame (forward, right, up) and its extent.
class CameraView {
 public:
  explicit CameraView(const CameraPose& pose, double hfov_deg = kCameraFovDeg, double aspect = kPictureAspect);
  /// The tangent of half the horizontal field of view (a lens's half sensor width over its focal length).
  struct HalfWidth {
    double tangent = 0;
  };
  /// The same camera from that tangent instead of the angle: no trigonometric function is called, so
  /// the develop stage gets the same view on every machine.
  CameraView(const CameraPose& pose, HalfWidth half_width, double aspect);

  const Vec3& eye() const { return eye_; }
  const Vec3& forward() const { return forward_; }  ///< unit, view_direction()
  const Vec3& right() const { return right_; }      ///< unit, the picture's right
  const Vec3& up() const { return up_; }            ///< unit, the picture's up (picture_up() made square)
  double aspect() const { return aspect_; }
  /// The tangent of half the horizontal field of view: the picture's half width at 1 m ahead.
  double half_width() const { return half_width_; }
  double half_height() const { return half_width_ / aspect_; }

  /// m, how far ahead of the camera `p` lies along its view (negative behind it).
  double depth(const Vec3& p) const { return (p - eye_).dot(forward_); }
  /// Where `p` lands in the picture (outside -1..1 when it is beside the picture); none when it is
  /// not in front of the camera.
  std::optional<PicturePoint> project(const Vec3& p) const;
  /// The unit direction from the eye through `at`: project() of any point on it ahead gives `at`.
  Vec3 ray(const PicturePoint& at) const;
  /// Whether `p` is in front of the camera and inside the picture, at least `margin` of the
  /// picture's width and height inside its edges.
  bool contains(const Vec3& p, double margin = 0) const;
  /// Where `p` is across the picture for the sound's pan: its horizontal angle off the view over half
  /// the field of view, -1 (left edge) to 1 (right edge), clamped; behind the camera, at its side.
  double pan(const Vec3& p) const;
  /// Half-angle, degrees, of the cone around the view that holds the picture's corners for a square
  /// aspect, so the whole picture for any aspect from square to wide.
  double cone_half_angle_deg() const;
  /// Whether `p` is ahead of the camera within `half_angle_deg` of its view direction.
  bool in_cone(const Vec3& p, double half_angle_deg) const;

 private:
  Vec3 eye_, forward_, right_, up_;
  double hfov_deg_, aspect_, half_width_;
};

/// A pixel (origin top-left, y down, of a `width` x `height` picture) as a place in the picture.
PicturePoint picture_point(double x, double y, double width, double height);

}  // namespace bsim
