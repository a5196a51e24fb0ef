// The cue stick in the picture: how much of a camera's picture it covers (stick_picture_share) and
// what it hides (stick_hides); in a game's movie, that it never fills the picture (the director keeps
// its shooter's view off the line of a stick raised over a cushion, and the stick comes and goes
// without sweeping across the picture), that the ball and pocket played at stay in view at the strike,
// and that the replay's camera sees the stick leave rather than vanish.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "camera_view.h"
#include "cue_geometry.h"
#include "director.h"
#include "files.h"
#include "shot.h"
#include "support.h"

using namespace bsim;

namespace {

/// A stick lying along -x from its tip at the origin.
CuePose stick_along_x() {
  CuePose stick;
  stick.tip = Vec3(0, 0, 0);
  stick.axis = Vec3(-1, 0, 0);
  stick.visible = true;
  return stick;
}

/// The share of the picture a stick seen side-on `distance` m away covers when it spans the picture's
/// width, about `s` m from its tip: the picture's whole width, as tall as the stick is thick.
double side_on_share(double distance, double s) {
  const double half_height = std::tan(0.5 * kCameraFovDeg * kDegToRad) / kPictureAspect;
  const double tall = 2 * stick_radius(s) / (distance * half_height);  // in the picture's -1..1 units
  return 2 * tall / 4;
}

ShotResult load_game(const std::string& name) {
  ShotResult loaded = load_shot(test::require_file(test::source_path("scenes/" + name + ".scn")), name);
  REQUIRE(loaded.scripted());
  return loaded;
}

/// What shot `k` is played at: the ball the struck ball meets first and, unless that meeting is a
/// group collision (a break), the pocket that ball drops into in the shot (or the `pot` line's).
struct PlayedAt {
  int ball = -1, pocket = -1;
};

PlayedAt played_at(const Shot& shot, int k) {
  PlayedAt out;
  const Cue& cue = shot.scene.cues[static_cast<std::size_t>(k)];
  for (const Event& e : shot.timeline.events()) {
    if (e.shot != k || e.type != EventType::ball_ball) continue;
    for (const Contact& c : e.contacts)
      if (c.a == cue.target || c.b == cue.target) out.ball = c.a == cue.target ? c.b : c.a;
    if (out.ball < 0) continue;
    if (cue.aims()) out.pocket = cue.pot_pocket;
    if (out.pocket < 0 && !e.grouped)
      for (const PocketDrop& d : shot.timeline.pocket_drops())
        if (d.ball == out.ball && shot.timeline.shot_at(d.time) == k) {
          out.pocket = d.pocket;
          break;
        }
    break;
  }
  return out;
}

}  // namespace

