#pragma once
// A player: chooses each shot of a game as a good amateur-to-professional player would, by trying
// strokes in the physics itself. The shape follows the Computational Pool Olympiad's winners
// (Smith, "PickPocket: A computer billiards shark", Artificial Intelligence 171 (2007); Archibald,
// Altman & Shoham, "Analysis of a winning computational billiards player" (CueCard), IJCAI 2009):
//  - candidate pots: each legal (ball, pocket) whose lines are open, aimed by the `pot` solver (aim.h),
//    with a handful of strokes (speeds, follow or draw, english) each;
//  - each candidate scored by the chance that it goes in under the player's own noise (a few noisy
//    simulations) and by how good the next shot is from where the cue ball stops (position play);
//  - a safety when no pot is worth taking: strokes that hit a legal ball and leave the opponent
//    nothing to pot;
//  - with ball in hand, places behind each candidate's ghost ball; the break from the kitchen, hard.
// Deterministic: the same table, rules, skill and seed give the same plan to the bit.
#include <cstdint>
#include <optional>
#include <string>

#include "rack.h"
#include "rules.h"
#include "scene.h"

namespace bsim {

/// One player of a game.
struct PlayerSkill {
  std::string name;
  double noise = 1;  ///< times the Olympiad's standard deviations (kNoise*)
  /// The second ply: each finalist stroke's leaves searched for the next shot itself. Off, a leave is
  /// judged by its geometry alone (for measuring what the look-ahead is worth).
  bool look_ahead = true;
};

/// The Computational Pool Olympiad's standard deviations at noise 1 (FastFiz `GaussianNoise`).
inline constexpr double kNoiseHeadingDeg = 0.125;
inline constexpr double kNoiseElevationDeg = 0.1;
inline constexpr double kNoiseOffsetM = 0.0005;  ///< each tip offset, m (side and height)
inline constexpr double kNoiseSpeed = 0.075;     ///< the tip's speed, m/s

/// A shot the player means to play.
struct PlannedShot {
  double heading_deg = 0;     ///< the stick's heading
  Stroke stroke;              ///< speed, side, height, elevation (no source locations)
  std::optional<Vec3> place;  ///< ball in hand: where the cue ball is put first (z = ball radius)
  ShotCall call;              ///< the ball and pocket meant, or a safety or a push-out
  double chance = 0;          ///< the planned pot's estimated chance under the player's noise (0 for a safety)
  int simulations = 0;        ///< shots simulated to choose it
};

/// The next shot for `table` (balls at rest where they stand; a ball down has Ball::pocket >= 0; its
/// cues are ignored) under `rules`, by a player of `skill`; `seed` feeds the player's own noisy trials.
PlannedShot plan_shot(const Scene& table, const ShotRules& rules, const PlayerSkill& skill, std::uint64_t seed);

/// After the opponent's push-out: whether the player takes the table (true) or hands it back.
bool take_push_out(const Scene& table, const ShotRules& rules, const PlayerSkill& skill, std::uint64_t seed);

/// The stroke and heading as the player's arm delivers them: each of heading, elevation, side and
/// height offsets and speed moved by a Gaussian error of `noise` times the Olympiad's deviation, drawn
/// from `random` (Marsaglia's polar method over splitmix64). The speed stays within (0, Stroke::kMaxSpeed],
/// the offsets within the miscue limit, the elevation within [0, 89] degrees.
void apply_noise(double noise, double ball_radius, SplitMix64& random, double& heading_deg, Stroke& stroke);

}  // namespace bsim
