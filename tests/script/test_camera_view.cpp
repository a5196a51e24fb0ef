// The one camera model: project, ray and contains agree with each other and with the picture the
// front ends draw; the view cone the cue stick leaves holds the picture.
#include <doctest/doctest.h>

#include <cmath>

#include "camera_view.h"

using namespace bsim;

namespace {

CameraPose pose_of(const Vec3& location, const Vec3& look_at) {
  CameraPose pose;
  pose.location = location;
  pose.look_at = look_at;
  return pose;
}

/// Cameras of every kind: oblique, level, straight down (on its look point too), looking up.
const CameraPose kPoses[] = {
    pose_of(Vec3(-1.8, 0.9, 1.4), Vec3(0.3, -0.1, 0)), pose_of(Vec3(0, 0, 0.2), Vec3(2, 1, 0.2)),
    pose_of(Vec3(0.4, 0.2, 2.5), Vec3(0.4, 0.2, 0)),   pose_of(Vec3(0.4, 0.2, 2.5), Vec3(0.4, 0.2, 2.5)),
    pose_of(Vec3(0, 0, 0), Vec3(0.3, 0.2, 4)),
};

const PicturePoint kPlaces[] = {{0, 0}, {0.5, -0.25}, {-0.99, 0.99}, {1, -1}, {-0.3, 0.7}, {2.5, 0.1}};

}  // namespace

TEST_SUITE("camera view") {
  TEST_CASE("a point on the ray through a place of the picture projects back to that place") {
    for (const CameraPose& pose : kPoses) {
      const CameraView view(pose);
      for (const PicturePoint& at : kPlaces)
        for (double distance : {0.01, 1.0, 7.5}) {
          const std::optional<PicturePoint> back = view.project(view.eye() + distance * view.ray(at));
          REQUIRE(back);
          CHECK(back->x == doctest::Approx(at.x).epsilon(1e-12));
          CHECK(back->y == doctest::Approx(at.y).epsilon(1e-12));
        }
    }
  }

  TEST_CASE("the frame is square and right-handed, the ray through the centre is the view") {
    for (const CameraPose& pose : kPoses) {
      const CameraView view(pose);
      CHECK(std::abs(view.forward().dot(view.right())) < 1e-12);
      CHECK(std::abs(view.forward().dot(view.up())) < 1e-12);
      CHECK(std::abs(view.right().dot(view.up())) < 1e-12);
      CHECK((view.right().cross(view.up()) + view.forward()).norm() < 1e-12);
      CHECK((view.ray({0, 0}) - view.forward()).norm() < 1e-15);
      CHECK((view.forward() - view_direction(pose.location, pose.look_at)).norm() == 0);
    }
  }

  TEST_CASE("contains agrees with project: inside the picture by the margin, in front of the camera") {
    for (const CameraPose& pose : kPoses) {
      const CameraView view(pose);
      for (const PicturePoint& at : kPlaces) {
        const Vec3 p = view.eye() + 2.0 * view.ray(at);
        const bool inside = std::abs(at.x) <= 1 && std::abs(at.y) <= 1;
        if (std::abs(at.x) == 1 || std::abs(at.y) == 1) continue;  // on the edge: either, by rounding
        CHECK(view.contains(p) == inside);
        CHECK(view.contains(p, 0.1) == (inside && std::abs(at.x) <= 0.8 && std::abs(at.y) <= 0.8));
        // The same direction behind the camera is never in the picture.
        CHECK_FALSE(view.project(view.eye() - 2.0 * view.ray(at)));
        CHECK_FALSE(view.contains(view.eye() - 2.0 * view.ray(at)));
      }
    }
  }

  TEST_CASE("the picture is kCameraFovDeg across and kPictureAspect wide") {
    const CameraView view(pose_of(Vec3(0, 0, 0), Vec3(1, 0, 0)));
    const double edge = std::tan(0.5 * kCameraFovDeg * kDegToRad);
    CHECK(view.half_width() == edge);
    CHECK(view.half_height() == edge / kPictureAspect);
    // Looking along +x with z up: +y is on the left of the picture.
    CHECK(view.project(Vec3(1, -edge, 0))->x == doctest::Approx(1));
    CHECK(view.project(Vec3(1, 0, edge / kPictureAspect))->y == doctest::Approx(1));
    CHECK(view.pan(Vec3(1, -edge, 0)) > 0.99);
    CHECK(view.pan(Vec3(1, 0.2, 0)) < 0);
  }

  TEST_CASE("a pixel is a place of the picture: corners at -1 and 1, y down the pixels and up the picture") {
    const PicturePoint top_left = picture_point(0, 0, 1280, 720), middle = picture_point(640, 360, 1280, 720);
    CHECK(top_left.x == -1);
    CHECK(top_left.y == 1);
    CHECK(middle.x == 0);
    CHECK(middle.y == 0);
  }

  TEST_CASE("the view cone holds the picture's corners and nothing behind the camera") {
    const CameraView view(pose_of(Vec3(0, 0, 0), Vec3(1, 0, 0)));
    const double cone = view.cone_half_angle_deg();
    CHECK(view.in_cone(Vec3(5, 0, 0), cone));
    CHECK_FALSE(view.in_cone(Vec3(-5, 0, 0), cone));
    // A point at the horizontal edge of the picture is inside; one well beyond the corner is not.
    const double edge = view.half_width();
    CHECK(view.in_cone(Vec3(1, edge * 0.99, 0), cone));
    CHECK(view.in_cone(Vec3(1, edge * 0.99, edge * 0.5), cone));
    CHECK_FALSE(view.in_cone(Vec3(1, 2.0, 0), cone));
    for (const PicturePoint& corner : {PicturePoint{1, 1}, PicturePoint{-1, 1}, PicturePoint{1, -1}})
      CHECK(view.in_cone(view.eye() + view.ray(corner), cone + 1e-9));
    CHECK(cone > 0.5 * kCameraFovDeg);
    CHECK(cone < 60.0);
  }
}
