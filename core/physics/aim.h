#pragma once
// Aim by intent (`cue I pot B P`): the stick's heading that drops ball B into pocket P, found by playing
// the shot itself. The ghost-ball heading (the struck ball's centre sent to where it touches B with the
// line of centres through the pocket's best entry point) is the first guess; a secant search on the
// heading then sends B off along that line as the real physics plays it, so that throw, the struck
// ball's curve and whatever the strike adds are allowed for; last, the headings either side that still
// pot are bracketed and the middle of that interval is taken: the ball drops with room on both sides.
//
// Ghost-ball aiming and the potting point follow pooltool's aim and pot helpers (Kiefl, pooltool
// `ai/aim/core.py`, `ai/pot/core.py`), which ignore throw; correcting by simulation is this program's.
#include <optional>
#include <string>
#include <vector>

#include "scene.h"
#include "strike.h"  // strike_heading: every heading the solver tries is struck there

namespace bsim {

/// "ball index 3 (the 7)": how a person finds a ball in the file and on the table (messages).
std::string ball_name(const Scene& scene, int i);

/// What the solver found, or why nothing pots.
struct AimResult {
  std::optional<double> heading_deg;  ///< degrees in [0, 360), counter-clockwise from +x
  std::string failure;                ///< when no heading pots: why, in a person's words
  Vec3 ghost{0, 0, 0};                ///< m, the ghost ball of the first guess (struck ball touching the target)
  Vec3 entry{0, 0, 0};                ///< m, the pocket's best entry point seen from the target ball
  int simulations = 0;                ///< shots played to find it (for the bench)
};

/// Cut angles beyond this many degrees are not tried: the struck ball would only graze the target.
inline constexpr double kMaxCutDeg = 89.0;

/// The heading for `scene.cue` (which must aim: Cue::aims()), from `scene` as parsed (validated: its
/// ball and pocket exist). Deterministic: the same scene gives the same heading to the last bit. When
/// nothing pots, `failure` is the reason and, on a line of its own, the other pockets the same stroke
/// does pot the ball in (pockets_that_take), in words.
AimResult aim_cue(const Scene& scene);

/// The pockets other than the one `scene.cue` names that the solver finds a heading for: the ball to pot
/// drops into each with the cue's own stroke. In the pockets' order.
std::vector<int> pockets_that_take(const Scene& scene);

/// For a scene whose cue aims: finds the heading (aim_cue) and strikes `scene` with it (strike_heading),
/// so that simulate(scene) plays the aimed shot. Returns the failure (empty when it pots, and for a
/// scene with a numeric heading, which is left as it is).
std::string apply_aim(Scene& scene);

}  // namespace bsim
