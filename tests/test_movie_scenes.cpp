// The scenes that ship: the built-in break and the gallery load cleanly and do what README says.
#include <doctest/doctest.h>

#include "builtin_scene.h"
#include "files.h"
#include "shot.h"
#include "shots.h"
#include "support.h"

using namespace bsim;
using bsim::test::load_clean;

namespace {

std::string scene_file(const std::string& name) { return test::require_file(test::source_path("scenes/" + name)); }

/// The file-order index of the ball painted `number`.
int ball_numbered(const Shot& shot, int number) {
  for (std::size_t i = 0; i < shot.scene.balls.size(); ++i)
    if (shot.scene.balls[i].number == number) return static_cast<int>(i);
  return -1;
}

bool pocketed(const Shot& shot, int ball, int pocket) {
  for (const PocketDrop& d : shot.timeline.pocket_drops())
    if (d.ball == ball && d.pocket == pocket) return true;
  return false;
}

}  // namespace

TEST_SUITE("movie scenes") {
  TEST_CASE("the built-in break is scenes/break.scn: a full rack that scatters, with a follow camera") {
    CHECK(std::string(builtin_scene_text()) == scene_file("break.scn"));
    const auto shot = load_clean(std::string(builtin_scene_text()), "break");
    CHECK(shot->scene.balls.size() == 16);
    int hits = 0;
    for (const Event& e : shot->timeline.events()) hits += e.type == EventType::ball_ball;
    CHECK(hits >= 15);
    bool follows = false;
    for (const CameraShot& c : shot->scene.camera) follows = follows || c.mode == CameraMode::follow;
    CHECK(follows);
  }

  // If the physics changes enough that one of these misses, retune the scene's aim (README names
  // what each one shows).
  TEST_CASE("the gallery: each shot pockets its ball where README says") {
    SUBCASE("a bank: the 3 into the top side pocket") {
      const auto shot = load_clean(scene_file("bank.scn"), "bank");
      CHECK(pocketed(*shot, ball_numbered(*shot, 3), 1));
      bool banked = false;
      for (const Event& e : shot->timeline.events())
        banked = banked || (e.type == EventType::ball_rail && e.balls.front() == ball_numbered(*shot, 3));
      CHECK(banked);
    }
    SUBCASE("a draw shot: the 6 into the top-right corner, the cue ball back past where it was struck") {
      const auto shot = load_clean(scene_file("draw.scn"), "draw");
      CHECK(pocketed(*shot, ball_numbered(*shot, 6), 2));
      const Vec3 start = shot->scene.balls[0].position;
      const Vec3 end = shot->timeline.state(0, shot->timeline.duration()).position;
      const Vec3 aim = shot->scene.balls[0].velocity.normalized();
      CHECK((end - start).dot(aim) < 0.0);
    }
    SUBCASE("a follow shot: the 2 into the bottom-right corner, filmed by a follow camera") {
      const auto shot = load_clean(scene_file("follow.scn"), "follow");
      CHECK(pocketed(*shot, ball_numbered(*shot, 2), 3));
      CHECK(shot->scene.camera.front().mode == CameraMode::follow);
    }
    SUBCASE("a cut: the 5 into the top-right corner") {
      const auto shot = load_clean(scene_file("cut_corner.scn"), "cut_corner");
      CHECK(pocketed(*shot, ball_numbered(*shot, 5), 2));
    }
  }
}
