// The ball-cushion impact: Han 2005 as published (restitution along the contact normal at the nose,
// stick or slide there), checked against the figures its published form gives with pooltool's pool
// inputs, against Han's equations written out in the cushion's frame, and for the laws any cushion
// must keep (no energy made, the ball leaves, spin acts the right way round, mirror symmetry).
#include <doctest/doctest.h>

#include <cmath>

#include "energy.h"
#include "motion.h"
#include "random_scenes.h"
#include "resolve.h"
#include "scene.h"
#include "tolerance.h"

using namespace bsim;

namespace {

const double kR = PhysicsParams{}.ball_radius;
const double kPi = std::acos(-1.0);

/// The nose height of the published comparisons: 64 % of the ball's diameter.
const double kAnchorNose = 0.64 * 2 * kR;

BallState ball(Vec3 v, Vec3 w = Vec3(0, 0, 0)) {
  BallState s;
  s.position = Vec3(0, 0, kR);
  s.velocity = v;
  s.spin = w;
  s.motion = Motion::sliding;
  return s;
}

/// A ball rolling on the bed at `speed`, `degrees` from the cushion's normal (toward +x, the cushion
/// along y; positive angles run along +y).
BallState rolling_in(double speed, double degrees) {
  const double a = degrees * kPi / 180;
  const Vec3 v(speed * std::cos(a), speed * std::sin(a), 0);
  return ball(v, Vec3(0, 0, 1).cross(v) / kR);
}

/// The horizontal speed after the impact.
double speed_out(const BallState& s) { return std::hypot(s.velocity.x(), s.velocity.y()); }

/// Degrees between the path after the impact and the cushion line (the cushion along y).
double degrees_from_cushion(const BallState& s) {
  return std::atan2(std::abs(s.velocity.x()), std::abs(s.velocity.y())) * 180 / kPi;
}

/// sin of the nose's angle above the ball's equator.
double lift(double nose_height) { return (nose_height - kR) / kR; }

/// Han's equations in the cushion's own frame: x toward the cushion, y along it, z up; the nose at
/// angle theta above the equator. Slip of the ball's point at the nose along the tangent pointing
/// down and in, t = (sin, 0, -cos), and along y; approach c along the normal n = (cos, 0, sin).
BallState han_reference(const BallState& in, double nose_height, const PhysicsParams& p) {
  const double m = p.ball_mass, s = lift(nose_height), c = std::sqrt(1 - s * s);
  const Vec3 v = in.velocity, w = in.spin;
  const double slip_t = v.x() * s - v.z() * c + kR * w.y();
  const double slip_y = v.y() + kR * (w.z() * c - w.x() * s);
  const double approach = v.x() * c + v.z() * s;
  const double normal = (1 + p.e_rail) * m * approach;
  double f_t = -2 * m * slip_t / 7, f_y = -2 * m * slip_y / 7;
  const double needed = std::hypot(f_t, f_y);
  if (needed > p.mu_rail * normal) {
    f_t *= p.mu_rail * normal / needed;
    f_y *= p.mu_rail * normal / needed;
  }
  BallState out = in;
  out.velocity += Vec3(-normal * c + f_t * s, f_y, 0) / m;
  out.spin += kR / (0.4 * m * kR * kR) * Vec3(-f_y * s, f_t, f_y * c);
  return out;
}

/// Mirror image in the plane of the cushion's normal and the vertical (y -> -y): a polar vector
/// flips y, an axial one (spin) flips x and z.
BallState mirrored(const BallState& s) {
  BallState m = s;
  m.velocity.y() = -s.velocity.y();
  m.spin = Vec3(-s.spin.x(), s.spin.y(), -s.spin.z());
  return m;
}

const Vec3 kToward(1, 0, 0);

}  // namespace

