#pragma once
// Closed-form motion of one ball on the cloth between events (the standard sliding / rolling model:
// Marlow, "The Physics of Pocket Billiards" 1995; Alciatore, TP 4-1; as in pooltool's evolve step).
//
//   sliding : the contact point slips with velocity u = v + R z x w; friction mu_slide*m*g opposes it,
//             so the centre decelerates at mu_slide*g along u and u shrinks at 7/2*mu_slide*g.
//   rolling : u = 0; the centre decelerates at mu_roll*g, horizontal spin stays locked to v.
//   spinning: only spin about z is left.
// In every state spin about z decays at 5*mu_spin*g/(2R) until it reaches zero.
#include <cmath>
#include <limits>
#include <vector>

#include "ball_state.h"
#include "physics_params.h"

namespace bsim {

/// The centre's path while the motion state lasts: p(t) = p + v t + a t^2 / 2 (a is constant).
struct Path {
  Vec3 p{0, 0, 0};
  Vec3 v{0, 0, 0};
  Vec3 a{0, 0, 0};
  Vec3 at(double t) const { return p + t * (v + 0.5 * t * a); }
  Vec3 velocity_at(double t) const { return v + t * a; }
  bool moves() const { return v.x() != 0 || v.y() != 0 || v.z() != 0 || a.x() != 0 || a.y() != 0 || a.z() != 0; }
};

/// m/s, velocity of the cloth contact point (zero while rolling).
inline Vec3 contact_slip(const BallState& s, const PhysicsParams& params) {
  const Vec3 up(0, 0, 1);
  return Vec3(s.velocity.x(), s.velocity.y(), 0) + params.ball_radius * up.cross(s.spin);
}

/// The motion state a ball on the bed is in, from its velocity and spin. Snaps values within round-off
/// of rolling (or of rest) onto it exactly, so transitions are not re-detected.
BallState classify(BallState s, const PhysicsParams& params);

/// The centre's path from `s` until its next transition.
Path path_of(const BallState& s, const PhysicsParams& params);

/// s from `s` to its next state transition (slide->roll, roll->spin/stop, spin->stop); infinity when none.
double transition_time(const BallState& s, const PhysicsParams& params);

// The small functions above, defined here so that callers in other files inline them (a ball's state
// passed and returned whole costs more than their arithmetic).
namespace motion_detail {

/// m/s: a contact-point slip this small is round-off of rolling (real slips are mm/s and up).
inline constexpr double kSlipTolerance = 1e-9;
/// m/s and rad/s: speeds this small are round-off of rest.
inline constexpr double kRestSpeed = 1e-9;
inline constexpr double kRestSpin = 1e-9;

/// v.norm() <= limit, the square root (Eigen's norm is the square root of squaredNorm) taken only where
/// the square lies within a part in 1e6 of the limit's: elsewhere the squares give the same answer.
inline bool norm_at_most(const Vec3& v, double limit) {
  const double square = v.squaredNorm(), limit2 = limit * limit;
  if (square < limit2 * (1 - 1e-6)) return true;
  if (square > limit2 * (1 + 1e-6)) return false;
  return std::sqrt(square) <= limit;
}

/// Spin about z after dt of decay at `rate` rad/s^2, stopping at zero.
inline double decayed_spin_z(double wz, double rate, double dt) {
  const double left = std::abs(wz) - rate * dt;
  if (left <= 0) return 0.0;
  return std::copysign(left, wz);
}

/// Unit direction of the slip while sliding (constant through the sliding phase).
inline Vec3 slip_direction(const BallState& s, const PhysicsParams& params) {
  const Vec3 u = contact_slip(s, params);
  const double n = u.norm();
  return n > 0 ? Vec3(u / n) : Vec3(0, 0, 0);
}

}  // namespace motion_detail

inline BallState classify(BallState s, const PhysicsParams& params) {
  using namespace motion_detail;
  if (s.motion == Motion::falling || s.motion == Motion::pocketed) return s;
  s.velocity.z() = 0;  // the bed carries the ball: jumps are not modelled
  const double R = params.ball_radius;
  if (norm_at_most(contact_slip(s, params), kSlipTolerance)) {
    // Rolling (or at rest): lock the horizontal spin to the velocity exactly.
    const Vec3 locked = Vec3(0, 0, 1).cross(s.velocity) / R;
    s.spin.x() = locked.x();
    s.spin.y() = locked.y();
    if (norm_at_most(s.velocity, kRestSpeed)) {
      s.velocity.setZero();
      s.spin.x() = 0;
      s.spin.y() = 0;
      if (std::abs(s.spin.z()) <= kRestSpin) s.spin.z() = 0;
      s.motion = s.spin.z() != 0 ? Motion::spinning : Motion::stationary;
    } else {
      s.motion = Motion::rolling;
    }
  } else {
    s.motion = Motion::sliding;
  }
  return s;
}

inline Path path_of(const BallState& s, const PhysicsParams& params) {
  Path path;
  path.p = s.position;
  switch (s.motion) {
    case Motion::sliding:
      path.v = s.velocity;
      path.a = -params.mu_slide * params.g * motion_detail::slip_direction(s, params);
      break;
    case Motion::rolling: {
      path.v = s.velocity;
      const double speed = s.velocity.norm();
      if (speed > 0) path.a = -params.roll_decel() / speed * s.velocity;
      break;
    }
    default: break;
  }
  return path;
}

inline BallState evolve(const BallState& s, const PhysicsParams& params, double dt) {
  using motion_detail::decayed_spin_z;
  using motion_detail::slip_direction;
  const Vec3 up(0, 0, 1);
  BallState out = s;
  if (dt == 0) return out;
  const double R = params.ball_radius;
  const double wz = decayed_spin_z(s.spin.z(), params.spin_decel(), dt);
  switch (s.motion) {
    case Motion::sliding: {
      const Vec3 u_hat = slip_direction(s, params);
      const double f = params.mu_slide * params.g;
      out.position = s.position + dt * (s.velocity - 0.5 * f * dt * u_hat);
      out.velocity = s.velocity - f * dt * u_hat;
      out.spin = s.spin + (2.5 * f / R * dt) * up.cross(u_hat);
      out.spin.z() = wz;
      break;
    }
    case Motion::rolling: {
      const double speed = s.velocity.norm();
      const Vec3 v_hat = speed > 0 ? Vec3(s.velocity / speed) : Vec3(0, 0, 0);
      const double a = params.roll_decel();
      out.position = s.position + (dt * (speed - 0.5 * a * dt)) * v_hat;
      out.velocity = (speed - a * dt) * v_hat;
      out.spin = up.cross(out.velocity) / R;
      out.spin.z() = wz;
      break;
    }
    case Motion::spinning: out.spin.z() = wz; break;
    default: break;
  }
  return out;
}

inline double transition_time(const BallState& s, const PhysicsParams& params) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  switch (s.motion) {
    case Motion::sliding: {
      const double rate = 3.5 * params.mu_slide * params.g;
      return rate > 0 ? contact_slip(s, params).norm() / rate : kNever;
    }
    case Motion::rolling: {
      const double rate = params.roll_decel();
      return rate > 0 ? s.velocity.norm() / rate : kNever;
    }
    case Motion::spinning: {
      const double rate = params.spin_decel();
      return rate > 0 ? std::abs(s.spin.z()) / rate : kNever;
    }
    default: return kNever;
  }
}

