#pragma once
// The physics' guard: no ball leaves the bed except by dropping into a pocket. The scene check makes
// sure the cushions close round the bed (cushion_gaps.h); this catches whatever still gets through (a
// ball put back where the table has no bed, a cushion the ball rolls under, a fault of the simulation)
// so that a run fails, naming the ball, instead of filming it off in the room.
#include <optional>
#include <string>

#include "scene.h"
#include "simulate.h"

namespace bsim {

/// m a ball's centre may stray beyond the box the cushions' nose lines span before it counts as gone:
/// no ball on the bed comes near it (its centre stays a reach inside every nose line).
inline constexpr double kEscapeTolerance = 0.001;

struct TableEscape {
  int ball = -1;        ///< file-order index
  double time = 0;      ///< s, in the simulation's own time
  Vec3 where{0, 0, 0};  ///< the centre, just beyond the box
};

/// The first moment a ball on the bed (neither falling nor pocketed) has its centre more than
/// kEscapeTolerance beyond the box the scene's cushions span; none when it never does, or when the
/// scene's cushions span no area (no rails: an unbounded bed).
std::optional<TableEscape> first_escape(const Scene& scene, const SimulationResult& result);

/// "the 3 (ball index 5) left the table at 7.412 s at (1.402, 0.301) ...": `offset` s is added to the
/// escape's time (the shot's start in the whole scene).
std::string escape_message(const Scene& scene, const TableEscape& escape, double offset);

}  // namespace bsim
