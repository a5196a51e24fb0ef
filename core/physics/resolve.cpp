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
  const double jt = std::min(params.mu_ball * normal_impulse, m * slip_speed / 7.0);
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

  if (params.mu_ball > 0) impulse_b += ball_ball_friction(a, b, n, jn, params);
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
  const double vn = Vec3(ball.velocity.x(), ball.velocity.y(), 0).dot(toward);  // horizontal approach
  if (!(vn > 0)) return out;
  const double m = params.ball_mass, R = params.ball_radius, e = params.e_rail, mu = params.mu_rail;
  const double sin_lift = std::clamp((nose_height - R) / R, -0.99, 0.99);
  const double cos_lift = std::sqrt(1 - sin_lift * sin_lift);
  // Contact frame: n from the centre to the nose; e1 along the cushion; e2 completes the tangent plane.
  const Vec3 n = cos_lift * toward + Vec3(0, 0, sin_lift);
  const Vec3 e1 = Vec3(0, 0, 1).cross(toward);
  const Vec3 e2 = -sin_lift * toward + Vec3(0, 0, cos_lift);
  const Vec3 arm = R * n;
  const Vec3 slip = ball.velocity + ball.spin.cross(arm);
  const double u1 = slip.dot(e1), u2 = slip.dot(e2);

  // Impulses: P along -n at the nose, F = F1 e1 + F2 e2 friction there, and the bed's B along +z under
  // the ball, which keeps it on the bed (B = P sin - F2 cos). Restitution acts on the horizontal
  // approach: the ball leaves at e times it, m dv_n = -P cos - F2 sin = -(1 + e) m vn. The nose's slip
  // then changes by 7/(2m) F1 along e1 and by (1 + e) vn sin + 5/(2m) F2 along e2, so it sticks with
  // F1 = -2m u1 / 7, F2 = -2m (u2 + (1 + e) vn sin) / 5, unless that needs more than mu P: then the
  // friction slides, in the same direction, at mu P (Coulomb).
  double f1 = -2.0 * m * u1 / 7.0, f2 = -2.0 * m * (u2 + (1 + e) * vn * sin_lift) / 5.0;
  auto normal_impulse = [&](double friction2) { return ((1 + e) * m * vn - friction2 * sin_lift) / cos_lift; };
  const double stick = std::hypot(f1, f2);
  if (stick > mu * normal_impulse(f2)) {
    const double scale = mu * (1 + e) * m * vn / (stick * cos_lift + mu * f2 * sin_lift);
    f1 *= scale;
    f2 *= scale;
  }
  const double p = normal_impulse(f2);
  const Vec3 friction = f1 * e1 + f2 * e2;
  const double inertia = 0.4 * m * R * R;
  out.velocity += (-p * n + friction + (p * sin_lift - f2 * cos_lift) * Vec3(0, 0, 1)) / m;
  out.velocity.z() = 0;  // exactly what the bed's impulse does, without round-off
  out.spin += arm.cross(friction) / inertia;
  return classify(out, params);
}

}  // namespace bsim
