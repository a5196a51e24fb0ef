#pragma once
// A ball dropping into a pocket, after the seed's model: its centre has crossed the pocket's circle.
// Below sqrt(g R) it rolls over the edge (pivoting on the lip until the lip's push vanishes, which
// happens at once from sqrt(g R) up: the seed's threshold), then it flies; it bounces off the pocket's
// far wall and stops at a fixed depth, where it stays, taking no further part in the shot.
// Only for display: integrated in fixed steps from the entry, so every query gives the same answer.
#include "ball_state.h"
#include "physics_params.h"
#include "scene.h"

namespace bsim {

/// m, how far below its height on the bed a pocketed ball's centre comes to rest.
inline constexpr double kPocketDepth = 0.1;
/// Share of the normal speed a ball keeps bouncing off the pocket's wall.
inline constexpr double kPocketWallRestitution = 0.3;
/// s, integration step of the drop.
inline constexpr double kFallStep = 1.0 / 2000.0;

/// s from entering the pocket to resting at its bottom.
double fall_duration(const BallState& entry, const Pocket& pocket, const PhysicsParams& params);

/// The falling ball dt seconds after it entered (state `falling`; `pocketed` from fall_duration on).
BallState fall_state(const BallState& entry, const Pocket& pocket, const PhysicsParams& params, double dt);

}  // namespace bsim
