// One straight-down camera: a camera without a direction of its own looks straight down, and a
// vertical view has the table's +y at the top of its picture, in the core, the preview, the POV-Ray
// frames and the sound's pan alike.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "pov_frame.h"
#include "shot.h"
#include "sound_mix.h"
#include "view.h"

using namespace bsim;

namespace {

std::unique_ptr<Shot> load(const std::string& camera) {
  const std::string text =
      "cue 0 0\nball 0 -0.6 0.1 0.028575  0.8 0 0  1 0 0 0\n"
      "ball 1 0.2 -0.3 0.028575  0 0 0  1 0 0 0\ncamera\nevent 0 0 0 " +
      camera + "\nendcamera\n";
  ShotResult r = load_shot(text, "down");
  REQUIRE(r.shot);
  return std::move(r.shot);
}

/// A camera on its look point: placed at the centre of the ball it looks at, which never moves.
std::unique_ptr<Shot> camera_on_its_point() { return load("look 0.2 -0.3 0.028575 1"); }

std::string frame_text(const Shot& shot) {
  std::ostringstream out;
  write_pov_frame(shot, 0, 30, out);
  return out.str();
}

}  // namespace

TEST_SUITE("straight-down camera") {
  TEST_CASE("the core's straight-down camera: above its point, looking down, +y up the picture") {
    const CameraPose pose = straight_down_camera(Vec3(0.2, 0.1, 0), 2.5);
    CHECK((pose.location - Vec3(0.2, 0.1, 2.5)).norm() < 1e-15);
    CHECK((pose.look_at - Vec3(0.2, 0.1, 0)).norm() == 0);
    CHECK((view_direction(pose.location, pose.look_at) - straight_down()).norm() < 1e-15);
    CHECK(straight_down() == Vec3(0, 0, -1));
    CHECK(picture_up(straight_down()) == Vec3::UnitY());
    CHECK(picture_up(Vec3(1e-4, 0, -1)) == Vec3::UnitY());  // within 0.06 degrees of vertical
    CHECK(picture_up(Vec3(0.01, 0, -1)) == Vec3::UnitZ());
    // A camera on its look point has no direction: it looks straight down.
    CHECK(view_direction(Vec3(1, 2, 3), Vec3(1, 2, 3)) == straight_down());
  }

  TEST_CASE("the preview draws a camera on its look point as the straight-down camera") {
    const auto shot = camera_on_its_point();
    const ViewCamera view = scripted_view(*shot, 0);
    REQUIRE(view.eye == view.target);
    CHECK(view_up(view) == Vec3::UnitY());
    const Eigen::Matrix4f vp = projection_matrix(view, 16.0 / 9.0) * view_matrix(view);
    REQUIRE(vp.allFinite());
    double x = 0, y = 0;
    REQUIRE(project_to_pixels(vp, Vec3(0.2, -0.3, -1), 160, 90, x, y));  // straight below: the middle
    CHECK(x == doctest::Approx(80));
    CHECK(y == doctest::Approx(45));
    REQUIRE(project_to_pixels(vp, Vec3(0.2, -0.1, -1), 160, 90, x, y));  // +y: up the picture
    CHECK(y < 45);
    REQUIRE(project_to_pixels(vp, Vec3(0.4, -0.3, -1), 160, 90, x, y));  // +x: to the right
    CHECK(x > 80);
  }

  TEST_CASE("POV-Ray gets the same straight-down camera, +y up, for a camera on its look point") {
    const std::string frame = frame_text(*camera_on_its_point());
    CHECK(frame.find("location <0.2, -0.3, 0.028575>") != std::string::npos);
    CHECK(frame.find("look_at <0.2, -0.2999, -0.971425>") != std::string::npos);
  }

  TEST_CASE("a nearly vertical view is turned +y up in POV-Ray, as in the preview") {
    const auto shot = load("hover 0.0001 0 1  0 0 0");
    CHECK(view_up(scripted_view(*shot, 0)) == Vec3::UnitY());
    const std::string frame = frame_text(*shot);
    CHECK(frame.find("location <0.0001, 0.0, 1.0>") != std::string::npos);
    CHECK(frame.find("look_at <0.0001, 0.0001, 0.0>") != std::string::npos);
  }

  TEST_CASE("the sound pans by the straight-down picture too") {
    const Vec3 eye(0.2, 0.1, 1.0);
    const CameraPose on_its_point{eye, eye, false};
    CHECK(view_position(on_its_point, eye + Vec3(0.3, 0, -1), kCameraFovDeg) > 0.1);    // +x: right
    CHECK(view_position(on_its_point, eye + Vec3(-0.3, 0, -1), kCameraFovDeg) < -0.1);  // -x: left
    CHECK(view_position(on_its_point, eye + Vec3(0, 0.3, -1), kCameraFovDeg) == doctest::Approx(0));
    // A nearly vertical camera pans as its picture shows it (+x right), whichever way it leans.
    const CameraPose leaning{Vec3(0, 1e-4, 1), Vec3(0, 0, 0), false};
    CHECK(view_position(leaning, Vec3(0.3, 0, 0), kCameraFovDeg) > 0.1);
  }
}