TEST_SUITE("cue stick in the picture") {
  TEST_CASE("the stick's share of the picture is its outline projected and clipped to the picture") {
    const CuePose stick = stick_along_x();
    // Side-on, looking at its middle from 1 m and from 0.1 m: the picture's width of it, as thick as it is.
    for (const double distance : {1.0, 0.1}) {
      CAPTURE(distance);
      const CameraPose camera{Vec3(-0.735, -distance, 0), Vec3(-0.735, 0, 0), false};
      CHECK(stick_picture_share(stick, camera) == doctest::Approx(side_on_share(distance, 0.735)).epsilon(0.02));
    }
    // Behind the camera: nothing. Looked at along its axis from behind the butt: its butt's round, a
    // little of the picture.
    CHECK(stick_picture_share(stick, {Vec3(1, 0, 0), Vec3(2, 0, 0), false}) == 0);
    const double end_on = stick_picture_share(stick, {Vec3(-1.6, 0, 0.05), Vec3(0, 0, 0), false});
    CHECK(end_on > 0);
    CHECK(end_on < 0.05);
    // A shooter's view low on the line of a stick raised 33 degrees (over a cushion) looks up along
    // it, its butt covering more of the picture than the director allows; the same camera sees the end
    // of a level stick.
    CuePose raised = stick;
    raised.axis = Vec3(-std::cos(33 * kDegToRad), 0, std::sin(33 * kDegToRad));
    const CameraPose shooter{Vec3(-0.8, 0, 0.45), Vec3(0.3, 0, 0), false};
    CHECK(stick_picture_share(raised, shooter) > kDirectorStickShare);
    CuePose level = stick;
    level.axis = Vec3(-std::cos(4 * kDegToRad), 0, std::sin(4 * kDegToRad));
    CHECK(stick_picture_share(level, shooter) < 0.01);
  }

  TEST_CASE("the stick hides a ball behind it, not one beside it, before it or only grazed") {
    const CuePose stick = stick_along_x();
    const CameraPose camera{Vec3(-0.5, -1, 0), Vec3(-0.5, 0, 0), false};
    const double radius = 0.028575;
    CHECK(stick_hides(stick, camera, Vec3(-0.5, 0.5, 0), radius));
    CHECK_FALSE(stick_hides(stick, camera, Vec3(-0.5, 0.5, 0.1), radius));    // seen above it
    CHECK_FALSE(stick_hides(stick, camera, Vec3(-0.5, -0.5, 0), radius));     // nearer than the stick
    CHECK_FALSE(stick_hides(stick, camera, Vec3(-0.5, 0.5, 0.035), radius));  // its edge behind the stick
    CHECK_FALSE(stick_hides(stick, camera, Vec3(0.5, 0.5, 0), radius));       // past the tip
  }

  TEST_CASE(
      "in a game's movie the stick never covers much of the picture, and the ball and pocket played at are seen") {
    if (test::kSanitizedBuild) return;  // whole games: Release builds only
    int raised = 0;
    for (const std::string name : {"game9", "game8"}) {
      CAPTURE(name);
      const ShotResult loaded = load_game(name);
      const Shot& shot = *loaded.shot;
      const double radius = shot.scene.physics.ball_radius;
      for (const CueStroke& stroke : shot.cue->strokes()) {
        CAPTURE(stroke.shot + 1);
        CAPTURE(stroke.elevation_deg());
        if (stroke.elevation_deg() >= 20) ++raised;
        // Every instant it is drawn, from its approach to its removal (the director looks at its picture
        // at 30 Hz: a little more may fall between its looks).
        double most = 0;
        for (double t = stroke.start; t < stroke.hide_time; t += 1.0 / 60) {
          const CuePose stick = shot.cue->pose(t);
          if (stick.visible) most = std::max(most, stick_picture_share(stick, shot.camera->pose(t)));
        }
        CHECK(most <= kDirectorStickShare + 0.005);
        // At the strike, the ball played at and its pocket in the picture, neither behind the stick.
        const PlayedAt played = played_at(shot, stroke.shot);
        const CameraPose camera = shot.camera->pose(stroke.cue_time);
        const CuePose stick = shot.cue->pose(stroke.cue_time);
        if (played.ball >= 0) {
          const Vec3 ball = shot.timeline.state(played.ball, stroke.cue_time).position;
          CHECK(CameraView(camera).contains(ball, 0.02));
          CHECK_FALSE(stick_hides(stick, camera, ball, radius));
        }
        if (played.pocket >= 0) {
          const Vec3 pocket = shot.scene.pockets[static_cast<std::size_t>(played.pocket)].center;
          CHECK(CameraView(camera).contains(pocket));
          CHECK_FALSE(stick_hides(stick, camera, pocket, radius));
        }
      }
    }
    // The games have strokes raised over a cushion, which a camera on the line of aim would look along
    // (game9's 8th at 33 degrees, game8's 2nd at 39).
    CHECK(raised >= 2);
  }

  TEST_CASE("the replay's camera sees the stick leave: it is removed only once out of the replay's view too") {
    if (test::kSanitizedBuild) return;  // a whole game: Release builds only
    const ShotResult loaded = load_game("game9");
    const Shot& shot = *loaded.shot;
    REQUIRE(shot.replay_camera);
    constexpr int kFps = 30;
    int shown = 0, removed = 0;
    bool was_visible = false;
    for (int k = 0; k < shot.movie.frame_count(kFps); ++k) {
      const MovieFrame frame = shot.movie.frame(k, kFps);
      if (!frame.replay) continue;
      CAPTURE(k);
      const CuePose stick = shot.cue->pose(frame.time);  // placed where it would be, visible or not
      const CameraPose camera = shot.replay_camera->pose(frame.time);
      if (stick.visible) {
        ++shown;
        CHECK(stick_picture_share(stick, camera) <= kDirectorStickShare + 0.005);
      } else if (was_visible) {
        ++removed;
        CHECK_FALSE(stick_in_view(stick, camera));
      }
      was_visible = stick.visible;
    }
    // The replay shows the strike, then the stick leaving.
    CHECK(shown > 0);
    CHECK(removed == 1);
  }
}
