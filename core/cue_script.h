#pragma once
// The scripted cue stick: approach, two practice strokes, the strike, retraction (the seed's four phases).
#include <vector>

#include "camera_script.h"
#include "scene.h"
#include "timeline.h"

namespace bsim {

enum class CuePhase { approach, preflight, impact, retraction };

struct CuePhaseSpan {
  CuePhase phase = CuePhase::approach;
  double begin = 0;  ///< s
  double end = 0;    ///< s
};

struct CuePose {
  Vec3 tip{0, 0, 0};   ///< m, centre of the tip's face
  Vec3 axis{-1, 0, 0}; ///< unit vector from the tip toward the butt
  bool visible = false;
};

class CueScript {
 public:
  /// `scene`, `timeline` and `camera` must outlive the script.
  CueScript(const Scene& scene, const Timeline& timeline, const CameraScript& camera);

  CuePose pose(double t) const;
  const std::vector<CuePhaseSpan>& phases() const { return phases_; }

 private:
  const Scene* scene_ = nullptr;
  const Timeline* timeline_ = nullptr;
  const CameraScript* camera_ = nullptr;
  std::vector<CuePhaseSpan> phases_;
};

}  // namespace bsim
