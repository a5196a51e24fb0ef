#pragma once
// Simultaneous contact of several balls: a compliant contact model for a group of touching (or nearly
// touching) balls, resolved together, after which the exact event loop takes the separated balls back.
//
// Why: resolving the contacts of touching balls one pair at a time turns a row of them into a Newton's
// cradle whose answer depends on the order of resolution. With touching targets the striker rebounds
// and the energy spreads; only with separated targets is the outcome a series of two-ball collisions
// (Donahue, Hrenya, Zelinskaya & Nakagawa, "Newton's cradle undone", Phys. Fluids 20, 2008). So a
// group is integrated as one system:
//
//  - normal force: Hertz (1882), F = k_hertz * delta^1.5 for an overlap delta of two equal spheres,
//    k = (4/3) E* sqrt(R*), E* = E / (2 (1 - nu^2)), R* = R / 2 (phenolic resin, E = 5.84 GPa,
//    nu = 0.34: 5.26e8 N/m^1.5 for 57.15 mm balls);
//  - dissipation: Hunt & Crossley (1975), F = k delta^1.5 (1 + alpha delta'), with the damping of
//    Flores, Machado, Silva & Martins (2011), alpha = 8 (1 - e) / (5 e v0), v0 the contact's approach
//    speed, so that an isolated pair leaves with restitution e_ball. A contact that starts from rest
//    (balls already touching) has no approach speed of its own: v0 is the largest closing speed the
//    contact has reached so far, which for an isolated pair is its approach speed.
//  - friction between the balls: the capped Coulomb impulse of the pairwise model (resolve.h: throw
//    and spin transfer), applied once the normal phase is over, to each pair in a fixed order, with the
//    normal impulse that pair accumulated.
//
// The geometry is frozen during the contact (each pair's normal is its line of centres at the start;
// the balls move by well under a millimetre during the 0.2-0.5 ms phase), and the cloth's friction is
// ignored for that time (it changes a ball's speed by mu_slide g * 0.3 ms, about 0.6 mm/s). The phase
// is thus an impulse map, as for an isolated pair: the velocities change at the event's instant and
// the positions stay where they are, so everything else stays event-exact.
//
// Integration: velocity Verlet over the group only, in a fixed order, with a fixed step of
// kGroupStepsPerContact steps per Hertz contact time at the group's largest relative speed, so the
// same input always gives the same bytes. Forces act in equal and opposite pairs (momentum is exact);
// the few parts in a million of energy the integration may create are taken off again (energy is never
// gained), and the phase ends only when no two balls overlap and no nearby pair is still closing.
#include <vector>

#include "ball_state.h"
#include "hertz.h"
#include "physics_params.h"

namespace bsim {

/// A group's gap threshold is kGroupGapRatio times the Hertz compression delta_max at the contact's
/// closing speed: a neighbour that close is reached while the first contact is still near its
/// deepest, so the contacts act together and the order of pairwise resolution would pick a winner
/// (a Newton's cradle). At 8 m/s delta_max is 0.7 mm, so the threshold is 70 micrometres: a tight rack
/// (touching but for a few micrometres) is one group; a rack with gaps of 0.1 mm or more keeps its
/// individual contacts. Past 1.47 delta_max (the distance the struck ball of an isolated Hertz contact
/// travels before the contact ends) the contacts no longer overlap in time and the pairwise result is
/// exactly the compliant one; in between it is an approximation (README, "What is not modelled").
inline constexpr double kGroupGapRatio = 0.1;
/// Integration steps per Hertz contact time at the group's largest relative speed.
inline constexpr double kGroupStepsPerContact = 100;
/// Safety net: a group phase longer than this many contact times stops (what is left goes back to the
/// event loop as ordinary contacts).
inline constexpr double kGroupMaxContactTimes = 60;

/// m, surface gap below which a neighbour joins a contact closing at `speed`: kGroupGapRatio * delta_max.
double group_gap(double speed, const PhysicsParams& params);

/// One contact inside a group: balls (indices into the group's list, a < b), when it began (s after the
/// group's instant) and the largest closing speed it reached (m/s).
struct GroupContact {
  int a = 0, b = 0;
  double time = 0;
  double speed = 0;
};

struct GroupResult {
  std::vector<BallState> after;        ///< same order as the input; untouched balls exactly as they were
  std::vector<bool> touched;           ///< whether each ball took part in a contact
  std::vector<GroupContact> contacts;  ///< in the order they began
  long steps = 0;                      ///< integration steps (for the bench and the tests)
  double duration = 0;                 ///< s, length of the compliant phase
};

/// Resolves a group of balls on the bed at one instant. `balls` must not overlap (touching is fine).
/// `steps_per_contact` is kGroupStepsPerContact except in tests of the step's convergence.
GroupResult resolve_group(const std::vector<BallState>& balls, const PhysicsParams& params,
                          double steps_per_contact = kGroupStepsPerContact);

}  // namespace bsim
