#include "motion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace bsim {

using motion_detail::decayed_spin_z;
using motion_detail::slip_direction;

namespace {

const Vec3 kUp(0, 0, 1);

Quat rotation(const Vec3& axis_angle) {
  const double angle = axis_angle.norm();
  if (angle == 0) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(angle, axis_angle / angle));
}

/// Angular velocity dt after s (within the same motion state): evolve's spin, without the position.
Vec3 spin_at(const BallState& s, const PhysicsParams& params, double dt) {
  const double R = params.ball_radius;
  Vec3 w = s.spin;
  if (s.motion == Motion::sliding) {
    w += (2.5 * params.mu_slide * params.g / R * dt) * kUp.cross(slip_direction(s, params));
  } else if (s.motion == Motion::rolling) {
    const double speed = s.velocity.norm();
    if (speed > 0) w = kUp.cross(s.velocity) * ((speed - params.roll_decel() * dt) / (speed * R));
  }
  w.z() = decayed_spin_z(s.spin.z(), params.spin_decel(), dt);
  return w;
}

}  // namespace

BallState after_transition(const BallState& s, const PhysicsParams& params) {
  BallState out = evolve(s, params, transition_time(s, params));
  switch (s.motion) {
    case Motion::sliding: {
      // The slip is zero now by construction: roll (or rest) exactly.
      const Vec3 locked = kUp.cross(out.velocity) / params.ball_radius;
      out.spin.x() = locked.x();
      out.spin.y() = locked.y();
      out.motion = Motion::rolling;
      return classify(out, params);
    }
    case Motion::rolling:
      out.velocity.setZero();
      out.spin.x() = 0;
      out.spin.y() = 0;
      out.motion = out.spin.z() != 0 ? Motion::spinning : Motion::stationary;
      return out;
    case Motion::spinning:
      out.spin.setZero();
      out.motion = Motion::stationary;
      return out;
    default: return out;
  }
}

namespace {

/// advance_orientation where the rotation axis stays fixed, in closed form; nullopt where it turns
/// (which depends on `s` alone, never on dt > 0).
std::optional<Quat> closed_form_orientation(const BallState& s, const PhysicsParams& params, double dt) {
  if (dt <= 0 || s.motion == Motion::stationary || s.motion == Motion::pocketed) return s.orientation;
  const double R = params.ball_radius;
  const double k = params.spin_decel();
  auto turned = [&](const Vec3& axis_angle) { return (rotation(axis_angle) * s.orientation).normalized(); };

  // Fixed axis: the rotation angle is the integral of the spin, in closed form.
  if (s.motion == Motion::spinning) {
    const double angle = s.spin.z() * dt - std::copysign(0.5 * k * dt * dt, s.spin.z());
    return turned(Vec3(0, 0, angle));
  }
  if (s.motion == Motion::falling) return turned(s.spin * dt);
  if (s.spin.z() == 0) {
    if (s.motion == Motion::rolling) {
      const double speed = s.velocity.norm();
      if (speed == 0) return s.orientation;
      const Vec3 axis = kUp.cross(s.velocity / speed);
      return turned(axis * ((speed * dt - 0.5 * params.roll_decel() * dt * dt) / R));
    }
    // Sliding with the horizontal spin parallel to the friction torque's axis.
    const Vec3 axis = kUp.cross(slip_direction(s, params));
    const Vec3 w(s.spin.x(), s.spin.y(), 0);
    if (std::abs(w.x() * axis.y() - w.y() * axis.x()) <= 1e-12 * (1 + w.norm())) {
      const double w0 = w.dot(axis);
      const double accel = 2.5 * params.mu_slide * params.g / R;
      return turned(axis * (w0 * dt + 0.5 * accel * dt * dt));
    }
  }
  return std::nullopt;
}

/// The axis turns: fourth-order Magnus steps on a fixed grid from the segment start. Within a state
/// the spin is linear in time, w(t) = w0 + w1 t, except where spin about z reaches zero, so each step
/// (split at that instant) is exp(h w_mid - h^3/12 w_mid x w1) to fourth order.
class MagnusGrid {
 public:
  MagnusGrid(const BallState& s, const PhysicsParams& params)
      : s_(s),
        params_(params),
        kink_(s.spin.z() != 0 && params.spin_decel() > 0 ? std::abs(s.spin.z()) / params.spin_decel() : -1.0) {}

  /// Whole steps of the grid before dt.
  static long whole_steps(double dt) { return static_cast<long>(std::floor(dt / kOrientationStep)); }
  /// s, where step i of the grid starts.
  static double node(long i) { return static_cast<double>(i) * kOrientationStep; }

  /// q turned over [a, b], split where spin about z stops.
  void step(Quat& q, double a, double b) const {
    if (kink_ > a && kink_ < b) {
      magnus(q, a, kink_);
      magnus(q, kink_, b);
    } else {
      magnus(q, a, b);
    }
  }

 private:
  void magnus(Quat& q, double a, double b) const {
    const double h = b - a;
    if (h <= 0) return;
    const Vec3 wa = spin_at(s_, params_, a), wb = spin_at(s_, params_, b), mid = 0.5 * (wa + wb);
    q = (rotation(h * mid - (h * h / 12.0) * mid.cross(wb - wa)) * q).normalized();
  }

  const BallState& s_;
  const PhysicsParams& params_;
  double kink_;
};

}  // namespace

Quat advance_orientation(const BallState& s, const PhysicsParams& params, double dt) {
  return advance_orientation(s, params, dt, {});
}

Quat advance_orientation(const BallState& s, const PhysicsParams& params, double dt, const std::vector<Quat>& steps) {
  if (const std::optional<Quat> q = closed_form_orientation(s, params, dt)) return *q;
  const MagnusGrid grid(s, params);
  const long whole = MagnusGrid::whole_steps(dt);
  // Resume from the last saved whole step at or before dt: the same steps follow, so the same value.
  long i = steps.empty() ? 0 : std::min(whole, static_cast<long>(steps.size()) - 1);
  Quat q = steps.empty() ? s.orientation : steps[static_cast<std::size_t>(i)];
  for (; i < whole; ++i) grid.step(q, MagnusGrid::node(i), MagnusGrid::node(i + 1));
  grid.step(q, MagnusGrid::node(whole), dt);
  return q;
}

std::vector<Quat> orientation_steps(const BallState& s, const PhysicsParams& params, double dt_max) {
  std::vector<Quat> steps;
  if (closed_form_orientation(s, params, dt_max)) return steps;
  const MagnusGrid grid(s, params);
  const long whole = MagnusGrid::whole_steps(dt_max);
  steps.reserve(static_cast<std::size_t>(whole) + 1);
  Quat q = s.orientation;
  steps.push_back(q);
  for (long i = 0; i < whole; ++i) {
    grid.step(q, MagnusGrid::node(i), MagnusGrid::node(i + 1));
    steps.push_back(q);
  }
  return steps;
}

}  // namespace bsim
