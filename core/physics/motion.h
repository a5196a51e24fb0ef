#pragma once
// Closed-form motion of one ball on the cloth between events (the standard sliding / rolling model:
// Marlow, "The Physics of Pocket Billiards" 1995; Alciatore, TP 4-1; as in pooltool's evolve step).
//
//   sliding : the contact point slips with velocity u = v + R z x w; friction mu_slide*m*g opposes it,
//             so the centre decelerates at mu_slide*g along u and u shrinks at 7/2*mu_slide*g.
//   rolling : u = 0; the centre decelerates at mu_roll*g, horizontal spin stays locked to v.
//   spinning: only spin about z is left.
// In every state spin about z decays at 5*mu_spin*g/(2R) until it reaches zero.
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
Vec3 contact_slip(const BallState& s, const PhysicsParams& params);

/// The motion state a ball on the bed is in, from its velocity and spin. Snaps values within round-off
/// of rolling (or of rest) onto it exactly, so transitions are not re-detected.
BallState classify(BallState s, const PhysicsParams& params);

/// The centre's path from `s` until its next transition.
Path path_of(const BallState& s, const PhysicsParams& params);

/// s from `s` to its next state transition (slide->roll, roll->spin/stop, spin->stop); infinity when none.
double transition_time(const BallState& s, const PhysicsParams& params);

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