/// The exact state dt seconds after `s`, for 0 <= dt <= transition_time(s). The motion label is kept;
/// orientation is not advanced (see advance_orientation).
BallState evolve(const BallState& s, const PhysicsParams& params, double dt);

/// The state at a transition: evolve to `transition_time` and classify the result.
BallState after_transition(const BallState& s, const PhysicsParams& params);

/// Orientation dt seconds after `s` (same preconditions as evolve). Exact while the rotation axis is
/// fixed; otherwise integrated in fixed steps of kOrientationStep from `s` (fourth-order Magnus; the
/// drift is below a milliradian a second), so the same query always gives the same answer.
Quat advance_orientation(const BallState& s, const PhysicsParams& params, double dt);

/// The orientations the integration of advance_orientation(s, params, dt) passes through at whole
/// steps of kOrientationStep, for every dt up to dt_max (first s.orientation); empty where the axis is
/// fixed and the closed form needs none. Saved once per segment, they make every later query cheap.
std::vector<Quat> orientation_steps(const BallState& s, const PhysicsParams& params, double dt_max);

/// advance_orientation(s, params, dt), resumed from the last of `steps` (orientation_steps of the
/// same s and params) at or before dt: at most one step is integrated, and the value is the same to
/// the bit, as the same steps are taken in the same order. With no steps, it integrates from s.
Quat advance_orientation(const BallState& s, const PhysicsParams& params, double dt, const std::vector<Quat>& steps);

/// s, step of the orientation integration when the rotation axis turns (display only).
inline constexpr double kOrientationStep = 1.0 / 60.0;

}  // namespace bsim
