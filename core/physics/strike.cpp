#include "strike.h"

#include <cmath>
#include <limits>

namespace bsim {

double squirt_angle(double side, double mass_ratio) {
  if (!std::isfinite(mass_ratio)) return 0;
  const double a2 = side * side;
  return std::atan(2.5 * side * std::sqrt(1 - a2) / (1 + mass_ratio + 2.5 * (1 - a2)));
}

StrikeResult strike(const Stroke& stroke, double heading_deg, const PhysicsParams& params) {
  const double m = params.ball_mass, R = params.ball_radius, M = params.cue_mass;
  const double phi = heading_deg * kDegToRad, theta = stroke.elevation_deg * kDegToRad;
  StrikeResult out;
  // d along the stick, s across it to the shooter's right (horizontal), n = s x d across it upward.
  const Vec3 d(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), -std::sin(theta));
  const Vec3 s(std::sin(phi), -std::cos(phi), 0);
  const Vec3 n = s.cross(d);
  const double a = stroke.side, b = stroke.height;
  const Vec3 rho = R * (a * s + b * n);
  const double impulse = (1 + params.e_tip) * stroke.speed / (1 / M + (1 + 2.5 * (a * a + b * b)) / m);
  const double inertia = 0.4 * m * R * R;
  out.direction = d;
  out.spin = (impulse / inertia) * rho.cross(d);
  Vec3 v = (impulse / m) * d;
  v.z() = 0;  // the bed takes the vertical part (no jumps)
  // Right english (a > 0) sends the ball left of the stick's line: a counter-clockwise turn.
  const double ratio = params.cue_end_mass > 0 ? m / params.cue_end_mass : std::numeric_limits<double>::infinity();
  out.squirt_rad = squirt_angle(a, ratio);
  const double c = std::cos(out.squirt_rad), sn = std::sin(out.squirt_rad);
  out.velocity = Vec3(c * v.x() - sn * v.y(), sn * v.x() + c * v.y(), 0);
  return out;
}

void strike_cue_ball(Scene& scene) {
  if (!scene.cue().stroke) return;
  const auto index = static_cast<std::size_t>(scene.cue().target);
  if (index >= scene.balls.size()) return;
  const StrikeResult struck = strike(*scene.cue().stroke, scene.cue().heading_deg, scene.physics);
  scene.balls[index].velocity = struck.velocity;
  scene.balls[index].spin = struck.spin;
}

void strike_heading(const Scene& written, double heading_deg, Scene& struck) {
  if (written.cue().stroke) {
    // A stroke: the stick's strike at this heading gives the ball its velocity and spin (strike.h),
    // squirt and swerve included.
    struck.cue().heading_deg = heading_deg;
    strike_cue_ball(struck);
    return;
  }
  const int i = written.cue().target;
  const Ball& ball = written.ball(i);
  Ball& out = struck.balls[static_cast<std::size_t>(i)];
  const double turn = radians(heading_deg) - std::atan2(ball.velocity.y(), ball.velocity.x());
  const Eigen::AngleAxisd about_z(turn, Vec3::UnitZ());
  out.velocity = about_z * ball.velocity;
  out.spin = about_z * ball.spin;
  struck.cue().heading_deg = heading_deg;
}

}  // namespace bsim
