// hover, look and follow on simulated shots: the follow frame, the heading at rest and through a
// cushion, the heading of a ball before it first moves, a pocketed ball's last visible place.
#include <doctest/doctest.h>
#include <cmath>
#include <string>
#include <vector>

#include "camera_script.h"
#include "files.h"
#include "play.h"
#include "scene_parse.h"
#include "shot.h"
#include "shots.h"
#include "support.h"
#include "tolerance.h"

using namespace bsim;
using bsim::test::load_scene;

namespace {

double distance(const Vec3& a, const Vec3& b) { return (a - b).norm(); }

/// Where a follow camera with offset (back, side, up) in the frame of a ball heading `angle` belongs.
Vec3 follow_location(const Vec3& ball, double angle, const Vec3& offset) {
  const Vec3 ahead(std::cos(angle), std::sin(angle), 0), left(-std::sin(angle), std::cos(angle), 0);
  return ball + offset.x() * ahead + offset.y() * left + offset.z() * Vec3::UnitZ();
}

constexpr double kR = 0.028575;

}  // namespace

TEST_SUITE("camera_modes") {
  TEST_CASE("hover holds its location and point") {
    auto shot = load_scene(
        "cue 0 0\nball 0 -0.5 0 0.028575 0.5 0 0 1 0 0 0\n"
        "camera\nevent 0 0 0 hover -1 -2 1.5 0.2 0.1 0\nendcamera\n");
    for (double t = 0; t <= shot->timeline.duration(); t += 0.25) {
      const CameraPose pose = shot->camera->pose(t);
      CHECK(distance(pose.location, Vec3(-1, -2, 1.5)) == 0);
      CHECK(distance(pose.look_at, Vec3(0.2, 0.1, 0)) == 0);
    }
  }

  TEST_CASE("look keeps its location and looks at the ball wherever it rolls") {
    auto shot = load_scene(
        "cue 0 0\nball 0 -0.5 0 0.028575 0.5 0 0 1 0 0 0\n"
        "camera\nevent 0 0 0 look 0 -2 1 0\nendcamera\n");
    for (double t = 0; t <= shot->timeline.duration(); t += 0.1) {
      const CameraPose pose = shot->camera->pose(t);
      CHECK(distance(pose.location, Vec3(0, -2, 1)) == 0);
      CHECK(distance(pose.look_at, shot->timeline.state(0, t).position) < 1e-12);
    }
    // The ball did move, so the look point did too.
    CHECK(shot->camera->pose(shot->timeline.duration()).look_at.x() > -0.4);
  }

  TEST_CASE("follow: <-1, 0, 1> is one behind and one up, along the cue heading before and after the strike") {
    const double angle = 30 * M_PI / 180;
    auto shot = load_scene(
        "cue 0 30\nball 0 -0.5 -0.2 0.028575 0.3464101615137755 0.2 0 1 0 0 0\n"
        "camera\nevent 0 0 0 follow 0 -1 0 1\nendcamera\n");
    const Vec3 offset(-1, 0, 1);
    const double duration = shot->timeline.duration();
    for (double t = 0; t <= duration; t += 0.05) {
      const Vec3 ball = shot->timeline.state(0, t).position;
      const CameraPose pose = shot->camera->pose(t);
      CHECK(distance(pose.look_at, ball) < 1e-12);
      // Straight-line motion: the heading is the cue's all along, at rest before and after.
      CHECK(distance(pose.location, follow_location(ball, angle, offset)) < 1e-6);
    }
    CHECK(shot->timeline.state(0, duration).velocity.norm() == 0);
  }

  TEST_CASE("follow: before the strike the struck ball faces the cue's heading, not its velocity's") {
    // Velocity 30.5 degrees, heading 30: within the 1 degree that passes without a warning.
    const double v = 0.4, moving = 30.5 * M_PI / 180;
    auto shot = load_scene("cue 0 30\nball 0 -0.5 -0.2 0.028575 " + std::to_string(v * std::cos(moving)) + " " +
                           std::to_string(v * std::sin(moving)) +
                           " 0 1 0 0 0\n"
                           "camera\nevent 0 0 0 follow 0 -1 0 1\nendcamera\n");
    const Vec3 offset(-1, 0, 1);
    const Vec3 start = shot->timeline.state(0, 0).position;
    CHECK(distance(shot->camera->pose(1.0).location, follow_location(start, 30 * M_PI / 180, offset)) < 1e-9);
    const double end = shot->timeline.duration();
    const Vec3 stop = shot->timeline.state(0, end).position;
    CHECK(distance(shot->camera->pose(end).location, follow_location(stop, moving, offset)) < 1e-4);
  }

  TEST_CASE("follow: sideways and ahead offsets turn with the ball") {
    auto shot = load_scene(
        "cue 0 90\nball 0 0 -0.3 0.028575 0 0.4 0 1 0 0 0\n"
        "camera\nevent 0 0 0 follow 0 0.5 -0.25 0.2\nendcamera\n");
    const double t = shot->timeline.cue_time() + 0.5;
    const Vec3 ball = shot->timeline.state(0, t).position;
    // Heading +y: ahead is +y, the right (-0.25 to the left) is +x.
    CHECK(distance(shot->camera->pose(t).location, ball + Vec3(0.25, 0.5, 0.2)) < 1e-6);
  }

  TEST_CASE("follow through a cushion: the camera swings round without jumping and ends behind") {
    auto shot = load_scene(
        "cue 0 0\nball 0 0.9 0 0.028575 1.5 0 0 1 0 0 0\n"
        "camera\nevent 0 0 0 follow 0 -0.5 0 0.3\nendcamera\n");
    bool has_rail = false;
    for (const Event& e : shot->timeline.events()) has_rail |= e.type == EventType::ball_rail;
    REQUIRE(has_rail);
    const double duration = shot->timeline.duration();
    double largest = 0;
    Vec3 previous = shot->camera->pose(0).location;
    for (double t = 1.0 / 240; t <= duration; t += 1.0 / 240) {
      const Vec3 location = shot->camera->pose(t).location;
      REQUIRE(std::isfinite(location.norm()));
      largest = std::max(largest, distance(location, previous));
      previous = location;
    }
    CHECK(largest < 0.06);
    // The camera swings round gently: at least a third of a second from leaving +x to facing -x.
    double left = -1, arrived = -1;
    for (double t = 0; t <= duration && arrived < 0; t += 1.0 / 240) {
      const CameraPose pose = shot->camera->pose(t);
      const double angle = std::atan2(pose.look_at.y() - pose.location.y(), pose.look_at.x() - pose.location.x());
      if (left < 0 && std::cos(angle) < std::cos(10 * M_PI / 180)) left = t;
      if (left >= 0 && std::cos(angle) < -std::cos(10 * M_PI / 180)) arrived = t;
    }
    REQUIRE(left > 0);
    REQUIRE(arrived > 0);
    CHECK(arrived - left > 0.33);
    // At the end the ball rolls toward -x and the camera sits behind it, on the +x side.
    const Vec3 ball = shot->timeline.state(0, duration).position;
    CHECK(distance(shot->camera->pose(duration).location, ball + Vec3(0.5, 0, 0.3)) < 1e-3);
  }

  TEST_CASE("follow: a ball at rest faces where it first goes") {
    auto shot = load_scene(
        "cue 0 0\nball 0 -0.5 0 0.028575 1 0 0 1 0 0 0\nball 1 0 0.03 0.028575 0 0 0 1 0 0 0\n"
        "camera\nevent 0 0 0 follow 1 -1 0 1\nendcamera\n");
    double hit = -1;
    for (const Event& e : shot->timeline.events())
      if (e.type == EventType::ball_ball && hit < 0) hit = e.time;
    REQUIRE(hit > 0);
    const Vec3 first = shot->timeline.state(1, hit + 0.002).velocity;
    REQUIRE(first.norm() > 0.1);
    const double angle = std::atan2(first.y(), first.x());
    const Vec3 ball = shot->timeline.state(1, 0).position;
    CHECK(distance(shot->camera->pose(1.0).location, follow_location(ball, angle, Vec3(-1, 0, 1))) < 2e-3);
    CHECK(distance(shot->camera->pose(hit).location, shot->camera->pose(1.0).location) < 2e-3);
  }

  TEST_CASE("a pocketed ball is watched to its last visible place") {
    auto shot = load_scene(
        "cue 0 42.15\nball 0 0.9 0.3 0.028575 1.1118 1.0067 0 1 0 0 0\n"
        "camera\nevent 0 0 0 look -2 1.5 0.8 0\nendcamera\n");
    REQUIRE(shot->timeline.pocket_drops().size() == 1);
    const double drop = shot->timeline.pocket_drops()[0].time;
    const double duration = shot->timeline.duration();
    const Vec3 last = shot->camera->pose(duration).look_at;
    // Where it sinks out of sight: its centre a radius below the bed (its top level with the cloth),
    // found to well under a nanometre, over the top-right corner's hole.
    CHECK(last.z() == test::near(-kR, 1e-9));
    const Pocket& hole = shot->scene.pockets[2];
    CHECK(distance(Vec3(last.x(), last.y(), 0), hole.center) < hole.radius);
    // It stops there: the same point from shortly after the drop to the end.
    const Vec3 settled = shot->camera->pose(drop + 0.5).look_at;
    CHECK(distance(settled, last) == 0);
    CHECK(shot->timeline.state(0, duration).position.z() < -kR);
  }

  TEST_CASE("the camera tour scene: every mode, windows around events, and no jump anywhere") {
    auto shot = load_scene(test::require_file(test::source_path("scenes/camera_tour.scn")));
    bool hover = false, look = false, follow = false;
    for (const CameraShot& s : shot->camera->shots()) {
      hover |= s.mode == CameraMode::hover;
      look |= s.mode == CameraMode::look;
      follow |= s.mode == CameraMode::follow;
    }
    CHECK((hover && look && follow));
    // The comments in the scene name the events it is written for.
    const auto& events = shot->timeline.events();
    REQUIRE(events.size() == 6);
    CHECK(events[1].type == EventType::cue);
    CHECK(events[2].type == EventType::ball_ball);
    CHECK(events[3].type == EventType::ball_rail);
    CHECK(events[3].balls == std::vector<int>{1});
    CHECK(events[4].type == EventType::ball_rail);
    CHECK(events[4].balls == std::vector<int>{0});
    CHECK(shot->camera->windows().size() == 4);
    // At 30 frames a second the camera never moves more than a few centimetres between frames.
    const double step = 1.0 / 30;
    CameraPose previous = shot->camera->pose(0);
    for (double t = step; t <= shot->timeline.duration(); t += step) {
      const CameraPose pose = shot->camera->pose(t);
      CHECK(distance(pose.location, previous.location) < 0.2);
      CHECK(distance(pose.look_at, previous.look_at) < 0.1);
      previous = pose;
    }
  }

  TEST_CASE("a ball's track is where the timeline says, up to its last visible place") {
    // Spin curves the cue ball's sliding path; the 1-ball is pocketed.
    auto shot = load_scene(
        "cue 0 39.289\nball 0 0.2 -0.3 0.028575 1.5491933 1.2675218 0 1 0 0 0\nspin 0 20 -25 30\n"
        "ball 1 0.75 0.15 0.028575 0 0 0 1 0 0 0\n"
        "camera\nevent 0 0 0 hover 0 -2 2 0 0 0\nendcamera\n");
    REQUIRE(shot->timeline.pocket_drops().size() == 1);
    for (int ball = 0; ball < 2; ++ball) {
      const BallTrack track(shot->timeline, ball, 0.0);
      const double hidden = track.hidden_time();
      CHECK(std::isinf(hidden) == (ball == 0));
      for (double t = 0; t <= shot->timeline.duration(); t += 0.01) {
        const Vec3 expected = shot->timeline.state(ball, std::min(t, hidden)).position;
        CHECK(distance(track.position(t), expected) < 1e-12);
      }
    }
  }

  TEST_CASE("several shots: a ball back on the bed is watched again, and faces each later shot's stick") {
    // Shot 1 sends the cue ball straight into the corner pocket at 46.5 degrees (a scratch); shot 2
    // strikes it from the head spot at 0 degrees into ball 1 (spec.md, "Several shots").
    const std::string text =
        "ball 0 1.0 0.35 0.028575 0 0 0 1 0 0 0\nball 1 0.3 0.0 0.028575 0 0 0 1 0 0 0\n"
        "cue 0 46.5\nstroke 1.5 0 0 0\ncue 0 0\nstroke 2 0 0 0\n";
    ParseResult parsed = parse_scene(text, "scratch");
    REQUIRE(parsed.scene);
    Scene scene = *parsed.scene;
    PlayResult played = play(scene);
    REQUIRE(!played.failure);
    write_found(scene, played.found);
    const Timeline& timeline = played.timeline;
    REQUIRE(timeline.shot_count() == 2);
    REQUIRE(timeline.pocket_drops().size() == 1);
    REQUIRE(timeline.pocket_drops()[0].ball == 0);
    const ShotSpan& second = timeline.shots()[1];
    const BallTrack track(timeline, 0, struck_heading(scene, timeline, 0), later_strikes(scene, timeline, 0));
    // Down in the pocket: its last visible place; back on the head spot: where the timeline has it.
    CHECK(track.hidden_time() > timeline.pocket_drops()[0].time);
    const double down = 0.5 * (track.hidden_time() + second.start);
    REQUIRE(down < second.start);
    CHECK(distance(track.position(down), timeline.motion_state(0, track.hidden_time()).position) < 1e-12);
    for (double t : {second.start + 0.5, second.cue, second.cue + 0.2}) {
      CAPTURE(t);
      CHECK(distance(track.position(t), timeline.motion_state(0, t).position) < 1e-12);
    }
    CHECK(distance(track.position(second.start + 0.5), Vec3(-0.635, 0, kR)) < 1e-9);
    // Before the first strike it faces the first stick (46.5 degrees); resting for the second, the
    // second's (0 degrees), not the way it last rolled; and along its run after it.
    const auto angle_of = [](const Vec3& h) { return std::atan2(h.y(), h.x()) * 180 / std::acos(-1.0); };
    CHECK(angle_of(track.heading(1.0)) == doctest::Approx(46.5).epsilon(1e-9));
    CHECK(std::abs(angle_of(track.heading(second.start + 1.0))) < 1e-9);
    CHECK(std::abs(angle_of(track.heading(second.cue))) < 1e-9);
    CHECK(std::abs(angle_of(track.heading(second.cue + 0.1))) < 0.5);
  }
}
