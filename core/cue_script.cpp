// PLACEHOLDER until the cue script lands.
#include "cue_script.h"
namespace bsim {
CueScript::CueScript(const Scene& scene, const Timeline& timeline, const CameraScript& camera)
    : scene_(&scene), timeline_(&timeline), camera_(&camera) {}
CuePose CueScript::pose(double) const { return {}; }
}  // namespace bsim
