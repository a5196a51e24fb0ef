// Contact detection: exact times for ball-ball, cushion line and end point, and pocket entry,
// including the cases where event-based simulators go wrong (grazing, touching, round-off).
#include <doctest/doctest.h>

#include <cmath>

#include "detect.h"
#include "physics_print.h"
#include "scene.h"

using namespace bsim;

namespace {

const PhysicsParams kParams;
const double kR = kParams.ball_radius;

BallState ball(double x, double y, double vx = 0, double vy = 0, Vec3 spin = Vec3(0, 0, 0)) {
  BallState s;
  s.position = Vec3(x, y, kR);
  s.velocity = Vec3(vx, vy, 0);
  s.spin = spin;
  return classify(s, kParams);
}

Path path(const BallState& s) { return path_of(s, kParams); }

/// Distance between two centres after dt (both paths from the same instant).
double distance_after(const Path& a, const Path& b, double dt) {
  const Vec3 d = b.at(dt) - a.at(dt);
  return std::hypot(d.x(), d.y());
}

}  // namespace

TEST_SUITE("detect") {
  TEST_CASE("head-on: the contact time solves the sliding motion exactly") {
    const double v0 = 1.5, gap = 0.1, mu = kParams.mu_slide * kParams.g;
    const BallState a = ball(0, 0, v0), b = ball(2 * kR + gap, 0);
    const auto t = next_ball_ball(path(a), path(b), 2 * kR, transition_time(a, kParams));
    REQUIRE(t.has_value());
    CHECK(*t == doctest::Approx((v0 - std::sqrt(v0 * v0 - 2 * mu * gap)) / mu).epsilon(1e-12));
    CHECK(distance_after(path(a), path(b), *t) >= 2 * kR);
    CHECK(distance_after(path(a), path(b), *t) == doctest::Approx(2 * kR).epsilon(1e-12));
  }

  TEST_CASE("grazing: a path passing exactly 2R from the centre touches; a hair wider misses, a hair closer hits") {
    const BallState target = ball(0.5, 0);
    for (double offset : {2 * kR - 1e-9, 2 * kR - 1e-7}) {
      CAPTURE(offset);
      const BallState a = ball(0, offset, 1.0, 0, Vec3(0, 1 / kR, 0));  // rolling along x
      const auto t = next_ball_ball(path(a), path(target), 2 * kR, transition_time(a, kParams));
      REQUIRE(t.has_value());
      CHECK(path(a).at(*t).x() < 0.5);
    }
    const BallState wide = ball(0, 2 * kR + 1e-9, 1.0, 0, Vec3(0, 1 / kR, 0));
    CHECK_FALSE(next_ball_ball(path(wide), path(target), 2 * kR, transition_time(wide, kParams)).has_value());
  }

  TEST_CASE("balls touching at rest, or touching and moving apart, do not collide; touching and closing collide now") {
    const BallState a = ball(0, 0), b = ball(2 * kR, 0);
    CHECK_FALSE(next_ball_ball(path(a), path(b), 2 * kR, 10).has_value());
    const BallState leaving = ball(2 * kR, 0, 0.5, 0);
    CHECK_FALSE(next_ball_ball(path(a), path(leaving), 2 * kR, transition_time(leaving, kParams)).has_value());
    const BallState pushing = ball(0, 0, 0.5, 0);
    const auto now = next_ball_ball(path(pushing), path(b), 2 * kR, transition_time(pushing, kParams));
    REQUIRE(now.has_value());
    CHECK(*now == 0);
    // Round-off: a hair of overlap (as a parsed scene may have) and separating is not a hit either.
    const BallState overlapping = ball(2 * kR - 1e-12, 0, 0.5, 0);
    CHECK_FALSE(next_ball_ball(path(a), path(overlapping), 2 * kR, transition_time(overlapping, kParams)).has_value());
  }

  TEST_CASE(
      "a pair pressing without closing (a push) meets again once its overlap grows, and never deeper than allowed") {
    // b rolls slowly ahead; a, touching it from behind, has follow and is pulled forward by the cloth.
    const BallState a = ball(0, 0, 0.2, 0, Vec3(0, 3 / kR, 0));
    const BallState b = ball(2 * kR, 0, 0.2, 0, Vec3(0, 0.2 / kR, 0));
    const double horizon = std::min(transition_time(a, kParams), transition_time(b, kParams));
    const auto t = next_ball_ball(path(a), path(b), 2 * kR, horizon);
    REQUIRE(t.has_value());
    CHECK(*t > 0);
    CHECK(*t <= kPushInterval);
    CHECK(distance_after(path(a), path(b), *t) >= 2 * kR - kMaxPushOverlap * (1 + 1e-6));
  }

  TEST_CASE("cushion line: contact when the centre is sqrt(R^2 - (h-R)^2) from the nose line") {
    const Rail rail{Vec3(1, 1, kStandardNoseHeight), Vec3(1, -1, kStandardNoseHeight), {}};  // playing side x < 1
    const double reach = cushion_reach(kR, kStandardNoseHeight);
    CHECK(reach == doctest::Approx(std::sqrt(kR * kR - std::pow(kStandardNoseHeight - kR, 2))));
    CHECK(reach < kR);
    const BallState s = ball(0, 0.2, 1.0, 0, Vec3(0, 1 / kR, 0));
    const auto t = next_ball_cushion(path(s), rail, reach, transition_time(s, kParams));
    REQUIRE(t.has_value());
    CHECK(path(s).at(*t).x() == doctest::Approx(1 - reach).epsilon(1e-12));
    // Moving away, or behind the cushion: nothing.
    const BallState away = ball(0, 0.2, -1.0, 0, Vec3(0, -1 / kR, 0));
    CHECK_FALSE(next_ball_cushion(path(away), rail, reach, transition_time(away, kParams)).has_value());
    const BallState behind = ball(1.5, 0.2, -1.0, 0, Vec3(0, -1 / kR, 0));
    CHECK_FALSE(next_ball_cushion(path(behind), rail, reach, transition_time(behind, kParams)).has_value());
  }

  TEST_CASE("a ball passing beyond a cushion's end misses the line but strikes the end point (a jaw)") {
    const Rail rail{Vec3(1, 1, kStandardNoseHeight), Vec3(1, 0, kStandardNoseHeight), {}};
    const double reach = cushion_reach(kR, kStandardNoseHeight);
    // Heading at the corner beside the end at (1, 0), a little below it.
    const BallState s = ball(0, -0.01, 1.0, 0, Vec3(0, 1 / kR, 0));
    const double horizon = transition_time(s, kParams);
    CHECK_FALSE(next_ball_cushion(path(s), rail, reach, horizon).has_value());
    const auto t = next_ball_point(path(s), rail.b, reach, horizon);
    REQUIRE(t.has_value());
    const Vec3 at = path(s).at(*t);
    CHECK(std::hypot(at.x() - 1, at.y()) == doctest::Approx(reach).epsilon(1e-12));
    // Well below the end it misses both.
    const BallState clear = ball(0, -0.1, 1.0, 0, Vec3(0, 1 / kR, 0));
    CHECK_FALSE(next_ball_point(path(clear), rail.b, reach, horizon).has_value());
  }

  TEST_CASE("a ball in a pocket's mouth, below a cushion's nose level past its end, meets the line coming down to it") {
    // The nose line runs from (0, 0) to (-1, 0), playing side y > 0 (a side pocket's mouth at x > 0). The
    // ball starts 1 mm below the contact reach but beside the line, past its end; it rises above the reach,
    // curves back (a sliding ball's swerve) and comes down onto the line. That is a contact at the reach,
    // not once it is 1 mm deep again (seeded 9-ball game 396, whose break left the 4 inside a side rail).
    const Rail rail{Vec3(0, 0, kStandardNoseHeight), Vec3(-1, 0, kStandardNoseHeight), {}};
    const double reach = cushion_reach(kR, kStandardNoseHeight);
    const Path ball{Vec3(0.05, reach - 1e-3, kR), Vec3(-1.5, 0.1, 0), Vec3(0, -2, 0)};
    const auto t = next_ball_cushion(ball, rail, reach, 1.0);
    REQUIRE(t.has_value());
    // s(t) = -1e-3 + 0.1 t - t^2 comes down through 0 at (0.1 + sqrt(0.006)) / 2.
    CHECK(*t == doctest::Approx((0.1 + std::sqrt(0.006)) / 2).epsilon(1e-12));
    CHECK(ball.at(*t).y() == doctest::Approx(reach).epsilon(1e-12));
    CHECK(ball.at(*t).x() < 0);  // on the line's span
    // Level with the nose past the end and not coming back above it: no contact with the line.
    const Path low{Vec3(0.05, reach - 1e-3, kR), Vec3(-1.5, 0.01, 0), Vec3(0, -2, 0)};
    CHECK_FALSE(next_ball_cushion(low, rail, reach, 1.0).has_value());
  }

  TEST_CASE("pocket entry: when the centre crosses the pocket's circle; a ball already over it drops at once") {
    const Pocket pocket{Vec3(1, 0, 0), 0.06, {}};
    const BallState s = ball(0, 0, 1.5, 0, Vec3(0, 1.5 / kR, 0));
    const auto t = next_pocket_entry(path(s), pocket, transition_time(s, kParams));
    REQUIRE(t.has_value());
    CHECK(path(s).at(*t).x() == doctest::Approx(1 - 0.06).epsilon(1e-12));
    const BallState over = ball(1.01, 0);
    CHECK(next_pocket_entry(path(over), pocket, 1).value_or(-1) == 0);
    const BallState beside = ball(0.9, 0);
    CHECK_FALSE(next_pocket_entry(path(beside), pocket, 10).has_value());
  }

  TEST_CASE("nothing is reported past the horizon") {
    const BallState a = ball(0, 0, 1.0, 0, Vec3(0, 1 / kR, 0)), b = ball(0.5, 0);
    const auto t = next_ball_ball(path(a), path(b), 2 * kR, transition_time(a, kParams));
    REQUIRE(t.has_value());
    CHECK_FALSE(next_ball_ball(path(a), path(b), 2 * kR, 0.5 * *t).has_value());
  }

  TEST_CASE("swept boxes cover the whole quadratic path, including where it turns back") {
    const Path p{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(-1, 0, 0)};  // turns back at t = 1, x = 0.5
    const SweptBox box = swept_box(p, 3);
    CHECK(box.hi.x() == doctest::Approx(0.5));
    CHECK(box.lo.x() == doctest::Approx(-1.5));
    CHECK(boxes_within(box, SweptBox{Vec3(0.6, 0, 0), Vec3(0.6, 0, 0)}, 0.2));
    CHECK_FALSE(boxes_within(box, SweptBox{Vec3(0.8, 0, 0), Vec3(0.8, 0, 0)}, 0.2));
  }
}
