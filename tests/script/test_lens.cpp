// The lens (core/script/lens.h): its focal length from the field of view, the thin-lens circle of
// confusion against figures worked by hand, the aperture that keeps wide shots sharp and close ones
// soft, and the focus following the camera script: on its subject in a still shot, a little behind a
// move and easing into it, at once after a cut, in movie time in a slowed replay.
#include <doctest/doctest.h>

#include <cmath>

#include "camera_script.h"
#include "lens.h"

using namespace bsim;

namespace {

/// A one-ball scene (ball at rest at the origin) whose shot has events at `times`.
struct Fixture {
  Scene scene;
  Timeline timeline;

  explicit Fixture(const std::vector<double>& times) {
    Ball ball;
    ball.position = Vec3(0, 0, scene.physics.ball_radius);
    scene.balls.push_back(ball);
    scene.rails = standard_rails();
    scene.pockets = standard_pockets();
    BallState rest;
    rest.position = ball.position;
    std::vector<Event> events;
    for (std::size_t i = 0; i < times.size(); ++i) {
      Event e;
      e.index = static_cast<int>(i);
      e.time = times[i];
      e.type = i == 0 ? EventType::start : i + 1 == times.size() ? EventType::end : EventType::ball_rail;
      events.push_back(e);
    }
    timeline = Timeline(scene, {{MotionSegment{0, rest, -1}}}, events, {});
  }

  /// A camera `distance` m from the origin along -y, looking at it, from event `event` on.
  void hover(int event, double pre, double post, double distance) {
    CameraShot shot;
    shot.event = event;
    shot.pre = pre;
    shot.post = post;
    shot.mode = CameraMode::hover;
    shot.location = Vec3(0, -distance, 0);
    shot.target = Vec3(0, 0, 0);
    scene.camera.push_back(shot);
  }

  CameraScript build() {
    std::vector<Diagnostic> diagnostics;
    auto script = CameraScript::build(scene, timeline, diagnostics);
    REQUIRE(diagnostics.empty());
    REQUIRE(script);
    return *script;
  }
};

}  // namespace

