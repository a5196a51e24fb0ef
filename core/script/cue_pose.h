#pragma once
// The cue stick's pose and its dimensions: what the stick script produces and every reader of the
// stick (its clearance, the preview's mesh, the POV-Ray model) draws.
#include "vec.h"

namespace bsim {

/// Cue stick dimensions, m.
inline constexpr double kCueLength = 1.47;
inline constexpr double kCueTipRadius = 0.0065;
inline constexpr double kCueButtRadius = 0.0145;

struct CuePose {
  Vec3 tip{0, 0, 0};    ///< m, centre of the tip's face
  Vec3 axis{-1, 0, 0};  ///< unit vector from the tip toward the butt
  bool visible = false;
};

}  // namespace bsim
