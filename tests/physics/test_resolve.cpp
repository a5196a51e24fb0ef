// Ball-ball collision models: conservation and dissipation laws, the frictionless textbook limits
// and the friction limits (stick and slip). The cushion has its own tests (test_cushion.cpp).
#include <doctest/doctest.h>

#include <cmath>

#include "energy.h"
#include "motion.h"
#include "physics_print.h"
#include "random_scenes.h"
#include "resolve.h"
#include "scene.h"
#include "tolerance.h"

using namespace bsim;

namespace {

const double kR = PhysicsParams{}.ball_radius;

BallState ball(double x, double y, Vec3 v, Vec3 w = Vec3(0, 0, 0)) {
  BallState s;
  s.position = Vec3(x, y, kR);
  s.velocity = v;
  s.spin = w;
  s.motion = Motion::sliding;
  return s;
}

PhysicsParams params(double e_ball, double mu_ball) {
  PhysicsParams p;
  p.e_ball = e_ball;
  p.mu_ball = mu_ball;
  return p;
}

double energy(const BallState& a, const BallState& b, const PhysicsParams& p) {
  return kinetic_energy(a, p) + kinetic_energy(b, p);
}

/// Angular momentum of a ball about the origin: r x m v + I w.
Vec3 angular_momentum(const BallState& s, const PhysicsParams& p) {
  return s.position.cross(p.ball_mass * s.velocity) + 0.4 * p.ball_mass * kR * kR * s.spin;
}

}  // namespace