TEST_SUITE("lens") {
  TEST_CASE("the focal length gives the camera's field of view on a 36 mm sensor") {
    // 18 mm / tan(27.5 degrees) = 18 / 0.520567 = 34.578 mm (look.md rounds it to 34.6).
    CHECK(focal_length_mm(55.0) == doctest::Approx(34.578).epsilon(1e-4));
    CHECK(focal_length_mm(90.0) == doctest::Approx(18.0));
  }

  TEST_CASE("the circle of confusion is the thin lens's, as worked by hand") {
    // f = 34.6 mm, focused at 1.3 m, f/2.8, 1280 pixels across 36 mm. At infinity:
    // c = f^2 / (N (Sf - f)) = 0.0346^2 / (2.8 x 1.2654) = 0.33788 mm = 12.01 pixels.
    const Lens lens{34.6, 2.8, 1.3};
    CHECK(circle_of_confusion_px(lens, 1e12, 1280) == doctest::Approx(12.01).epsilon(0.002));
    // Twice the focus distance: half of that; 0.7 of it (in front): 0.3 / 0.7 of it, and negative.
    CHECK(circle_of_confusion_px(lens, 2.6, 1280) == doctest::Approx(6.007).epsilon(0.002));
    CHECK(circle_of_confusion_px(lens, 0.91, 1280) == doctest::Approx(-5.148).epsilon(0.002));
    CHECK(circle_of_confusion_px(lens, 1.3, 1280) == 0.0);
    // In proportion to the picture's width.
    CHECK(circle_of_confusion_px(lens, 2.6, 320) == doctest::Approx(6.007 / 4).epsilon(0.002));
    // Two stops down (f/5.6), half the blur: look.md's table, 6.0 pixels at infinity.
    CHECK(circle_of_confusion_px({34.6, 5.6, 1.3}, 1e12, 1280) == doctest::Approx(6.0).epsilon(0.01));
  }

  TEST_CASE("the aperture keeps a wide shot sharp and opens for a close one") {
    CHECK(aperture_for(0.5) == kOpenAperture);
    CHECK(aperture_for(1.0) == kOpenAperture);
    CHECK(aperture_for(std::sqrt(2.0)) == doctest::Approx(5.6));
    CHECK(aperture_for(3.0) == kClosedAperture);
    const double f = focal_length_mm(55.0);
    // A wide shot focused at 2.5 m: the far wall (6 m) and the near rail (1.5 m) under 1.5 pixels.
    const Lens wide{f, aperture_for(2.5), 2.5};
    CHECK(std::abs(circle_of_confusion_px(wide, 6.0, 1280)) < 1.5);
    CHECK(std::abs(circle_of_confusion_px(wide, 1.5, 1280)) < 1.5);
    // A ball 0.7 m away: the far rail (2.5 m) and the cloth 0.4 m away are well blurred.
    const Lens close{f, aperture_for(0.7), 0.7};
    CHECK(circle_of_confusion_px(close, 2.5, 1280) > 10.0);
    CHECK(circle_of_confusion_px(close, 0.4, 1280) < -10.0);
  }

  TEST_CASE("the focus follows the camera script: on its subject, at once after a cut, eased through a move") {
    // 1 m away until 1 s, cut to 2 m; at 2 s a move over 1.5 to 3 s to 1.5 m; to the end at 5 s.
    Fixture f({0, 1, 2, 5});
    f.hover(0, 0, 0, 1.0);
    f.hover(1, 0, 0, 2.0);
    f.hover(2, 0.5, 1.0 / 3.0, 1.5);
    const CameraScript script = f.build();
    CHECK(focus_target(script.pose(0.5)) == doctest::Approx(1.0));
    CHECK(eased_focus(script, 0.0, 0.0, 1.0) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(eased_focus(script, 0.9, 0.0, 1.0) == doctest::Approx(1.0).epsilon(1e-12));
    // The cut: on the new subject from its first instant, nothing of the old one.
    CHECK(eased_focus(script, 1.0, 0.0, 1.0) == doctest::Approx(2.0).epsilon(1e-12));
    CHECK(eased_focus(script, 1.1, 0.0, 1.0) == doctest::Approx(2.0).epsilon(1e-12));
    // The move from 2 m to 1.5 m: the focus lags behind the subject (still farther) and eases in.
    double previous = 2.0;
    for (double t = 1.55; t < 3.6; t += 0.05) {
      CAPTURE(t);
      const double focus = eased_focus(script, t, 0.0, 1.0), target = focus_target(script.pose(t));
      CHECK(focus >= target - 1e-12);
      CHECK(focus <= previous + 1e-12);  // never back and forth
      previous = focus;
    }
    CHECK(eased_focus(script, 2.25, 0.0, 1.0) - focus_target(script.pose(2.25)) > 0.02);
    // A focus puller's few tenths of a second after the move ends (3 s), on the subject.
    CHECK(eased_focus(script, 3.0 + kFocusPull, 0.0, 1.0) == doctest::Approx(1.5).epsilon(1e-12));
    CHECK(eased_focus(script, 3.0 + 0.5 * kFocusPull, 0.0, 1.0) - 1.5 < 0.01);
  }

  TEST_CASE("the focus eases over movie time: a half-speed replay's pull spans half the simulation time") {
    Fixture f({0, 2, 4});
    f.hover(0, 0, 0, 2.0);
    f.hover(1, 0.5, 0.5, 1.0);  // a move from 1 s to 3 s
    const CameraScript script = f.build();
    const double t = 1.8, target = focus_target(script.pose(t));
    const double plain = eased_focus(script, t, 0.0, 1.0), slowed = eased_focus(script, t, 0.0, 0.5);
    CHECK(plain > slowed);
    CHECK(slowed > target);
    // Nothing from before the stretch of the movie the frame belongs to: a replay starting at 1.7 s
    // is on its subject from its first frame.
    CHECK(eased_focus(script, 1.7, 1.7, 0.5) == doctest::Approx(focus_target(script.pose(1.7))).epsilon(1e-12));
    // The frame's lens: the scene camera's focal length and the aperture for the focus.
    const Lens lens = frame_lens(script, t, 0.0, 1.0);
    CHECK(lens.focus == plain);
    CHECK(lens.focal_mm == focal_length_mm(kCameraFovDeg));
    CHECK(lens.aperture == aperture_for(plain));
  }
}
