#include "resolve.h"

#include <algorithm>
#include <cmath>

#include "motion.h"

namespace bsim {

namespace {

Vec3 horizontal_unit(const Vec3& v) {
  const Vec3 h(v.x(), v.y(), 0);
  const double n = h.norm();
  return n > 0 ? Vec3(h / n) : Vec3(1, 0, 0);
}

/// Unit vector from the centre to the cushion contact (the nose is above the equator when h > R).
Vec3 cushion_normal(const Vec3& toward, double nose_height, const PhysicsParams& params) {
  const double R = params.ball_radius;
  const double sin_lift = std::clamp((nose_height - R) / R, -1.0, 1.0);
  const double cos_lift = std::sqrt(1 - sin_lift * sin_lift);
  return cos_lift * toward + Vec3(0, 0, sin_lift);
}

}  // namespace

void apply_impulse(BallState& s, const Vec3& r, const Vec3& j, const PhysicsParams& params) {
  const double m = params.ball_mass, inertia = 0.4 * m * params.ball_radius * params.ball_radius;
  s.velocity += j / m;
  s.spin += r.cross(j) / inertia;
}

double closing_speed(const BallState& a, const BallState& b) {
  const Vec3 n = horizontal_unit(b.position - a.position);
  return (a.velocity - b.velocity).dot(n);
}

Vec3 ball_ball_friction(const BallState& a, const BallState& b, const Vec3& n, double normal_impulse,
                        const PhysicsParams& params) {
  // Coulomb friction against the contact points' relative slip, capped where the slip would stop:
  // each ball's contact point moves 7/(2m) per unit tangential impulse, so 7/m for the pair.
  const double m = params.ball_mass;
  const Vec3 arm_a = params.ball_radius * n, arm_b = -params.ball_radius * n;
  const Vec3 slip = (a.velocity + a.spin.cross(arm_a)) - (b.velocity + b.spin.cross(arm_b));
  const Vec3 slip_t = slip - slip.dot(n) * n;
  const double slip_speed = slip_t.norm();
  if (!(slip_speed > 0)) return Vec3(0, 0, 0);
  // The coefficient depends on that slip speed (TP A-14's fit) unless the scene sets mu_ball.
  const double jt = std::min(params.ball_friction(slip_speed) * normal_impulse, m * slip_speed / 7.0);
  return (jt / slip_speed) * slip_t;
}

std::pair<BallState, BallState> resolve_ball_ball(const BallState& a, const BallState& b, const PhysicsParams& params) {
  const double vn = closing_speed(a, b);
  if (!(vn > 0)) return {a, b};
  BallState ra = a, rb = b;
  const double m = params.ball_mass;
  const Vec3 n = horizontal_unit(b.position - a.position);
  const Vec3 arm_a = params.ball_radius * n, arm_b = -params.ball_radius * n;

  // Normal impulse on b: equal masses share the closing momentum, scaled by restitution.
  const double jn = 0.5 * m * (1 + params.e_ball) * vn;
  Vec3 impulse_b = jn * n;

  if (params.has_ball_friction()) impulse_b += ball_ball_friction(a, b, n, jn, params);
  apply_impulse(ra, arm_a, -impulse_b, params);
  apply_impulse(rb, arm_b, impulse_b, params);
  return {classify(ra, params), classify(rb, params)};
}

std::pair<BallState, BallState> resolve_push(const BallState& a, const BallState& b, const PhysicsParams& params) {
  const double vn = closing_speed(a, b);
  if (!(vn > 0)) return {a, b};
  const double m = params.ball_mass, R = params.ball_radius;
  const Vec3 n = horizontal_unit(b.position - a.position);
  BallState ra = a, rb = b;
  auto rolls = [](const BallState& s) { return s.motion != Motion::sliding; };
  auto inverse_mass = [&](const BallState& s) { return rolls(s) ? 5.0 / (7.0 * m) : 1.0 / m; };
  const double j = vn / (inverse_mass(a) + inverse_mass(b));
  auto push = [&](BallState& s, double sign) {
    s.velocity += sign * j * inverse_mass(s) * n;
    if (rolls(s)) {
      const Vec3 locked = Vec3(0, 0, 1).cross(s.velocity) / R;
      s.spin.x() = locked.x();
      s.spin.y() = locked.y();
    }
    s = classify(s, params);
  };
  push(ra, -1);
  push(rb, 1);
  return {ra, rb};
}

Vec3 cushion_contact_point(const BallState& ball, const Vec3& toward, double nose_height, const PhysicsParams& params) {
  return ball.position + params.ball_radius * cushion_normal(toward, nose_height, params);
}

double cushion_closing_speed(const BallState& ball, const Vec3& toward, double nose_height,
                             const PhysicsParams& params) {
  return ball.velocity.dot(cushion_normal(toward, nose_height, params));
}

BallState resolve_ball_cushion(const BallState& ball, const Vec3& toward, double nose_height,
                               const PhysicsParams& params) {
  BallState out = ball;
  const double m = params.ball_mass, R = params.ball_radius, e = params.e_rail, mu = params.mu_rail;
  // Han, "Dynamics in carom and three cushion billiards", J. Mech. Sci. Tech. 19(4), 2005. The nose
  // touches the ball at angle theta above its equator, sin theta = (h - R) / R, so the contact normal
  // n (from the centre to the nose) leans up by theta. The ball is taken as free during the impact:
  //  - normal: restitution e along n, P = (1 + e) m c, where c is the approach speed along n;
  //  - friction F in the tangent plane at the nose, against the slip s of the ball's point there. An
  //    impulse F through that point changes s by 7/(2m) F (its velocity by F/m, and its spin's part by
  //    5/(2m) F), so F = -2m s / 7 stops the slip ("stick"), unless that needs more than mu P: then
  //    the nose slides on the ball and F = -mu P s / |s| (Coulomb).
  // The ball's velocity changes by (-P n + F) / m and its spin by the torque of F about its centre
  // (P passes through the centre). The bed then takes the vertical velocity this leaves.
  const double sin_lift = std::clamp((nose_height - R) / R, -0.99, 0.99);
  const Vec3 n = std::sqrt(1 - sin_lift * sin_lift) * toward + Vec3(0, 0, sin_lift);
  const double approach = ball.velocity.dot(n);
  if (!(approach > 0)) return out;
  const double normal = (1 + e) * m * approach;
  const Vec3 arm = R * n;
  const Vec3 slip = ball.velocity + ball.spin.cross(arm);
  Vec3 friction = -2.0 * m / 7.0 * (slip - slip.dot(n) * n);
  const double stick = friction.norm();
  if (stick > mu * normal) friction *= mu * normal / stick;
  const Vec3 impulse = -normal * n + friction;
  out.velocity += impulse / m;
  out.velocity.z() = 0;
  out.spin += arm.cross(friction) / (0.4 * m * R * R);
  // With a small e (below about 0.15 at the standard nose and mu_rail 0.2) the nose's push down into
  // the bed can leave the free ball still moving into the cushion once the bed has taken its vertical
  // velocity; the cushion then stops that approach with a push through the centre (no spin).
  const double still_closing = out.velocity.dot(toward);
  if (still_closing > 0) out.velocity -= still_closing * toward;
  return classify(out, params);
}

}  // namespace bsim