TEST_SUITE("resolve") {
  TEST_CASE("frictionless elastic head-on: the balls exchange velocities and keep their spins") {
    const PhysicsParams p = params(1, 0);
    const BallState a = ball(0, 0, Vec3(2, 0, 0), Vec3(3, 4, 5)), b = ball(2 * kR, 0, Vec3(0, 0, 0));
    const auto [na, nb] = resolve_ball_ball(a, b, p);
    CHECK(na.velocity.x() == 0);
    CHECK(nb.velocity.x() == 2);
    CHECK(na.spin == a.spin);
    CHECK(nb.spin == b.spin);
  }

  TEST_CASE("frictionless cut: the object ball leaves along the line of centres, the cue ball along the tangent") {
    const PhysicsParams p = params(1, 0);
    const double cut = 0.4;
    const BallState a = ball(0, 0, Vec3(1, 0, 0));
    const BallState b = ball(2 * kR * std::cos(cut), 2 * kR * std::sin(cut), Vec3(0, 0, 0));
    const auto [na, nb] = resolve_ball_ball(a, b, p);
    CHECK(std::atan2(nb.velocity.y(), nb.velocity.x()) == doctest::Approx(cut));
    CHECK(nb.velocity.norm() == doctest::Approx(std::cos(cut)));
    CHECK(na.velocity.dot(nb.velocity) == doctest::Approx(0).epsilon(1e-15));
  }

  TEST_CASE("restitution e along the line of centres: the closing speed comes back as e times it") {
    for (double e : {0.0, 0.5, 0.95}) {
      CAPTURE(e);
      const PhysicsParams p = params(e, 0.05);
      const BallState a = ball(0, 0, Vec3(1.5, 0.2, 0), Vec3(0, 30, 0)), b = ball(2 * kR, 0, Vec3(-0.3, 0, 0));
      const double before = closing_speed(a, b);
      const auto [na, nb] = resolve_ball_ball(a, b, p);
      CHECK(closing_speed(na, nb) == doctest::Approx(-e * before));
    }
  }

  TEST_CASE("ball-ball on random inputs: momentum and angular momentum conserved, energy never created") {
    scenes::Rng rng(11);
    for (int k = 0; k < 500; ++k) {
      const double e = rng.uniform(0, 1);
      const PhysicsParams p = params(e, rng.uniform(0, 0.3));
      const double angle = rng.uniform(0, 2 * M_PI);
      const Vec3 n(std::cos(angle), std::sin(angle), 0);
      const Vec3 va = rng.vector(-3, 3), wa = rng.vector(-100, 100, -100, 100);
      const Vec3 vb = rng.vector(-3, 3), wb = rng.vector(-100, 100, -100, 100);
      const BallState a = ball(0, 0, va, wa);
      const BallState b = ball(2 * kR * n.x(), 2 * kR * n.y(), vb, wb);
      if (closing_speed(a, b) <= 0) continue;
      const auto [na, nb] = resolve_ball_ball(a, b, p);
      CAPTURE(a);
      CAPTURE(b);
      const Vec3 momentum = a.velocity + b.velocity, after = na.velocity + nb.velocity;
      // Horizontal momentum is exact; the bed takes any vertical impulse (no jumps).
      CHECK(after.x() == doctest::Approx(momentum.x()).epsilon(1e-12).scale(1));
      CHECK(after.y() == doctest::Approx(momentum.y()).epsilon(1e-12).scale(1));
      CHECK(energy(na, nb, p) <= energy(a, b, p) * (1 + 1e-12));
      // About the vertical, the contact impulses conserve angular momentum.
      const double lz = (angular_momentum(a, p) + angular_momentum(b, p)).z();
      const double lz_after = (angular_momentum(na, p) + angular_momentum(nb, p)).z();
      CHECK(lz_after == doctest::Approx(lz).epsilon(1e-9).scale(1e-6));
    }
  }

  TEST_CASE("friction: a small slip sticks (the contact points end up matched), a large one slides at mu") {
    const PhysicsParams p = params(1, 0.2);
    const double cut = 0.5;
    const Vec3 n(std::cos(cut), std::sin(cut), 0);
    const BallState b = ball(2 * kR * n.x(), 2 * kR * n.y(), Vec3(0, 0, 0));
    auto tangential_slip = [&](const BallState& s1, const BallState& s2) {
      const Vec3 d = s2.position - s1.position, m = Vec3(d.x(), d.y(), 0).normalized();
      const Vec3 u = (s1.velocity + s1.spin.cross(kR * m)) - (s2.velocity + s2.spin.cross(-kR * m));
      const Vec3 ut = u - u.dot(m) * m;
      return Vec3(ut.x(), ut.y(), 0).norm();
    };
    // A nearly full hit: the slip is small against the friction available, so the contact sticks.
    const BallState a = ball(0, 0, Vec3(1, 0, 0));
    const BallState straight = ball(std::sqrt(4 * kR * kR - 1e-8), 0.0001, Vec3(0, 0, 0));
    CHECK(tangential_slip(a, straight) > 0);
    const auto [sa, sb] = resolve_ball_ball(a, straight, p);
    CHECK(tangential_slip(sa, sb) == doctest::Approx(0).epsilon(1e-12).scale(1));
    // The cut: throw turns the object ball off the line of centres, toward the cue ball's path, by
    // exactly the angle the capped friction gives. With the cue ball a at v = (1, 0, 0) without spin,
    // b at rest at angle c = `cut` on the line of centres n = (cos c, sin c, 0), and e = 1:
    //   normal impulse      jn = m (1 + e) (v.n) / 2 = m cos c
    //   slip of the contact points across n (no spin, b at rest: the slip is v itself)
    //                       v - (v.n) n = sin c t,  t = (sin c, -cos c, 0),  |slip| = sin c
    //   friction impulse    jt = min(mu jn, m |slip| / 7) = m min(mu cos c, sin c / 7)
    // so b leaves with velocity (jn n + jt t) / m, turned from n toward t by
    //   throw = atan(jt / jn) = atan(min(mu, tan c / 7)),
    // Alciatore's min(mu v_n, v_slip / 7) in impulse form. At c = 0.5 rad, tan c / 7 = 0.0780 < mu = 0.2:
    // the slip stops before friction runs out (the cap), throw = atan(tan 0.5 / 7) = 0.0779 rad.
    const auto [na, nb] = resolve_ball_ball(a, b, p);
    const double throw_angle = cut - std::atan2(nb.velocity.y(), nb.velocity.x());
    REQUIRE(std::tan(cut) / 7 < *p.mu_ball);
    CHECK(throw_angle == test::near(std::atan(std::tan(cut) / 7), 1e-12));
    CHECK(nb.velocity.dot(n) == test::near(std::cos(cut), 1e-12));
    CHECK(nb.velocity.norm() == test::near(std::hypot(std::cos(cut), std::sin(cut) / 7), 1e-12));
    // A thinner cut: tan c / 7 > mu, so friction slides at mu jn and the throw is atan(mu) whatever c is.
    const double thin = 1.2;
    REQUIRE(std::tan(thin) / 7 > *p.mu_ball);
    const BallState far = ball(2 * kR * std::cos(thin), 2 * kR * std::sin(thin), Vec3(0, 0, 0));
    const BallState thrown = resolve_ball_ball(a, far, p).second;
    CHECK(thin - std::atan2(thrown.velocity.y(), thrown.velocity.x()) == test::near(std::atan(*p.mu_ball), 1e-12));
    // mu_ball = 0 gives exactly the textbook direction.
    const auto [fa, fb] = resolve_ball_ball(a, b, params(1, 0));
    CHECK(std::atan2(fb.velocity.y(), fb.velocity.x()) == doctest::Approx(cut).epsilon(1e-15));
  }

  TEST_CASE("no impulse when the balls are not closing") {
    const PhysicsParams p = params(0.9, 0.1);
    const BallState a = ball(0, 0, Vec3(-1, 0, 0)), b = ball(2 * kR, 0, Vec3(0, 0, 0));
    const auto [na, nb] = resolve_ball_ball(a, b, p);
    CHECK(na.velocity == a.velocity);
    CHECK(nb.velocity == b.velocity);
  }

  TEST_CASE("a push removes the closing speed and keeps rolling balls rolling, losing energy") {
    const PhysicsParams p;
    BallState a = ball(0, 0, Vec3(0.3, 0, 0), Vec3(0, 0.3 / kR, 0)),
              b = ball(2 * kR, 0, Vec3(0.29, 0, 0), Vec3(0, 0.29 / kR, 0));
    a = classify(a, p);
    b = classify(b, p);
    const auto [na, nb] = resolve_push(a, b, p);
    CHECK(closing_speed(na, nb) == doctest::Approx(0).epsilon(1e-15));
    CHECK(na.motion == Motion::rolling);
    CHECK(nb.motion == Motion::rolling);
    CHECK(na.velocity.x() + nb.velocity.x() == doctest::Approx(0.59));
    CHECK(energy(na, nb, p) < energy(a, b, p));
  }
}

