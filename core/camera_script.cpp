// PLACEHOLDER until the camera script lands.
#include "camera_script.h"
namespace bsim {
std::optional<CameraScript> CameraScript::build(const Scene& scene, const Timeline& timeline, std::vector<Diagnostic>&) {
  CameraScript s;
  s.scene_ = &scene;
  s.timeline_ = &timeline;
  return s;
}
CameraPose CameraScript::pose(double) const { return {}; }
}  // namespace bsim
