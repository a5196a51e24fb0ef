#pragma once
// The Hertz contact of two equal balls (Hertz 1882): F = k * delta^1.5 for an overlap delta, with
// k = (4/3) E* sqrt(R*), E* = E / (2 (1 - nu^2)), R* = R / 2 (Johnson, Contact Mechanics). How deep
// and how long two balls closing at a speed press into each other: the group contact's time step
// (group.h) and the sound of a ball-ball click (sound_synth.h) both come from here.
#include "physics_params.h"

namespace bsim {

/// Hertz contact time of two equal spheres, in units of delta_max / v (2 * integral_0^1 dx / sqrt(1 - x^2.5)).
inline constexpr double kHertzTimeFactor = 2.9432;

/// Two equal balls in contact: each `ball_mass` kg, pressed together by F = stiffness * overlap^1.5.
struct HertzPair {
  double ball_mass = 0;  ///< kg, each ball's
  double stiffness = 0;  ///< N/m^1.5
};

/// The scene's balls: its ball mass and `param k_hertz`.
inline HertzPair hertz_pair(const PhysicsParams& params) { return {params.ball_mass, params.k_hertz}; }

/// N/m^1.5, the Hertz stiffness (4/3) E* sqrt(R*) of two equal balls of radius `ball_radius` (m) of a
/// material with Young's modulus `young_modulus` (Pa) and Poisson's ratio `poisson`.
double hertz_stiffness(double young_modulus, double poisson, double ball_radius);

/// m, the largest overlap of an isolated Hertz contact of two balls closing at `speed` (m/s) without
/// damping: delta_max = (5 m* v^2 / (4 k))^(2/5), m* = m / 2 the pair's reduced mass.
double hertz_compression(double speed, const HertzPair& pair);
double hertz_compression(double speed, const PhysicsParams& params);
/// s, the duration of that contact: time_factor * delta_max / v, time_factor kHertzTimeFactor unless
/// a caller keeps a rounded one of its own.
double hertz_contact_time(double speed, const HertzPair& pair, double time_factor = kHertzTimeFactor);
double hertz_contact_time(double speed, const PhysicsParams& params);

}  // namespace bsim
