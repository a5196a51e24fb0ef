#pragma once
// Collision models: the states of the balls just before a contact -> their states just after.
// Both are instantaneous impulses with Coulomb friction limited to stopping the slip ("stick"):
//
//  Ball-ball: equal masses, restitution e_ball along the line of centres, friction mu_ball on the
//  relative slip of the contact points (spin transfer and cut-induced throw). This is the impulse form
//  of Alciatore's throw analysis (TP A-14: throw = min(mu v_n, v_slip / 7)); with mu_ball = 0 it is
//  exactly the frictionless textbook collision and each ball keeps its spin.
//
//  Ball-cushion: Han, "Dynamics in carom and three cushion billiards", J. Mech. Sci. Tech. 19(4),
//  2005, as published: the impulse acts at the nose, which touches the ball at height h above the bed,
//  along the line to the ball's centre, with restitution e_rail along that line and friction mu_rail
//  against the slip of that point (stick or slide), so the cushion also acts on the ball's spin. The
//  ball is free during the impact; the bed then takes the vertical velocity the tilted impulse leaves.
//
// The bed keeps balls on it: a vertical velocity an impulse would give is dropped (no jumps).
#include <utility>

#include "ball_state.h"
#include "physics_params.h"

namespace bsim {

/// m/s, speed at which b's centre and a's approach along the line of centres (> 0 when closing).
double closing_speed(const BallState& a, const BallState& b);

/// Touching balls a and b -> after the impact. Unchanged when they are not closing.
std::pair<BallState, BallState> resolve_ball_ball(const BallState& a, const BallState& b, const PhysicsParams& params);

/// Applies impulse j at offset r from the centre of a solid ball (moment of inertia 2/5 m R^2).
void apply_impulse(BallState& s, const Vec3& r, const Vec3& j, const PhysicsParams& params);

/// N s, the friction impulse on b (on a: its opposite) of a contact with unit normal n from a to b that
/// carries `normal_impulse`: Coulomb friction mu_ball against the contact points' relative slip, capped
/// where that slip would stop. Shared by the pairwise model and the group contact (group.h).
Vec3 ball_ball_friction(const BallState& a, const BallState& b, const Vec3& n, double normal_impulse,
                        const PhysicsParams& params);

/// A push: a gentle contact after which the two would at once press together again (one ball driving
/// another, as in a follow shot at close range or two balls rolling on side by side). Instead of a
/// bounce the closing speed is removed, without friction, and a ball rolling (or at rest) stays rolling:
/// the cloth's static friction acts with the push, so it answers with its rolling mass 7/5 m. Energy
/// is lost as in any plastic impact.
std::pair<BallState, BallState> resolve_push(const BallState& a, const BallState& b, const PhysicsParams& params);

/// Where the nose of a cushion at `nose_height` touches the ball; `toward` is the horizontal unit vector
/// from the ball's centre toward the cushion.
Vec3 cushion_contact_point(const BallState& ball, const Vec3& toward, double nose_height, const PhysicsParams& params);

/// m/s, the ball's approach speed along the cushion contact normal (> 0 when closing).
double cushion_closing_speed(const BallState& ball, const Vec3& toward, double nose_height,
                             const PhysicsParams& params);

/// A ball touching a cushion -> after the impact. Unchanged when it is not closing.
BallState resolve_ball_cushion(const BallState& ball, const Vec3& toward, double nose_height,
                               const PhysicsParams& params);

}  // namespace bsim