TEST_SUITE("ball-ball throw depends on speed (TP A-14)") {
  TEST_CASE("a stun cut: throw against TP A-14's cut-angle and speed curves") {
    // Alciatore, TP A-14 "Ball-ball collision throw": for a stun shot at speed v and cut angle c with
    // e = 1, tan(throw) = min(mu(v sin c), tan(c) / 7), mu(v_rel) = 9.951e-3 + 0.108 exp(-1.088 v_rel).
    // Values of that formula: at 1 mph (0.447 m/s) throw peaks near 5 degrees about a half-ball hit
    // (Dr. Dave's "maximum throw is about 5 degrees, at slow speed near a 1/2-ball hit"); at 7 mph
    // (3.129 m/s) it is far less. Each row: speed, cut (degrees), throw (degrees).
    const double table[][3] = {{0.447, 30, 4.715004}, {0.447, 45, 4.945123}, {0.447, 60, 4.621081},
                               {3.129, 30, 1.697632}, {3.129, 45, 1.127313}, {3.129, 60, 0.894518}};
    PhysicsParams p;
    p.e_ball = 1;
    REQUIRE_FALSE(p.mu_ball.has_value());  // the default is the speed-dependent fit
    for (const auto& row : table) {
      const double speed = row[0], cut = row[1] * kDegToRad;
      CAPTURE(speed);
      CAPTURE(row[1]);
      const BallState a = ball(0, 0, Vec3(speed, 0, 0));
      const BallState b = ball(2 * kR * std::cos(cut), 2 * kR * std::sin(cut), Vec3(0, 0, 0));
      const BallState thrown = resolve_ball_ball(a, b, p).second;
      CHECK((cut - std::atan2(thrown.velocity.y(), thrown.velocity.x())) / kDegToRad == test::near(row[2], 1e-6));
    }
  }

  TEST_CASE("a set mu_ball keeps a constant coefficient at every speed") {
    const PhysicsParams p = params(1, 0.05);
    for (double speed : {0.447, 3.129}) {
      const double cut = 60 * kDegToRad;  // tan(60)/7 = 0.247 > 0.05: friction slides at mu
      const BallState a = ball(0, 0, Vec3(speed, 0, 0));
      const BallState b = ball(2 * kR * std::cos(cut), 2 * kR * std::sin(cut), Vec3(0, 0, 0));
      const BallState thrown = resolve_ball_ball(a, b, p).second;
      CHECK(cut - std::atan2(thrown.velocity.y(), thrown.velocity.x()) == test::near(std::atan(0.05), 1e-12));
    }
    CHECK(PhysicsParams{}.ball_friction(0) == test::near(0.117951, 1e-12));
    CHECK(PhysicsParams{}.ball_friction(1) == test::near(9.951e-3 + 0.108 * std::exp(-1.088), 1e-15));
  }
}
