#pragma once
// Several shots (`cue` lines) played in file order into one timeline. Each shot is simulated on its own
// (simulate.h) from where the shot before left the balls: a pocketed ball stays down, the `place`
// lines of the shot put balls back on the bed, and a struck ball that went down comes back on the head
// spot. A shot that aims (`cue I pot B P`) is aimed there, from those positions (aim.h). The pieces are
// then laid end to end: a later shot's stick comes in as soon as every ball of the shot before rests,
// events are numbered over the scene with one start and one end, and each shot's span is kept.
#include <optional>
#include <string>

#include "scene.h"
#include "timeline.h"

namespace bsim {

/// The head spot, where a struck ball that went down is put back for a later shot (spec.md), m.
inline constexpr double kHeadSpotX = -0.635;
inline constexpr double kHeadSpotY = 0.0;

/// Why a shot could not be played: a `pot` with no heading from where the balls stopped, a `place`
/// that puts a ball onto another, a ball that left the table (table_escape.h; the shot is then in the
/// timeline).
struct PlayFailure {
  int shot = 0;   ///< from 0
  SourceLoc loc;  ///< the line to blame: the shot's `cue` line, or a `place` line
  std::string message;
};

struct PlayResult {
  Timeline timeline;  ///< every shot played (those before a failure)
  std::optional<PlayFailure> failure;
};

/// Plays every shot of `scene`. Each cue that aims is aimed from where the balls stood before it and
/// the heading found is written to its Cue; the first shot's struck ball takes the velocity and spin of
/// its strike (strike.h). Deterministic: the same scene gives the same bytes.
PlayResult play(Scene& scene);

/// Where a later shot's struck ball is put back after it went down: on the head spot, or the nearest
/// place behind it on the long axis (y = 0, toward the head cushion) where it touches no ball; in front
/// of the spot when nothing behind is free. `balls` as they stand, `ball` the one to put back.
Vec3 respot_place(const Scene& scene, const std::vector<Ball>& balls, int ball);

}  // namespace bsim
