// The camera script on hand-made timelines: segments, the seed's window arithmetic, continuity,
// cuts, touching and overlapping windows, event 65535, the default camera, validation messages.
#include <doctest/doctest.h>
#include <cmath>
#include <limits>

#include "camera_interpolation.h"
#include "camera_script.h"

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

  CameraShot& hover(int event, double pre, double post, Vec3 location, Vec3 target, int line = 0) {
    CameraShot shot;
    shot.event = event;
    shot.pre = pre;
    shot.post = post;
    shot.mode = CameraMode::hover;
    shot.location = location;
    shot.target = target;
    shot.loc = {line, 1};
    shot.event_loc = {line, 7};
    scene.camera.push_back(shot);
    return scene.camera.back();
  }

  CameraScript build() {
    std::vector<Diagnostic> diagnostics;
    auto script = CameraScript::build(scene, timeline, diagnostics);
    REQUIRE(diagnostics.empty());
    REQUIRE(script);
    return *script;
  }
};

double distance(const Vec3& a, const Vec3& b) { return (a - b).norm(); }

/// Largest camera move per second between samples `step` apart over [from, to].
double max_speed(const CameraScript& script, double from, double to, double step) {
  double fastest = 0;
  CameraPose previous = script.pose(from);
  for (double t = from + step; t <= to; t += step) {
    const CameraPose pose = script.pose(t);
    if (!std::isfinite(pose.location.norm()) || !std::isfinite(pose.look_at.norm()))
      return std::numeric_limits<double>::infinity();
    fastest = std::max(
        fastest, std::max(distance(pose.location, previous.location), distance(pose.look_at, previous.look_at)) / step);
    previous = pose;
  }
  return fastest;
}

const Vec3 kA(-2, -1, 1.5), kB(2, -1.5, 1), kC(0, 2, 2.5);

}  // namespace

