// Motion between events: every state's closed form against the textbook results (Marlow; Alciatore),
// its transition time, and the orientation that follows the spin.
#include <doctest/doctest.h>

#include <cmath>

#include "energy.h"
#include "motion.h"
#include "physics_print.h"

using namespace bsim;

namespace {

const PhysicsParams kParams;  // pool defaults
const double kR = kParams.ball_radius;
const double kG = kParams.g;

BallState on_bed(Vec3 velocity, Vec3 spin) {
  BallState s;
  s.position = Vec3(0.1, -0.2, kR);
  s.velocity = velocity;
  s.spin = spin;
  return classify(s, kParams);
}

}  // namespace

TEST_SUITE("motion") {
  TEST_CASE("a ball struck at its centre slides, then rolls at 5/7 of its speed where the textbook says") {
    const double v0 = 1.3;
    const BallState s = on_bed(Vec3(v0, 0, 0), Vec3(0, 0, 0));
    REQUIRE(s.motion == Motion::sliding);
    const double t = transition_time(s, kParams);
    CHECK(t == doctest::Approx(2 * v0 / (7 * kParams.mu_slide * kG)).epsilon(1e-14));
    const BallState rolled = after_transition(s, kParams);
    CHECK(rolled.motion == Motion::rolling);
    CHECK(rolled.velocity.x() == doctest::Approx(5.0 / 7.0 * v0).epsilon(1e-14));
    CHECK(rolled.velocity.y() == 0);
    CHECK(rolled.position.x() - s.position.x() ==
          doctest::Approx(12 * v0 * v0 / (49 * kParams.mu_slide * kG)).epsilon(1e-13));
    // Rolling: the contact point does not slip.
    CHECK(contact_slip(rolled, kParams).norm() == doctest::Approx(0).epsilon(1e-15));
  }

  TEST_CASE("sliding: friction opposes the slip, so backspin first slows the ball harder than the slip alone") {
    // Draw: spin about +y makes the contact point slip forward faster than the centre moves.
    const BallState s = on_bed(Vec3(1, 0, 0), Vec3(0, -2 / kR, 0));
    REQUIRE(s.motion == Motion::sliding);
    const BallState later = evolve(s, kParams, 0.05);
    CHECK(later.velocity.x() == doctest::Approx(1 - kParams.mu_slide * kG * 0.05));
    // The slip shrinks at 7/2 mu g along its own direction.
    const double slip0 = contact_slip(s, kParams).norm(), slip1 = contact_slip(later, kParams).norm();
    CHECK(slip0 - slip1 == doctest::Approx(3.5 * kParams.mu_slide * kG * 0.05));
    const BallState rolled = after_transition(s, kParams);
    // Draw strong enough to come back: it ends rolling backwards at (5 v - 2 R w)/7.
    CHECK(rolled.velocity.x() == doctest::Approx((5.0 * 1 - 2.0 * 2) / 7.0));
    CHECK(rolled.motion == Motion::rolling);
  }

  TEST_CASE("natural roll (w R = v) rolls at once") {
    const BallState s = on_bed(Vec3(0.8, 0.6, 0), Vec3(-0.6 / kR, 0.8 / kR, 0));
    CHECK(s.motion == Motion::rolling);
  }

  TEST_CASE("rolling decelerates at mu_roll g with the spin locked to the velocity, then stops") {
    const BallState s = on_bed(Vec3(0.6, -0.8, 0), Vec3(0.8 / kR, 0.6 / kR, 0));
    REQUIRE(s.motion == Motion::rolling);
    const double t = transition_time(s, kParams);
    CHECK(t == doctest::Approx(1.0 / kParams.roll_decel()).epsilon(1e-14));
    const BallState mid = evolve(s, kParams, 0.5 * t);
    CHECK(mid.velocity.norm() == doctest::Approx(0.5));
    CHECK(contact_slip(mid, kParams).norm() == doctest::Approx(0).epsilon(1e-15));
    const BallState stopped = after_transition(s, kParams);
    CHECK(stopped.motion == Motion::stationary);
    CHECK(stopped.velocity == Vec3(0, 0, 0));
    CHECK((stopped.position - s.position).norm() == doctest::Approx(1.0 / (2 * kParams.roll_decel())));
  }

  TEST_CASE("spin about z decays at 5 mu_spin g / 2R in every moving state; a ball with only that spin is spinning") {
    const double rate = 5 * kParams.mu_spin * kG / (2 * kR);
    for (const BallState& s : {on_bed(Vec3(1, 0, 0), Vec3(0, 0, 30)), on_bed(Vec3(1, 0, 0), Vec3(0, 1 / kR, -30)),
                               on_bed(Vec3(0, 0, 0), Vec3(0, 0, 30))}) {
      CAPTURE(s);
      CHECK(std::abs(evolve(s, kParams, 0.1).spin.z()) == doctest::Approx(30 - rate * 0.1));
    }
    const BallState spinning = on_bed(Vec3(0, 0, 0), Vec3(0, 0, -12));
    CHECK(spinning.motion == Motion::spinning);
    CHECK(transition_time(spinning, kParams) == doctest::Approx(12 / rate));
    CHECK(evolve(spinning, kParams, 0.3).position == spinning.position);
    const BallState stopped = after_transition(spinning, kParams);
    CHECK(stopped.motion == Motion::stationary);
    CHECK(stopped.spin == Vec3(0, 0, 0));
    // Spin about z never reverses: it stops at zero even when the ball goes on rolling.
    const BallState rolling = on_bed(Vec3(2, 0, 0), Vec3(0, 2 / kR, 1));
    CHECK(evolve(rolling, kParams, 1.0).spin.z() == 0);
  }

  TEST_CASE("a stationary ball stays put and never transitions") {
    const BallState s = on_bed(Vec3(0, 0, 0), Vec3(0, 0, 0));
    CHECK(s.motion == Motion::stationary);
    CHECK(std::isinf(transition_time(s, kParams)));
    CHECK(evolve(s, kParams, 5).position == s.position);
    CHECK_FALSE(path_of(s, kParams).moves());
  }

  TEST_CASE("the path is the exact position while the state lasts") {
    const BallState s = on_bed(Vec3(1.1, 0.4, 0), Vec3(5, -20, 8));
    const Path path = path_of(s, kParams);
    const double end = transition_time(s, kParams);
    for (double t : {0.0, 0.25 * end, 0.5 * end, end}) {
      CAPTURE(t);
      CHECK((path.at(t) - evolve(s, kParams, t).position).norm() < 1e-15);
      CHECK((path.velocity_at(t) - evolve(s, kParams, t).velocity).norm() < 1e-15);
    }
  }

  TEST_CASE("classify snaps round-off onto rolling and rest, and drops vertical velocity") {
    BallState s;
    s.position = Vec3(0, 0, kR);
    s.velocity = Vec3(1, 0, 0.3);
    s.spin = Vec3(0, 1 / kR + 1e-12, 0);
    s = classify(s, kParams);
    CHECK(s.motion == Motion::rolling);
    CHECK(s.velocity.z() == 0);
    CHECK(s.spin.y() == 1 / kR);
    BallState still;
    still.position = Vec3(0, 0, kR);
    still.velocity = Vec3(1e-13, 0, 0);
    CHECK(classify(still, kParams).motion == Motion::stationary);
  }

  TEST_CASE("a rolling ball turns through its travel over R about the axis across its path") {
    const BallState s = on_bed(Vec3(0.7, 0, 0), Vec3(0, 0.7 / kR, 0));
    const double t = 0.1;  // less than half a turn, so the angle is unambiguous
    const double travel = evolve(s, kParams, t).position.x() - s.position.x();
    const Quat q = advance_orientation(s, kParams, t);
    const Eigen::AngleAxisd turn(q * s.orientation.inverse());
    CHECK(turn.angle() == doctest::Approx(travel / kR));
    CHECK(std::abs(turn.axis().y()) == doctest::Approx(1));
  }

  TEST_CASE("orientation with a turning axis: fixed steps agree with a fine integration, and repeat exactly") {
    const BallState s = on_bed(Vec3(2, 1, 0), Vec3(10, -30, 25));
    const double t = std::min(3.0, transition_time(s, kParams));
    const Quat coarse = advance_orientation(s, kParams, t);
    Quat fine = s.orientation;
    const int steps = 200000;
    for (int k = 0; k < steps; ++k) {
      const Vec3 w = evolve(s, kParams, (k + 0.5) * t / steps).spin * (t / steps);
      fine = Quat(Eigen::AngleAxisd(w.norm(), w.normalized())) * fine;
    }
    CHECK(coarse.angularDistance(fine) < 1e-3);
    CHECK(advance_orientation(s, kParams, t).coeffs() == coarse.coeffs());
  }

  TEST_CASE("kinetic energy of a solid ball counts 2/5 m R^2 for rotation") {
    const BallState s = on_bed(Vec3(1, 0, 0), Vec3(0, 1 / kR, 0));
    CHECK(kinetic_energy(s, kParams) == doctest::Approx(0.5 * kParams.ball_mass * 1.4));
  }
}
