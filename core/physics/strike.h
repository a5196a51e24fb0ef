#pragma once
// The stick's strike: a stroke (speed, tip offset, elevation) and the stick's heading -> the struck
// ball's velocity and spin just after the tip leaves it. The one place where a stroke becomes motion.
//
// The model is the instantaneous point impulse of Alciatore, "Cue tip efficiency" / TP A-30 (the
// (1 + e) form), the same as Leckie & Greenspan, "An Event-Based Pool Physics Simulator", Advances in
// Computer Games 11, LNCS 4250 (2006), FastFiz, and pooltool's `instantaneous_point` (after its PR #181,
// whose offsets are measured across the stick, as ours are). The stick (mass M, speed V at impact)
// meets the ball (m, R, I = 2/5 m R^2) at offsets a (side) and b (height), fractions of R across the
// stick's axis d; the impulse J acts along d through the contact point, centre offset rho = R (a s + b n):
//   J = (1 + e) V / (1/M + (1 + 5/2 (a^2 + b^2)) / m),   v = (J / m) d,   w = (J / I) rho x d,
// so |v| = (1 + e) V / (1 + m/M + 5/2 (a^2 + b^2)) and w R / |v| = 5/2 sqrt(a^2 + b^2).
//  - Squirt (Alciatore, "The physics of squirt", TP A-31; pooltool's squirt.py): the ball leaves the
//    stick's line away from the english side by atan(5/2 a sqrt(1 - a^2) / (1 + m/m_e + 5/2 (1 - a^2)))
//    with m_e the stick's effective end mass (none when m_e = 0); the spin is not turned.
//  - The bed takes the vertical part of the impulse of an elevated stick (no jumps): the velocity's
//    vertical part is dropped. The bed's push acts through the ball's centre, so the spin is kept, and
//    an elevated stick with english leaves spin about the direction of travel: the sliding motion then
//    curves the path (swerve, masse) with no further model (motion.h).
#include "physics_params.h"
#include "scene.h"
#include "vec.h"

namespace bsim {

struct StrikeResult {
  Vec3 velocity{0, 0, 0};   ///< m/s, horizontal, squirt included
  Vec3 spin{0, 0, 0};       ///< rad/s
  Vec3 direction{1, 0, 0};  ///< unit vector of the stick's axis, pointing from butt to tip (down when raised)
  double squirt_rad = 0;    ///< angle between the stick's heading and the ball's, > 0 counter-clockwise
};

/// The struck ball's velocity and spin from `stroke` with the stick heading `heading_deg` (counter-
/// clockwise from +x, the `cue` line's heading). Pure; uses the ball's and the stick's params.
StrikeResult strike(const Stroke& stroke, double heading_deg, const PhysicsParams& params);

/// Squirt angle in rad (TP A-31) for a side offset `side` (fraction of R) and ball/end-mass ratio
/// `mass_ratio` = m / m_e; > 0 for side > 0. Zero when mass_ratio is infinite (no end mass).
double squirt_angle(double side, double mass_ratio);

/// Gives the `cue` line's ball its velocity and spin from the scene's stroke and the cue's heading,
/// as the simulation takes them at the strike; does nothing without a stroke. Call it whenever the
/// heading changes (an aim search sets Scene::cue.heading_deg and calls it again) before simulate().
void strike_cue_ball(Scene& scene);

/// The shot as struck with the stick at `heading_deg`: the one place a heading becomes the struck ball's
/// initial state. `struck` is `written` (the scene as parsed) with cue.heading_deg set and the struck
/// ball's state at the strike set. In the seed's form the struck ball's `ball`-line velocity is turned
/// about the vertical to the heading, keeping its speed, and its `spin`-line spin is turned by the same
/// angle: spin written for a shot along the written velocity (draw about the axis across it, side spin
/// about the vertical) stays draw and side spin along the heading. A strike from the stick (a stroke)
/// replaces this body; the solver calls nothing else to strike.
void strike_heading(const Scene& written, double heading_deg, Scene& struck);

}  // namespace bsim
