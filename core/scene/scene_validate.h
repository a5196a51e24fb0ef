#pragma once
// Whole-scene checks that need every line read first (params apply wherever they appear): ball
// references in range, balls on the bed, apart and inside the cushions, rails clockwise, and the
// cue's heading against its ball's velocity.
#include <vector>

#include "diagnostics.h"
#include "scene.h"

namespace bsim {

/// Token locations the Scene itself does not keep, for errors that point inside a line.
struct SceneSourceMap {
  struct BallTokens {
    SourceLoc number, position_x, position_z;
    bool short_form = false;  ///< written `ball N X Y` (at rest on the bed)
  };
  struct RailTokens {
    SourceLoc a_z, b_z;
  };
  struct SpinLine {
    int ball = 0;
    SourceLoc loc, ball_loc;  ///< the `spin` keyword and the ball index
  };
  std::vector<BallTokens> balls;  ///< parallel to Scene::balls
  std::vector<RailTokens> rails;  ///< parallel to the scene's own rails (empty for the standard ones)
  std::vector<SpinLine> spins;
  bool has_cue = false;
  SourceLoc end;  ///< just past the last token
};

/// Appends errors and warnings for `scene`. Scene::rails and pockets already hold the defaults.
void validate_scene(const Scene& scene, const SceneSourceMap& map, std::vector<Diagnostic>& diagnostics);

/// Distances below which two things count as touching, m: far below anything a person types.
inline constexpr double kPlacementTolerance = 1e-6;
/// A cue heading this far from its ball's velocity direction is worth a warning, degrees.
inline constexpr double kHeadingToleranceDeg = 1.0;

}  // namespace bsim
