// The scenes that ship: the built-in break and the gallery load cleanly and do what README says.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "builtin_scene.h"
#include "energy.h"
#include "files.h"
#include "motion.h"
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
  TEST_CASE("the built-in break is scenes/break.scn: a real rack broken at 10.7 m/s that opens, with a follow camera") {
    CHECK(std::string(builtin_scene_text()) == scene_file("break.scn"));
    const auto shot = load_clean(std::string(builtin_scene_text()), "break");
    const Scene& scene = shot->scene;
    const Timeline& timeline = shot->timeline;
    REQUIRE(scene.balls.size() == 16);
    // A real rack: every object ball within a few tenths of a millimetre of a neighbour, none overlapping.
    const double R = scene.physics.ball_radius;
    for (std::size_t i = 1; i < 16; ++i) {
      double nearest = 1e9;
      for (std::size_t j = 1; j < 16; ++j)
        if (j != i) nearest = std::min(nearest, (scene.balls[i].position - scene.balls[j].position).norm());
      CHECK(nearest >= 2 * R - 1e-12);
      CHECK(nearest < 2 * R + 0.5e-3);
    }
    // A real break speed (pros average 10.7 m/s).
    const double speed = scene.balls[0].velocity.norm();
    CHECK(speed >= 8.0);
    CHECK(speed <= 11.0);
    // The cue ball meets the rack in one group collision of the balls that touch or nearly touch (a
    // ball with a wider gap joins later), and no ball takes half the rack's energy.
    const Event* hit = nullptr;
    for (const Event& e : timeline.events())
      if (!hit && e.type == EventType::ball_ball) hit = &e;
    REQUIRE(hit);
    CHECK(hit->balls.size() >= 12);
    CHECK(hit->contacts.size() >= 15);
    double rack = 0, largest = 0;
    for (std::size_t k = 0; k < hit->balls.size(); ++k) {
      if (hit->balls[k] == 0) continue;
      const double energy = kinetic_energy(hit->after[k], scene.physics);
      rack += energy;
      largest = std::max(largest, energy);
    }
    MESSAGE("largest share of the rack's energy: " << largest / rack);
    CHECK(largest < 0.5 * rack);
    // At least 12 of the 15 object balls travel more than 0.3 m.
    int travelled = 0;
    for (int i = 1; i < 16; ++i) {
      double distance = 0;
      Vec3 last = timeline.state(i, timeline.cue_time()).position;
      for (double t = timeline.cue_time(); t <= timeline.duration(); t += 0.002) {
        const Vec3 p = timeline.state(i, t).position;
        distance += std::hypot(p.x() - last.x(), p.y() - last.y());
        last = p;
      }
      travelled += distance > 0.3;
    }
    MESSAGE(travelled << " of 15 object balls travel more than 0.3 m");
    CHECK(travelled >= 12);
    // Balls drop, and the cue ball stays on the table.
    CHECK(!timeline.pocket_drops().empty());
    for (const PocketDrop& d : timeline.pocket_drops()) CHECK(d.ball != 0);
    CHECK(pocketed(*shot, ball_numbered(*shot, 1), 4));
    bool follows = false;
    for (const CameraShot& c : scene.camera) follows = follows || c.mode == CameraMode::follow;
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
