// The scenes that ship: the built-in break and the gallery load cleanly and do what README says.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

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

/// (ball, pocket) of each drop in shot `k` (from 0), in time order.
std::vector<std::pair<int, int>> drops_in(const Shot& shot, int k) {
  const ShotSpan& span = shot.timeline.shots().at(static_cast<std::size_t>(k));
  std::vector<std::pair<int, int>> out;
  for (const PocketDrop& d : shot.timeline.pocket_drops())
    if (d.time >= span.cue && d.time <= span.rest) out.emplace_back(d.ball, d.pocket);
  return out;
}

/// The struck ball's first ball-ball contact in shot `k`: the ball it meets (file-order index), or -1.
int first_ball_met(const Shot& shot, int k, int struck) {
  for (const Event& e : shot.timeline.events()) {
    if (e.shot != k || e.type != EventType::ball_ball) continue;
    for (const Contact& c : e.contacts)
      if (c.a == struck || c.b == struck) return c.a == struck ? c.b : c.a;
    if (e.balls.size() == 2 && (e.balls[0] == struck || e.balls[1] == struck))
      return e.balls[0] == struck ? e.balls[1] : e.balls[0];
  }
  return -1;
}

/// Degrees by which the cue ball's way from its hit on the object ball in shot `k` to its first cushion
/// runs forward of the tangent line (negative: behind it, drawn back).
double forward_of_tangent(const Shot& shot, int k) {
  const Timeline& timeline = shot.timeline;
  double hit = -1, cushion = -1;
  for (const Event& e : timeline.events()) {
    if (e.shot != k) continue;
    if (hit < 0 && e.type == EventType::ball_ball) hit = e.time;
    if (hit >= 0 && cushion < 0 && e.type == EventType::ball_rail && e.balls.front() == 0) cushion = e.time;
  }
  REQUIRE(hit >= 0);
  REQUIRE(cushion > hit);
  const Vec3 object = timeline.state(1, hit + 0.02).velocity.normalized();
  const Vec3 way = (timeline.state(0, cushion).position - timeline.state(0, hit).position).normalized();
  return std::asin(std::clamp(way.dot(object), -1.0, 1.0)) * 180 / std::numbers::pi;
}

bool meets_jaw(const Shot& shot, int ball, int pocket) {
  for (const Event& e : shot.timeline.events())
    if (e.type == EventType::ball_jaw && e.balls.front() == ball && e.pocket == pocket) return true;
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
    // README's story: the 10 drops in the bottom-right corner; the 4 rattles in the bottom side
    // pocket's jaws and the 1 clips them, and both stay up.
    CHECK(pocketed(*shot, ball_numbered(*shot, 10), 3));
    for (const int number : {4, 1}) {
      CAPTURE(number);
      CHECK(meets_jaw(*shot, ball_numbered(*shot, number), 4));
      for (const PocketDrop& d : timeline.pocket_drops()) CHECK(d.ball != ball_numbered(*shot, number));
    }
    bool follows = false;
    for (const CameraShot& c : scene.camera) follows = follows || c.mode == CameraMode::follow;
    CHECK(follows);
  }

  TEST_CASE("the run of shots: a 9-ball break, then the table cleared lowest ball first, one ball a shot") {
    const auto shot = load_clean(scene_file("runout.scn"), "runout");
    const Scene& scene = shot->scene;
    REQUIRE(scene.shot_count() == 7);
    REQUIRE(shot->timeline.shot_count() == 7);
    // The break (the scene's comment): the 6 and the 2 into the bottom-right corner, the 7 into the top
    // side pocket; the 1 rattles in the bottom-left corner's jaws and stays out.
    const auto broke = drops_in(*shot, 0);
    const auto dropped = [&](int number, int pocket) {
      return std::count(broke.begin(), broke.end(), std::pair{ball_numbered(*shot, number), pocket}) == 1;
    };
    CHECK(broke.size() == 3);
    CHECK(dropped(6, 3));
    CHECK(dropped(2, 3));
    CHECK(dropped(7, 1));
    CHECK(meets_jaw(*shot, ball_numbered(*shot, 1), 5));
    // Each later shot meets the lowest ball on the table first and pots it, and nothing else, where its
    // line says; the 9 goes last.
    std::vector<int> up;
    for (int i = 1; i < static_cast<int>(scene.balls.size()); ++i)
      if (std::none_of(broke.begin(), broke.end(), [&](const auto& d) { return d.first == i; })) up.push_back(i);
    for (int k = 1; k < 7; ++k) {
      CAPTURE(k + 1);
      const Cue& cue = scene.cues[static_cast<std::size_t>(k)];
      REQUIRE(cue.aims());
      REQUIRE(!up.empty());
      const int lowest = *std::min_element(up.begin(), up.end(), [&](int a, int b) {
        return scene.balls[static_cast<std::size_t>(a)].number < scene.balls[static_cast<std::size_t>(b)].number;
      });
      CHECK(cue.pot_ball == lowest);
      CHECK(first_ball_met(*shot, k, 0) == cue.pot_ball);
      CHECK(drops_in(*shot, k) == std::vector<std::pair<int, int>>{{cue.pot_ball, cue.pot_pocket}});
      up.erase(std::find(up.begin(), up.end(), cue.pot_ball));
    }
    CHECK(up.empty());
    CHECK(scene.cues.back().pot_ball == ball_numbered(*shot, 9));
  }

  TEST_CASE("the drill: the same cut three times, the cue ball sent off the tangent line three ways, never down") {
    const auto shot = load_clean(scene_file("drill.scn"), "drill");
    REQUIRE(shot->timeline.shot_count() == 3);
    for (int k = 0; k < 3; ++k) {
      CAPTURE(k + 1);
      CHECK(drops_in(*shot, k) == std::vector<std::pair<int, int>>{{1, 2}});
    }
    // At centre it slides at the hit and leaves close to the tangent line, a little forward of it; with
    // draw it comes back behind the line; with follow it rolls on well forward of it.
    const double centre = forward_of_tangent(*shot, 0), draw = forward_of_tangent(*shot, 1),
                 follow = forward_of_tangent(*shot, 2);
    MESSAGE("forward of the tangent line: centre " << centre << ", draw " << draw << ", follow " << follow
                                                   << " degrees");
    CHECK(centre > 5);
    CHECK(centre < 20);
    CHECK(draw < -15);
    CHECK(follow > 25);
    CHECK(follow > centre + 10);
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
