#pragma once
// The kinetic energy of a ball: what the tests and the benchmark's soak hold collisions to (never more
// after one than before).
#include "ball_state.h"
#include "physics_params.h"

namespace bsim {

/// J, kinetic energy (translation + rotation) of a solid ball.
inline double kinetic_energy(const BallState& s, const PhysicsParams& params) {
  const double m = params.ball_mass, R = params.ball_radius;
  return 0.5 * m * s.velocity.squaredNorm() + 0.5 * 0.4 * m * R * R * s.spin.squaredNorm();
}

}  // namespace bsim