TEST_SUITE("cushion") {
  TEST_CASE("Han 2005, pooltool's inputs: head-on, a sliding ball comes back at 0.727, a rolling one at 0.804") {
    const PhysicsParams p;  // e_rail 0.85, mu_rail 0.2
    REQUIRE(p.e_rail == 0.85);
    REQUIRE(p.mu_rail == 0.2);
    const BallState sliding = resolve_ball_cushion(ball(Vec3(1, 0, 0)), kToward, kAnchorNose, p);
    const BallState rolling = resolve_ball_cushion(rolling_in(1, 0), kToward, kAnchorNose, p);
    CHECK(sliding.velocity.x() == doctest::Approx(-0.727).epsilon(0.01));
    CHECK(rolling.velocity.x() == doctest::Approx(-0.804).epsilon(0.01));
    CHECK(sliding.velocity.y() == test::near(0, 1e-15));
    CHECK(rolling.velocity.y() == test::near(0, 1e-15));
    // The speed scales: twice as fast in, twice as fast out.
    CHECK(resolve_ball_cushion(rolling_in(2, 0), kToward, kAnchorNose, p).velocity.x() ==
          doctest::Approx(2 * rolling.velocity.x()));
  }

  TEST_CASE("Han 2005, pooltool's inputs: rolling in at 45 degrees, the ball leaves at 0.762 and 46.0 degrees") {
    const PhysicsParams p;
    const BallState out = resolve_ball_cushion(rolling_in(1, 45), kToward, kAnchorNose, p);
    CHECK(out.velocity.x() < 0);
    CHECK(out.velocity.y() > 0);
    CHECK(speed_out(out) == doctest::Approx(0.762).epsilon(0.01));
    CHECK(degrees_from_cushion(out) == test::near(46.0, 0.5));
    // On the standard table's slightly lower nose (63.5 % of the diameter): 0.766 at 46.3 degrees.
    const BallState standard = resolve_ball_cushion(rolling_in(1, 45), kToward, kStandardNoseHeight, p);
    CHECK(speed_out(standard) == doctest::Approx(0.766).epsilon(0.01));
    CHECK(degrees_from_cushion(standard) == test::near(46.3, 0.5));
  }

  TEST_CASE("on random inputs the impact is Han's equations written in the cushion's frame, at any heading") {
    scenes::Rng rng(12);
    for (int k = 0; k < 1000; ++k) {
      PhysicsParams p;
      // (Where the free ball would still move into the cushion once the bed has taken its vertical
      // velocity, the cushion stops it: a small e on a high nose. Not here.)
      p.e_rail = rng.uniform(0.6, 1);
      p.mu_rail = rng.uniform(0, 0.3);
      const double nose = rng.uniform(1.2 * kR, 1.4 * kR);
      const BallState s = ball(rng.vector(0.01, 4) - Vec3(0, 2, 0), rng.vector(-150, 150, -150, 150));
      CAPTURE(s);
      CAPTURE(p.e_rail);
      CAPTURE(p.mu_rail);
      const BallState expected = han_reference(s, nose, p);
      const BallState out = resolve_ball_cushion(s, kToward, nose, p);
      CHECK(out.velocity == test::near(expected.velocity, 1e-12));
      CHECK(out.spin == test::near(expected.spin, 1e-9));
      // The same impact on a cushion turned to any heading: everything turns with it.
      const double a = rng.uniform(0, 2 * kPi);
      const auto turn = [a](const Vec3& x) {
        return Vec3(std::cos(a) * x.x() - std::sin(a) * x.y(), std::sin(a) * x.x() + std::cos(a) * x.y(), x.z());
      };
      const BallState turned = resolve_ball_cushion(ball(turn(s.velocity), turn(s.spin)), turn(kToward), nose, p);
      CHECK(turned.velocity == test::near(turn(out.velocity), 1e-12));
      CHECK(turned.spin == test::near(turn(out.spin), 1e-9));
    }
  }

  TEST_CASE("a ball never gains energy; a smooth cushion takes what restitution along the nose's normal takes") {
    scenes::Rng rng(5);
    for (int k = 0; k < 1000; ++k) {
      PhysicsParams p;
      p.e_rail = rng.uniform(0, 1);
      p.mu_rail = rng.uniform(0, 0.5);
      const double angle = rng.uniform(0, 2 * kPi);
      const Vec3 toward(std::cos(angle), std::sin(angle), 0);
      const BallState s = ball(rng.vector(-3, 3), rng.vector(-150, 150, -150, 150));
      if (s.velocity.dot(toward) <= 0) continue;
      CAPTURE(s);
      const BallState out = resolve_ball_cushion(s, toward, kStandardNoseHeight, p);
      CHECK(kinetic_energy(out, p) <= kinetic_energy(s, p) * (1 + 1e-12));
    }
    // Without friction a head-on ball keeps no spin and the fraction (1 - (1 + e) cos^2)^2 of its
    // energy: e acts along the normal at the nose, which leans up from the horizontal.
    PhysicsParams smooth;
    smooth.mu_rail = 0;
    const double s = lift(kStandardNoseHeight), kept = 1 - (1 + smooth.e_rail) * (1 - s * s);
    const BallState in = ball(Vec3(1.3, 0, 0));
    const BallState out = resolve_ball_cushion(in, kToward, kStandardNoseHeight, smooth);
    CHECK(out.spin.norm() == 0);
    CHECK(kinetic_energy(out, smooth) == doctest::Approx(kept * kept * kinetic_energy(in, smooth)));
  }

  TEST_CASE("the ball leaves the cushion: its speed along the normal comes back reversed") {
    scenes::Rng rng(7);
    for (int k = 0; k < 1000; ++k) {
      PhysicsParams p;
      p.e_rail = rng.uniform(0, 1);
      p.mu_rail = rng.uniform(0, 0.5);
      const double angle = rng.uniform(0, 2 * kPi);
      const Vec3 toward(std::cos(angle), std::sin(angle), 0);
      const double nose = rng.uniform(kR, 1.9 * kR);
      const BallState s = ball(rng.vector(-3, 3), rng.vector(-150, 150, -150, 150));
      if (s.velocity.dot(toward) <= 0) continue;
      CAPTURE(s);
      const BallState out = resolve_ball_cushion(s, toward, nose, p);
      CHECK(out.velocity.z() == 0);
      CHECK(out.velocity.dot(toward) <= 1e-12);
      CHECK(cushion_closing_speed(out, toward, nose, p) <= 1e-12);
    }
    // With the defaults it leaves with speed to spare, whatever its spin.
    for (double w : {-200.0, -50.0, 0.0, 50.0, 200.0}) {
      CAPTURE(w);
      const BallState out =
          resolve_ball_cushion(ball(Vec3(1, 0.3, 0), Vec3(w, w, -w)), kToward, kStandardNoseHeight, PhysicsParams{});
      CHECK(out.velocity.x() < -0.5);
    }
    // Smooth, head-on: it comes back at (1 + e) cos^2 - 1 of its approach, not e.
    PhysicsParams smooth;
    smooth.mu_rail = 0;
    const double s = lift(kStandardNoseHeight);
    const BallState out = resolve_ball_cushion(ball(Vec3(1, 0, 0)), kToward, kStandardNoseHeight, smooth);
    CHECK(out.velocity.x() == doctest::Approx(1 - (1 + smooth.e_rail) * (1 - s * s)));
    // No impulse on a ball that is not closing.
    const BallState leaving = ball(Vec3(-1, 0.5, 0), Vec3(3, 4, 5));
    const BallState same = resolve_ball_cushion(leaving, kToward, kStandardNoseHeight, PhysicsParams{});
    CHECK(same.velocity == leaving.velocity);
    CHECK(same.spin == leaving.spin);
  }

  TEST_CASE("spin: the nose above the centre grips the ball's top, and sidespin throws the rebound") {
    const PhysicsParams p;
    const double s = lift(kAnchorNose), c = std::sqrt(1 - s * s);
    // A sliding ball without spin sticks at the nose and comes back turning forward (toward its new
    // path, here -x): the grip costs it 2/7 of its slip there, v sin.
    const BallState slid = resolve_ball_cushion(ball(Vec3(1, 0, 0)), kToward, kAnchorNose, p);
    CHECK(slid.spin.y() == doctest::Approx(-5.0 / 7.0 * s / kR));
    CHECK(slid.spin.x() == test::near(0, 1e-12));
    CHECK(slid.spin.z() == test::near(0, 1e-12));
    // A rolling ball slides at the nose: friction mu P takes most of its roll, leaving a little
    // backspin for its way back.
    const BallState rolled = resolve_ball_cushion(rolling_in(1, 0), kToward, kAnchorNose, p);
    CHECK(rolled.spin.y() == doctest::Approx((1 - 2.5 * p.mu_rail * (1 + p.e_rail) * c) / kR));
    CHECK(rolled.spin.y() > 0);
    CHECK(rolled.motion == Motion::sliding);
    // Left english (struck left of centre: clockwise seen from above) on a straight-in ball throws it
    // to the left on the way back (+y for a ball going +x), and the cushion takes some of the spin.
    const BallState left = resolve_ball_cushion(ball(Vec3(1, 0, 0), Vec3(0, 1 / kR, -20)), kToward, kAnchorNose, p);
    CHECK(left.velocity.y() > 0);
    CHECK(left.spin.z() < 0);
    CHECK(left.spin.z() > -20);
    const BallState right = resolve_ball_cushion(ball(Vec3(1, 0, 0), Vec3(0, 1 / kR, 20)), kToward, kAnchorNose, p);
    CHECK(right.velocity.y() == doctest::Approx(-left.velocity.y()));
    // Running english (turning the way the ball runs along the cushion) sends it off flatter than
    // none, and reverse english steeper, as players know it.
    const BallState plain = resolve_ball_cushion(rolling_in(1, 45), kToward, kAnchorNose, p);
    BallState running_in = rolling_in(1, 45), reverse_in = rolling_in(1, 45);
    running_in.spin.z() = -20;  // the ball runs along +y: clockwise from above carries it on
    reverse_in.spin.z() = 20;
    CHECK(degrees_from_cushion(resolve_ball_cushion(running_in, kToward, kAnchorNose, p)) <
          degrees_from_cushion(plain));
    CHECK(degrees_from_cushion(resolve_ball_cushion(reverse_in, kToward, kAnchorNose, p)) >
          degrees_from_cushion(plain));
    CHECK(degrees_from_cushion(plain) == test::near(46.0, 0.5));
  }

  TEST_CASE("mirror symmetry: the mirror image of an approach gives the mirror image of the result") {
    const PhysicsParams p;
    scenes::Rng rng(3);
    for (int k = 0; k < 200; ++k) {
      const BallState s = ball(rng.vector(0.01, 3) - Vec3(0, 1.5, 0), rng.vector(-100, 100, -100, 100));
      CAPTURE(s);
      const BallState out = resolve_ball_cushion(s, kToward, kStandardNoseHeight, p);
      const BallState image = resolve_ball_cushion(mirrored(s), kToward, kStandardNoseHeight, p);
      CHECK(image.velocity == test::near(mirrored(out).velocity, 1e-12));
      CHECK(image.spin == test::near(mirrored(out).spin, 1e-9));
    }
    // Rolling in at 45 degrees from either side, the ball leaves at Han's 46.0 degrees on the other.
    const BallState left = resolve_ball_cushion(rolling_in(1, 45), kToward, kAnchorNose, p);
    const BallState right = resolve_ball_cushion(rolling_in(1, -45), kToward, kAnchorNose, p);
    CHECK(right.velocity.y() == doctest::Approx(-left.velocity.y()));
    CHECK(right.velocity.x() == doctest::Approx(left.velocity.x()));
    CHECK(degrees_from_cushion(right) == test::near(46.0, 0.5));
  }
}
