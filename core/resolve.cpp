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

/// Applies impulse j at offset r from the centre of a solid ball.
void apply_impulse(BallState& s, const Vec3& r, const Vec3& j, const PhysicsParams& params) {
  const double m = params.ball_mass, inertia = 0.4 * m * params.ball_radius * params.ball_radius;
  s.velocity += j / m;
  s.spin += r.cross(j) / inertia;
}

/// Unit vector from the centre to the cushion contact (the nose is above the equator when h > R).
Vec3 cushion_normal(const Vec3& toward, double nose_height, const PhysicsParams& params) {
  const double R = params.ball_radius;
  const double sin_lift = std::clamp((nose_height - R) / R, -1.0, 1.0);
  const double cos_lift = std::sqrt(1 - sin_lift * sin_lift);
  return cos_lift * toward + Vec3(0, 0, sin_lift);
}

}  // namespace

double closing_speed(const BallState& a, const BallState& b) {
  const Vec3 n = horizontal_unit(b.position - a.position);
  return (a.velocity - b.velocity).dot(n);
}

std::pair<BallState, BallState> resolve_ball_ball(const BallState& a, const BallState& b, const PhysicsParams& params) {
  BallState ra = a, rb = b;
  const double vn = closing_speed(a, b);
  if (!(vn > 0)) return {ra, rb};
  const double m = params.ball_mass, R = params.ball_radius;
  const Vec3 n = horizontal_unit(b.position - a.position);
  const Vec3 arm_a = R * n, arm_b = -R * n;

  // Normal impulse on b: equal masses share the closing momentum, scaled by restitution.
  const double jn = 0.5 * m * (1 + params.e_ball) * vn;
  Vec3 impulse_b = jn * n;

  if (params.mu_ball > 0) {
    // Coulomb friction against the contact points' relative slip, capped where the slip would stop:
    // each ball's contact point moves 7/(2m) per unit tangential impulse, so 7/m for the pair.
    const Vec3 slip = (a.velocity + a.spin.cross(arm_a)) - (b.velocity + b.spin.cross(arm_b));
    const Vec3 slip_t = slip - slip.dot(n) * n;
    const double slip_speed = slip_t.norm();
    if (slip_speed > 0) {
      const double jt = std::min(params.mu_ball * jn, m * slip_speed / 7.0);
      impulse_b += (jt / slip_speed) * slip_t;
    }
  }
  apply_impulse(ra, arm_a, -impulse_b, params);
  apply_impulse(rb, arm_b, impulse_b, params);
  return {classify(ra, params), classify(rb, params)};
}

std::pair<BallState, BallState> resolve_push(const BallState& a, const BallState& b, const PhysicsParams& params) {
  BallState ra = a, rb = b;
  const double vn = closing_speed(a, b);
  if (!(vn > 0)) return {ra, rb};
  const double m = params.ball_mass, R = params.ball_radius;
  const Vec3 n = horizontal_unit(b.position - a.position);
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

double cushion_closing_speed(const BallState& ball, const Vec3& toward, double nose_height, const PhysicsParams& params) {
  return ball.velocity.dot(cushion_normal(toward, nose_height, params));
}

BallState resolve_ball_cushion(const BallState& ball, const Vec3& toward, double nose_height, const PhysicsParams& params) {
  BallState out = ball;
  const Vec3 normal = cushion_normal(toward, nose_height, params);
  const double approach = ball.velocity.dot(normal);
  if (!(approach > 0)) return out;
  const double m = params.ball_mass;
  const Vec3 arm = params.ball_radius * normal;

  // Normal impulse through the centre (no torque): restitution on the approach speed.
  Vec3 impulse = -(1 + params.e_rail) * m * approach * normal;

  // Friction against the slip of the contact point in the tangent plane (Han's stick/slip branches):
  // the point moves 7/(2m) per unit tangential impulse.
  const Vec3 point_velocity = ball.velocity + ball.spin.cross(arm);
  const Vec3 slip = point_velocity - point_velocity.dot(normal) * normal;
  const double slip_speed = slip.norm();
  if (slip_speed > 0 && params.mu_rail > 0) {
    const double jt = std::min(params.mu_rail * (1 + params.e_rail) * m * approach, 2.0 * m * slip_speed / 7.0);
    impulse -= (jt / slip_speed) * slip;
  }
  apply_impulse(out, arm, impulse, params);
  return classify(out, params);
}

}  // namespace bsim
