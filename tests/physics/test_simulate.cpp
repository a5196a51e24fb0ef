// The shot as a timeline: its shape (start, cue, events, end), exact states at any time, ordering of
// simultaneous events, cushion ends, pocket drops, determinism, and physical sanity over random scenes.
#include <doctest/doctest.h>

#include <cmath>

#include "motion.h"
#include "physics_print.h"
#include "play.h"
#include "pocket_fall.h"
#include "random_scenes.h"
#include "shot_checks.h"
#include "simulate.h"
#include "timeline.h"

using namespace bsim;

namespace {

const double kR = PhysicsParams{}.ball_radius;

Scene table_with(std::vector<Ball> balls) {
  Scene scene = scenes::standard_table();
  scene.balls = std::move(balls);
  return scene;
}

Ball ball(int number, double x, double y, double vx = 0, double vy = 0) {
  return scenes::ball_at(number, x, y, PhysicsParams{}, Vec3(vx, vy, 0));
}

std::vector<const Event*> of_type(const Timeline& timeline, EventType type) {
  std::vector<const Event*> out;
  for (const Event& e : timeline.events())
    if (e.type == type) out.push_back(&e);
  return out;
}

}  // namespace

TEST_SUITE("simulate") {
  TEST_CASE(
      "start at 0, all at rest until the cue at kCueLeadTime, end a whole number of seconds after the last rest") {
    const Timeline timeline = simulate(table_with({ball(0, -0.5, 0.1, 1.2, 0.3), ball(3, 0.4, -0.2)}));
    const auto& events = timeline.events();
    REQUIRE(events.size() >= 3);
    CHECK(events.front().type == EventType::start);
    CHECK(events.front().time == 0);
    CHECK(events[1].type == EventType::cue);
    CHECK(events[1].time == kCueLeadTime);
    CHECK(events[1].balls == std::vector<int>{0});
    CHECK(events[1].speed == doctest::Approx(std::hypot(1.2, 0.3)));
    CHECK(timeline.cue_time() == kCueLeadTime);
    CHECK(events.back().type == EventType::end);
    for (std::size_t k = 0; k < events.size(); ++k) {
      CHECK(events[k].index == static_cast<int>(k));
      if (k > 0) CHECK(events[k - 1].time <= events[k].time);
    }
    const double end = timeline.duration();
    CHECK(end == std::floor(end));
    double last_rest = 0;
    for (int i = 0; i < timeline.ball_count(); ++i) last_rest = std::max(last_rest, timeline.segments(i).back().t0);
    CHECK(end >= last_rest + kEndHold);
    CHECK(end < last_rest + kEndHold + kDurationStep);
    for (double t : {0.0, 1.0, kCueLeadTime - 1e-9}) {
      const BallState s = timeline.state(0, t);
      CHECK(s.motion == Motion::stationary);
      CHECK(s.position == Vec3(-0.5, 0.1, kR));
    }
    for (int i = 0; i < timeline.ball_count(); ++i) {
      const BallState s = timeline.state(i, end);
      CHECK(s.velocity.norm() == 0);
      CHECK(s.spin.norm() == 0);
    }
  }

  TEST_CASE("state(t) is the closed form from the segment in force, continuous across events") {
    const Timeline timeline = simulate(table_with({ball(0, -0.8, 0, 2.0, 0.5), ball(1, 0.1, 0.15)}));
    for (int i = 0; i < timeline.ball_count(); ++i) {
      const auto& segments = timeline.segments(i);
      for (std::size_t k = 1; k < segments.size(); ++k) {
        const MotionSegment &previous = segments[k - 1], &next = segments[k];
        if (previous.start.motion == Motion::falling) continue;
        const BallState end = evolve(previous.start, timeline.physics(), next.t0 - previous.t0);
        CHECK((end.position - next.start.position).norm() < 1e-12);
        const double mid = 0.5 * (previous.t0 + next.t0);
        CHECK((timeline.state(i, mid).position - evolve(previous.start, timeline.physics(), mid - previous.t0).position)
                  .norm() == 0);
      }
    }
  }

  TEST_CASE("two hits at one instant are one group event with both contacts, and the balls leave mirrored") {
    // The cue ball meets balls 1 and 2, placed symmetrically about its path, at the same time.
    const double x = 0.3 + std::sqrt(3.0) * kR;
    const Timeline timeline = simulate(table_with({ball(0, -0.3, 0, 1.5, 0), ball(1, x, kR), ball(2, x, -kR)}));
    const auto hits = of_type(timeline, EventType::ball_ball);
    REQUIRE(hits.size() >= 1);
    CHECK(hits[0]->balls == std::vector<int>{0, 1, 2});
    REQUIRE(hits[0]->contacts.size() == 2);
    CHECK(hits[0]->contacts[0].a == 0);
    CHECK(hits[0]->contacts[0].b == 1);
    CHECK(hits[0]->contacts[1].a == 0);
    CHECK(hits[0]->contacts[1].b == 2);
    CHECK(hits[0]->contacts[0].time == hits[0]->contacts[1].time);
    const BallState one = hits[0]->after[1], two = hits[0]->after[2];
    CHECK(one.velocity.y() > 0);
    CHECK(two.velocity.y() < 0);
    // Ball-ball friction acts pair by pair in a fixed order, so the mirror image holds to a part in 1000;
    // without friction it is exact to round-off.
    CHECK(one.velocity.x() == doctest::Approx(two.velocity.x()).epsilon(2e-3));
    CHECK(one.velocity.y() == doctest::Approx(-two.velocity.y()).epsilon(2e-3));
    Scene frictionless = table_with({ball(0, -0.3, 0, 1.5, 0), ball(1, x, kR), ball(2, x, -kR)});
    frictionless.physics.mu_ball = 0;
    const Timeline mirrored = simulate(frictionless);  // kept: the event lives in it
    const Event& hit = *of_type(mirrored, EventType::ball_ball)[0];
    CHECK(hit.after[1].velocity.x() == doctest::Approx(hit.after[2].velocity.x()).epsilon(1e-12));
    CHECK(hit.after[1].velocity.y() == doctest::Approx(-hit.after[2].velocity.y()).epsilon(1e-12));
  }

  TEST_CASE("two hits at one instant on balls far apart are two events, ordered by ball index") {
    // The cue ball and ball 3 run into balls 1 and 2 at the same instant, far from each other.
    const Timeline timeline = simulate(
        table_with({ball(0, -0.6, 0.3, 1.0, 0), ball(1, -0.3, 0.3), ball(2, -0.3, -0.3), ball(3, -0.6, -0.3, 1.0, 0)}));
    const auto hits = of_type(timeline, EventType::ball_ball);
    REQUIRE(hits.size() >= 2);
    CHECK(hits[0]->balls == std::vector<int>{0, 1});
    CHECK(hits[1]->balls == std::vector<int>{2, 3});
    CHECK(hits[0]->time == hits[1]->time);
    CHECK(hits[1]->index == hits[0]->index + 1);
    CHECK_FALSE(hits[0]->grouped);
    REQUIRE(hits[0]->contacts.size() == 1);
    CHECK(hits[0]->contacts[0].time == hits[0]->time);
    CHECK(hits[0]->contacts[0].speed == hits[0]->speed);
  }

  TEST_CASE("a ball at a cut pocket's jaw point strikes the jaw: a ball-jaw event of that pocket") {
    // Just inside the top side pocket's jaw point, the first end of rail 1: its centre 2 mm nearer the
    // pocket's middle than the jaw point, so it meets the jaw's rounding or its facing, not the rail.
    const Scene scene = table_with({ball(0, standard_rails()[1].a.x() - 0.002, 0.3, 0, 1.0)});
    const Timeline timeline = simulate(scene);
    const auto jaws = of_type(timeline, EventType::ball_jaw);
    REQUIRE_FALSE(jaws.empty());
    CHECK(jaws[0]->pocket == 1);
    CHECK(jaws[0]->rail == 1);
    CHECK(of_type(timeline, EventType::ball_rail).empty());
    CHECK(jaws[0]->where.z() == doctest::Approx(kStandardNoseHeight).epsilon(1e-9));
    // On the jaw: within the rounding of the jaw point, or on the facing behind it.
    CHECK(std::abs(jaws[0]->where.x() - standard_rails()[1].a.x()) < 0.01);
    CHECK(jaws[0]->where.y() >= 0.635 - 1e-9);
    CHECK(jaws[0]->after[0].velocity.y() < jaws[0]->before[0].velocity.y());
  }

  TEST_CASE("a ball glancing off a side pocket's jaw and swerving back meets the next rail at its nose, not inside") {
    // The 4 of seeded 9-ball game 396's break, where it stood 40 ms before it reached the bottom side
    // pocket: it glances off the right jaw's rounding 1 mm below the nose level of rail 4 (the left
    // one), crosses the mouth rising, and its sidespin brings it back down onto rail 4.
    Ball four = ball(4, 0.1176, -0.5661, -1.43, -1.054);
    four.spin = Vec3(36.9, -50.0, -5.0);
    const Scene scene = table_with({four});
    PlayResult result = play(scene);
    REQUIRE_FALSE(result.failure);
    const auto jaws = of_type(result.timeline, EventType::ball_jaw);
    const auto rails = of_type(result.timeline, EventType::ball_rail);
    REQUIRE_FALSE(jaws.empty());
    REQUIRE_FALSE(rails.empty());
    CHECK(jaws[0]->pocket == 4);
    CHECK(jaws[0]->before[0].position.y() < -0.635 + cushion_reach(kR, kStandardNoseHeight));
    CHECK(rails[0]->rail == 4);
    CHECK(rails[0]->time > jaws[0]->time);
    const checks::Faults faults = checks::find_faults(scene, result.timeline);
    CHECK(faults.escapes == 0);
    CHECK(faults.deepest < checks::kFaultTolerance);
  }

  TEST_CASE("a ball at a cushion's end point beside a bare pocket strikes the end: a ball-rail event there") {
    // A bare drop circle (a scene's own pocket) leaves the rail's end a square corner: rail 1 begins at
    // (0.065, 0.635) on a table of the scene's own cushions.
    Scene scene = table_with({ball(0, 0.062, 0.3, 0, 1.0)});
    const std::vector<Pocket> bare = bare_standard_pockets();
    scene.pockets = bare;
    scene.rails[0].b.x() = -bare[1].radius;
    scene.rails[1].a.x() = bare[1].radius;
    const Timeline timeline = simulate(scene);
    const auto rails = of_type(timeline, EventType::ball_rail);
    REQUIRE_FALSE(rails.empty());
    CHECK(rails[0]->rail == 1);
    CHECK(rails[0]->where.x() == doctest::Approx(0.065).epsilon(1e-9));
    CHECK(rails[0]->where.y() == doctest::Approx(0.635).epsilon(1e-9));
    CHECK(rails[0]->where.z() == doctest::Approx(kStandardNoseHeight).epsilon(1e-9));
    CHECK(rails[0]->after[0].velocity.y() < 0);
    CHECK(rails[0]->after[0].velocity.x() < 0);  // the jaw's corner sends it off sideways
    CHECK(of_type(timeline, EventType::ball_jaw).empty());
  }

  TEST_CASE("a ball rolled into a corner pocket falls, settles below the bed, and takes no further part") {
    const double speed = 1.0, d = 0.3;
    const Timeline timeline = simulate(table_with({ball(0, 1.27 - d, 0.635 - d, speed, speed)}));
    REQUIRE(timeline.pocket_drops().size() == 1);
    const PocketDrop drop = timeline.pocket_drops()[0];
    CHECK(drop.ball == 0);
    CHECK(drop.pocket == 2);
    CHECK(timeline.state(0, drop.time - 1e-6).motion != Motion::falling);
    const BallState falling = timeline.state(0, drop.time + 0.05);
    CHECK(falling.motion == Motion::falling);
    CHECK(falling.position.z() < kR);
    const BallState rest = timeline.state(0, timeline.duration());
    CHECK(rest.motion == Motion::pocketed);
    CHECK(rest.position.z() == doctest::Approx(kR - kPocketDepth));
    // In the cup, under the hole behind the mouth.
    const Pocket hole = standard_pockets()[2];
    CHECK(std::hypot(rest.position.x() - hole.center.x(), rest.position.y() - hole.center.y()) < hole.radius);
    for (const Event& e : timeline.events())
      if (e.type != EventType::start && e.type != EventType::end && e.type != EventType::cue) CHECK(e.time < drop.time);
  }

  TEST_CASE("a slow ball over the lip rolls over the edge before it falls") {
    const Pocket pocket{Vec3(0, 0, 0), 0.06, {}};
    BallState entry;
    entry.position = Vec3(-0.06, 0, kR);
    entry.velocity = Vec3(0.1, 0, 0);  // well below sqrt(g R) = 0.53 m/s
    entry.motion = Motion::falling;
    const PhysicsParams params;
    const BallState early = fall_state(entry, pocket, params, 0.01);
    // Pivoting on the lip: the centre stays R from it.
    CHECK((early.position - Vec3(-0.06, 0, 0)).norm() == doctest::Approx(kR).epsilon(1e-9));
    const double settle = fall_duration(entry, pocket, params);
    CHECK(settle > 0.1);
    CHECK(fall_state(entry, pocket, params, settle).motion == Motion::pocketed);
    CHECK(std::hypot(fall_state(entry, pocket, params, settle).position.x(), 0) < pocket.radius);
  }

  TEST_CASE("fall_end is fall_duration and fall_state at that duration, bit for bit, from one integration") {
    // Creeping over the lip (pivoting), slow, fast, straight at the wall and glancing; the pocket's
    // wall far and near; a fall long enough to reach the 5 s limit (no wall, no floor within it).
    const PhysicsParams params;
    int compared = 0;
    for (const double radius : {0.03, 0.06, 0.1})
      for (const double speed : {0.0, 1e-4, 0.1, 0.4, 0.53, 1.0, 3.0, 9.0})
        for (const double angle : {0.0, 0.7, 1.5}) {
          const Pocket pocket{Vec3(0, 0, 0), radius, {}};
          BallState entry;
          entry.position = Vec3(-radius, 0.001, kR);
          entry.velocity = speed * Vec3(std::cos(angle), std::sin(angle), 0);
          entry.spin = Vec3(0.5, -2, 3);
          entry.motion = Motion::falling;
          const FallEnd end = fall_end(entry, pocket, params);
          const double duration = fall_duration(entry, pocket, params);
          CAPTURE(radius);
          CAPTURE(speed);
          CAPTURE(angle);
          CHECK(end.duration == duration);
          CHECK(end.state == fall_state(entry, pocket, params, duration));
          ++compared;
        }
    CHECK(compared == 72);
  }

  TEST_CASE("the same scene gives the same timeline, bit for bit") {
    const Scene scene = scenes::random_break(42);
    const Timeline a = simulate(scene), b = simulate(scene);
    REQUIRE(a.events().size() > 3);
    CHECK(a == b);
    for (int i = 0; i < a.ball_count(); ++i) CHECK(a.state(i, 3.7) == b.state(i, 3.7));
    // == sees a difference in any event: one contact point moved by one step of the last bit.
    std::vector<std::vector<MotionSegment>> segments;
    for (int i = 0; i < a.ball_count(); ++i) segments.push_back(a.segments(i));
    std::vector<Event> events = a.events();
    events[2].where.x() = std::nextafter(events[2].where.x(), INFINITY);
    CHECK_FALSE(Timeline(scene, segments, events, a.pocket_drops(), a.shots()) == a);
    CHECK(Timeline(scene, segments, a.events(), a.pocket_drops(), a.shots()) == a);
  }

  TEST_CASE(
      "random breaks and scattered tables: no overlap, nobody past a cushion or off the bed, no NaN, energy never "
      "rises") {
    std::vector<Scene> scenes_to_check;
    for (std::uint64_t seed = 1; seed <= 25; ++seed) scenes_to_check.push_back(scenes::random_break(seed));
    for (std::uint64_t seed = 1; seed <= 3; ++seed) scenes_to_check.push_back(scenes::stress_table(30, seed));
    for (const Scene& scene : scenes_to_check) {
      CAPTURE(scene.name);
      // Played as the programs play it, with the physics' guard (table_escape.h): no ball leaves the bed.
      Scene played = scene;
      PlayResult result = play(played);
      CHECK_MESSAGE(!result.failure, (result.failure ? result.failure->message : std::string()));
      const Timeline timeline = std::move(result.timeline);
      const checks::Faults faults = checks::find_faults(scene, timeline);
      CHECK(faults.overlaps == 0);
      CHECK(faults.escapes == 0);
      CHECK(faults.nans == 0);
      CHECK(faults.missed == 0);
      CHECK(faults.energy_gains == 0);
      // Energy of the balls on the bed, after each event, never rises.
      double previous = INFINITY;
      for (const Event& e : timeline.events()) {
        if (e.time < timeline.cue_time()) continue;
        double energy = 0;
        for (int i = 0; i < timeline.ball_count(); ++i) {
          const BallState s = checks::detail::state_at(timeline, i, e.time);
          if (on_bed(s)) energy += kinetic_energy(s, timeline.physics());
        }
        CHECK(energy <= previous * (1 + 1e-12) + 1e-15);
        previous = energy;
      }
    }
  }

  TEST_CASE("a shot that would never end is cut off") {
    Scene scene;
    scene.physics.mu_roll = 0;
    scene.balls.push_back(ball(0, 0, 0, 1, 0));
    const SimulationResult result = simulate_events(scene);
    CHECK(result.cut_off);
    CHECK(result.events.back().time == std::ceil(kCueLeadTime + kMaxShotTime + kEndHold));
  }
}
