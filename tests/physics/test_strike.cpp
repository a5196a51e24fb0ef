// The stick's strike (strike.h): each check states its oracle.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "shots.h"
#include "strike.h"
#include "tolerance.h"

using namespace bsim;

namespace {

Stroke stroke(double speed, double side, double height, double elevation_deg) {
  Stroke s;
  s.speed = speed;
  s.side = side;
  s.height = height;
  s.elevation_deg = elevation_deg;
  return s;
}

double degrees_of(const Vec3& v) { return std::atan2(v.y(), v.x()) / kDegToRad; }

/// The first segment after the strike (the ball rests before it).
const MotionSegment& struck_segment(const Timeline& timeline) {
  const auto& segments = timeline.segments(0);
  const auto it = std::find_if(segments.begin(), segments.end(),
                               [](const MotionSegment& s) { return s.start.motion != Motion::stationary; });
  REQUIRE(it != segments.end());
  return *it;
}

/// A lone ball struck along +x from the head string, with the given stroke and cloth friction.
std::string lone_ball(const std::string& stroke_line, double mu_slide) {
  return "cue 0 0\n" + stroke_line + "\nball 0 -0.9 0 0.028575 0 0 0 1 0 0 0\nparam cue_end_mass 0\nparam mu_slide " +
         std::to_string(mu_slide) + "\n";
}

}  // namespace

TEST_SUITE("strike") {
  TEST_CASE("a centre hit: |v| = (1 + e) V / (1 + m/M), no spin") {
    // TP A-30 with a = b = 0: 1.75 * 2 / (1 + 0.170097 / 0.54) = 2.661608 m/s for V = 2 m/s.
    const StrikeResult r = strike(stroke(2, 0, 0, 0), 0, PhysicsParams{});
    CHECK(r.velocity.norm() == test::near(2.661608, 1e-6));
    CHECK(r.velocity.y() == test::near(0.0, 1e-15));
    CHECK(r.spin.norm() == test::near(0.0, 1e-12));
    // The heading turns the ball's direction with it.
    CHECK(degrees_of(strike(stroke(2, 0, 0, 0), 135, PhysicsParams{}).velocity) == test::near(135.0, 1e-12));
  }

  TEST_CASE("natural roll at 0.4 R: the ball rolls from the strike") {
    // w R / v = 5/2 b (TP A-30), = 1 at b = 0.4: Alciatore's immediate-roll height.
    const StrikeResult r = strike(stroke(1.5, 0, 0.4, 0), 0, PhysicsParams{});
    CHECK(r.spin.y() * PhysicsParams{}.ball_radius == test::near(r.velocity.x(), 1e-12));
    const auto shot = test::load_clean(lone_ball("stroke 1.5 0 0.4 0", 0.2));
    CHECK(struck_segment(shot->timeline).start.motion == Motion::rolling);
  }

  TEST_CASE("draw at -0.3 R: spin/speed ratio w R / v = 5/2 b = -0.75") {
    const PhysicsParams p;
    const StrikeResult r = strike(stroke(1.5, 0, -0.3, 0), 0, p);
    CHECK(r.spin.y() * p.ball_radius / r.velocity.x() == test::near(-0.75, 1e-12));
    // The speed falls by the off-centre hit: (1 + e) V / (1 + m/M + 5/2 b^2).
    CHECK(r.velocity.norm() == test::near(1.75 * 1.5 / (1 + p.ball_mass / p.cue_mass + 2.5 * 0.09), 1e-12));
  }

  TEST_CASE("squirt: 1.1994 degrees at a = 0.2 and m/m_e = 20 (TP A-31; pooltool's own test)") {
    CHECK(squirt_angle(0.2, 20) / kDegToRad == test::near(1.1994, 5e-5));
    PhysicsParams p;
    p.cue_end_mass = p.ball_mass / 20;
    // Right english pushes the ball left of the stick's line (counter-clockwise), left english right.
    CHECK(degrees_of(strike(stroke(2, 0.2, 0, 0), 0, p).velocity) == test::near(1.1994, 5e-5));
    CHECK(degrees_of(strike(stroke(2, -0.2, 0, 0), 90, p).velocity) == test::near(90 - 1.1994, 5e-5));
    // No end mass, no squirt.
    p.cue_end_mass = 0;
    CHECK(degrees_of(strike(stroke(2, 0.2, 0, 0), 0, p).velocity) == test::near(0.0, 1e-12));
    // Default end mass: 1-3 degrees at 0.5 R (the range; m/m_e = 29.8 gives 1.90).
    CHECK(squirt_angle(0.5, PhysicsParams{}.ball_mass / PhysicsParams{}.cue_end_mass) / kDegToRad ==
          test::near(1.90, 0.01));
  }

  TEST_CASE("an elevated stroke: the bed takes the vertical part, the speed does not depend on the elevation") {
    // With offsets across the stick |Q x d| = R sqrt(a^2 + b^2) at every elevation (pooltool PR #181).
    const StrikeResult level = strike(stroke(2, 0.3, 0, 0), 0, PhysicsParams{});
    const StrikeResult raised = strike(stroke(2, 0.3, 0, 30), 0, PhysicsParams{});
    CHECK(raised.velocity.z() == 0);
    CHECK(raised.velocity.norm() == test::near(level.velocity.norm() * std::cos(30 * kDegToRad), 1e-12));
    CHECK(raised.spin.norm() == test::near(level.spin.norm(), 1e-9));
  }

  TEST_CASE("swerve: the rolling heading ends atan(a tan theta) off the stick's line, whatever the friction") {
    // Angular momentum about the cloth contact point is kept from the strike to rolling (Coriolis
    // 1835), so with b = 0 and no squirt the ball rolls off toward the english side (right: clockwise).
    const double expected = -std::atan(0.3 * std::tan(30 * kDegToRad)) / kDegToRad;  // -9.826 degrees
    for (double mu : {0.1, 0.3}) {
      CAPTURE(mu);
      const auto shot = test::load_clean(lone_ball("stroke 1 0.3 0 30", mu));
      const auto& segments = shot->timeline.segments(0);
      REQUIRE(struck_segment(shot->timeline).start.motion == Motion::sliding);
      const auto rolling = std::find_if(segments.begin(), segments.end(),
                                        [](const MotionSegment& s) { return s.start.motion == Motion::rolling; });
      REQUIRE(rolling != segments.end());
      CHECK(degrees_of(rolling->start.velocity) == test::near(expected, 1e-9));
    }
  }

  TEST_CASE("strike_cue_ball gives the cue line's ball the strike, and only with a stroke") {
    auto shot = test::load_clean(
        "cue 1 90\nstroke 2 0 0.2 0\nball 3 0.5 0 0.028575 0 0 0 1 0 0 0\n"
        "ball 0 0 0 0.028575 0 0 0 1 0 0 0\n");
    const StrikeResult r = strike(*shot->scene.cue().stroke, 90, shot->scene.physics);
    CHECK(shot->scene.balls[1].velocity == r.velocity);
    CHECK(shot->scene.balls[1].spin == r.spin);
    CHECK(shot->scene.balls[0].velocity == Vec3(0, 0, 0));
    Scene seed = shot->scene;
    seed.cue().stroke.reset();
    seed.balls[1].velocity = Vec3(1, 0, 0);
    strike_cue_ball(seed);
    CHECK(seed.balls[1].velocity == Vec3(1, 0, 0));
  }
}