TEST_SUITE("camera_script") {
  TEST_CASE("the seed's example: events at 0, 6, 10 with 2/3 and 3/4 interpolate from 2 to 9") {
    Fixture f({0, 6, 10});
    f.hover(0, 0, 0, kA, Vec3(0, 0, 0));
    f.hover(1, 2.0 / 3.0, 3.0 / 4.0, kB, Vec3(0.5, 0, 0));
    f.hover(2, 0, 0, kC, Vec3(0, 0.3, 0));
    const CameraScript script = f.build();
    REQUIRE(script.windows().size() == 2);
    const CameraWindow& w = script.windows()[0];
    CHECK(w.shot == 1);
    CHECK(w.begin == doctest::Approx(2.0));
    CHECK(w.event_time == 6.0);
    CHECK(w.end == doctest::Approx(9.0));
    CHECK(script.windows()[1].begin == 10.0);
    CHECK(script.windows()[1].end == 10.0);

    // Between 0 and 2 the first description, between 9 and 10 the second, exactly.
    for (double t : {0.0, 1.0, 1.99}) {
      const CameraPose pose = script.pose(t);
      CHECK_FALSE(pose.interpolating);
      CHECK(distance(pose.location, kA) == 0);
    }
    for (double t : {2.01, 6.0, 8.99}) CHECK(script.pose(t).interpolating);
    for (double t : {9.01, 9.99}) {
      const CameraPose pose = script.pose(t);
      CHECK_FALSE(pose.interpolating);
      CHECK(distance(pose.location, kB) == 0);
      CHECK(distance(pose.look_at, Vec3(0.5, 0, 0)) == 0);
    }
    CHECK(distance(script.pose(10.0).location, kC) == 0);
    // The window's ends meet the descriptions they blend.
    CHECK(distance(script.pose(2.0).location, kA) < 1e-12);
    CHECK(distance(script.pose(9.0).location, kB) < 1e-12);
  }

  TEST_CASE("inside a window: Bezier look point, Smooth distance, slerped direction") {
    Fixture f({0, 4, 8});
    f.hover(0, 0, 0, Vec3(0, -3, 0), Vec3(0, 0, 0));
    f.hover(1, 0.5, 0.5, Vec3(2, 0, 0), Vec3(1, 0, 0));
    f.hover(2, 0, 0, kC, Vec3(0, 0, 0));
    const CameraScript script = f.build();
    // Window [2, 6], u = 1/2 at the event: look = p0/4 + p2/2 + p1/4; hover's p2 = p1 = (1,0,0).
    const CameraPose middle = script.pose(4.0);
    CHECK(distance(middle.look_at, Vec3(0.75, 0, 0)) < 1e-12);
    // Distances 3 and 1, Smooth(1/2) = 1/2: 2 from the look point, direction halfway from +y to -x.
    CHECK(distance(middle.location, middle.look_at) == doctest::Approx(2.0));
    const Vec3 direction = (middle.look_at - middle.location).normalized();
    CHECK(distance(direction, Vec3(-1, 1, 0).normalized()) < 1e-12);
  }

  TEST_CASE("the camera moves continuously across every window") {
    Fixture f({0, 3, 5, 9, 12});
    f.hover(0, 0, 0, kA, Vec3(0, 0, 0));
    f.hover(1, 0.9, 0.3, kB, Vec3(0.5, 0.2, 0));
    f.hover(3, 0.4, 1.0, kC, Vec3(-0.5, 0, 0));
    f.hover(4, 0.2, 0, Vec3(0, 0, 3), Vec3(0, 0, 0));
    const CameraScript script = f.build();
    // Scene distances are a few metres and windows last seconds: a few m/s at most, at any step.
    CHECK(max_speed(script, 0, 12, 1e-3) < 20);
    for (const CameraWindow& w : script.windows()) {
      CHECK(max_speed(script, w.begin - 0.01, w.begin + 0.01, 1e-6) < 20);
      CHECK(max_speed(script, w.end - 0.01, w.end + 0.01, 1e-6) < 20);
      for (double edge : {w.begin, w.end}) {
        const double e = 1e-9;
        CHECK(distance(script.pose(edge - e).location, script.pose(edge + e).location) < 1e-6);
        CHECK(distance(script.pose(edge - e).look_at, script.pose(edge + e).look_at) < 1e-6);
      }
    }
  }

  TEST_CASE("a straight-down camera blends without NaN, even into its opposite") {
    Fixture f({0, 2, 4});
    f.hover(0, 0, 0, Vec3(0, 0, 3), Vec3(0, 0, 0));
    f.hover(1, 1, 1, Vec3(0, 0, -3), Vec3(0, 0, 0));
    f.hover(2, 1, 0, Vec3(0.1, 0, 3), Vec3(0.1, 0, 0));
    const CameraScript script = f.build();
    CHECK(max_speed(script, 0, 4, 1e-3) < 40);
    CHECK(distance(script.pose(1.0).location, script.pose(1.0).look_at) == doctest::Approx(3.0));
  }

  TEST_CASE("a zero-length window is a cut: no interpolation, no NaN") {
    Fixture f({0, 5, 10});
    f.hover(0, 0, 0, kA, Vec3(0, 0, 0));
    f.hover(1, 0, 0, kB, Vec3(1, 0, 0));
    const CameraScript script = f.build();
    REQUIRE(script.windows().size() == 1);
    CHECK(script.windows()[0].begin == script.windows()[0].end);
    for (double t = 0; t <= 10; t += 0.01) CHECK_FALSE(script.pose(t).interpolating);
    CHECK(distance(script.pose(std::nextafter(5.0, 0.0)).location, kA) == 0);
    CHECK(distance(script.pose(5.0).location, kB) == 0);
  }

  TEST_CASE("touching windows hand over without a jump") {
    Fixture f({0, 4, 8, 12});
    f.hover(0, 0, 0, kA, Vec3(0, 0, 0));
    f.hover(1, 0.5, 0.5, kB, Vec3(1, 0, 0));
    f.hover(2, 0.5, 0.5, kC, Vec3(0, 1, 0));
    const CameraScript script = f.build();
    REQUIRE(script.windows().size() == 2);
    CHECK(script.windows()[0].end == doctest::Approx(6.0));
    CHECK(script.windows()[1].begin == doctest::Approx(6.0));
    for (double t = 2.001; t < 10; t += 0.01) CHECK(script.pose(t).interpolating);
    CHECK(distance(script.pose(6.0).location, kB) < 1e-12);
    CHECK(max_speed(script, 0, 12, 1e-3) < 20);
  }

  TEST_CASE("overlapping windows share the span in the ratio of their fractions") {
    Fixture f({0, 4, 8, 12});
    f.hover(0, 0, 0, kA, Vec3(0, 0, 0));
    f.hover(1, 0.5, 0.75, kB, Vec3(1, 0, 0));
    f.hover(2, 0.25, 0.5, kC, Vec3(0, 1, 0));
    const CameraScript script = f.build();
    REQUIRE(script.windows().size() == 2);
    // 0.75 + 0.25 = 1 just touches at 7; no overlap, nothing changes.
    CHECK(script.windows()[0].end == doctest::Approx(7.0));
    Fixture g({0, 4, 8, 12});
    g.hover(0, 0, 0, kA, Vec3(0, 0, 0));
    g.hover(1, 0.5, 0.75, kB, Vec3(1, 0, 0));
    g.hover(2, 0.75, 0.5, kC, Vec3(0, 1, 0));
    const CameraScript overlapping = g.build();
    CHECK(overlapping.windows()[0].end == doctest::Approx(6.0));
    CHECK(overlapping.windows()[1].begin == doctest::Approx(6.0));
    CHECK(max_speed(overlapping, 0, 12, 1e-3) < 20);
  }

  TEST_CASE("event 65535 is the last event, and times before the first listed event use it") {
    Fixture f({0, 1.5, 4, 7.25});
    f.hover(1, 0, 0, kA, Vec3(0, 0, 0));
    f.hover(CameraShot::kLastEvent, 0.5, 0, kB, Vec3(0, 0, 0));
    const CameraScript script = f.build();
    REQUIRE(script.windows().size() == 1);
    CHECK(script.windows()[0].event_time == 7.25);
    CHECK(script.windows()[0].begin == doctest::Approx(7.25 - 0.5 * (7.25 - 1.5)));
    CHECK(script.windows()[0].end == 7.25);
    CHECK(distance(script.pose(0.0).location, kA) == 0);
    CHECK(distance(script.pose(7.25).location, kB) < 1e-12);
    REQUIRE(script.segments().size() == 2);
    CHECK(script.segments()[0].begin == 0.0);
    CHECK(script.segments()[0].end == 7.25);
    CHECK(script.segments()[1].begin == 7.25);
    // Which description holds: the first from the start (before its event too), the last from its event.
    CHECK(script.shot_at(0.0) == 0);
    CHECK(script.shot_at(1.0) == 0);
    CHECK(script.shot_at(7.2) == 0);
    CHECK(script.shot_at(7.25) == 1);
    CHECK(script.shot_at(100.0) == 1);
  }

  TEST_CASE("a script with no description gets a wide hover over the table") {
    Fixture f({0, 2.5, 6});
    const CameraScript script = f.build();
    REQUIRE(script.shots().size() == 1);
    CHECK(script.shots()[0].mode == CameraMode::hover);
    const CameraPose pose = script.pose(3.0);
    CHECK(distance(pose.look_at, Vec3(0, 0, 0)) < 1e-12);
    CHECK(pose.location.z() > 1.5);
    // The whole table lies inside a 16:9 picture.
    const Vec3 view = (pose.look_at - pose.location).normalized();
    const Vec3 right = view.cross(Vec3::UnitZ()).normalized(), up = right.cross(view);
    const double half_width = std::tan(0.5 * kCameraFovDeg * M_PI / 180), half_height = half_width * 9 / 16;
    for (double x : {-1.27, 1.27})
      for (double y : {-0.635, 0.635}) {
        const Vec3 corner = Vec3(x, y, 0) - pose.location;
        const double ahead = corner.dot(view);
        CHECK(std::abs(corner.dot(right)) / ahead < half_width);
        CHECK(std::abs(corner.dot(up)) / ahead < half_height);
      }
  }

  TEST_CASE("validation: missing events, events out of order, balls out of range") {
    Fixture f({0, 1, 2, 3, 4, 5, 6});
    f.hover(0, 0, 0, kA, Vec3(0, 0, 0), 10);
    f.hover(9, 0, 0, kB, Vec3(0, 0, 0), 11);
    f.hover(5, 0, 0, kB, Vec3(0, 0, 0), 12);
    f.hover(3, 0, 0, kB, Vec3(0, 0, 0), 13);
    f.hover(CameraShot::kLastEvent, 0, 0, kB, Vec3(0, 0, 0), 14);
    f.hover(6, 0, 0, kB, Vec3(0, 0, 0), 15);
    CameraShot& look = f.hover(6, 0, 0, kB, Vec3(0, 0, 0), 16);
    look.mode = CameraMode::follow;
    look.ball = 1;
    look.ball_loc = {16, 23};
    std::vector<Diagnostic> diagnostics;
    CHECK_FALSE(CameraScript::build(f.scene, f.timeline, diagnostics));
    REQUIRE(diagnostics.size() == 5);
    CHECK(diagnostics[0].message == "event 9 does not exist: the shot has 7 events (0 to 6)");
    CHECK(diagnostics[0].loc.line == 11);
    CHECK(diagnostics[0].loc.column == 7);
    CHECK(diagnostics[1].message == "event 3 is listed after event 5: list the camera's events in increasing order");
    CHECK(diagnostics[1].loc.line == 13);
    CHECK(diagnostics[2].message ==
          "event 6 is listed after event 65535 (the last event, 6): list the camera's events in increasing order");
    CHECK(diagnostics[2].loc.line == 15);
    CHECK(diagnostics[3].message == "event 6 is listed after event 6: list the camera's events in increasing order");
    CHECK(diagnostics[3].loc.line == 16);
    CHECK(diagnostics[4].message == "ball 1 does not exist: the scene has 1 ball (index 0)");
    CHECK(diagnostics[4].loc.line == 16);
    CHECK(diagnostics[4].loc.column == 23);
    for (const Diagnostic& d : diagnostics) CHECK(d.severity == Severity::error);
  }
}
