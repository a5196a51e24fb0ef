#pragma once
// Whether the scripted camera stays in the open: not inside the table, a ball, the lamp or the
// floor. Warnings only (the movie is still made), one per span of time and kind, at the `event`
// keyword of the description in charge of the camera then.
#include <vector>

#include "camera_script.h"
#include "diagnostics.h"
#include "scene.h"
#include "timeline.h"

namespace bsim {

/// m a camera keeps from a ball's surface: room for its lens (so from the centre, ball radius + this).
inline constexpr double kCameraBallClearance = 0.12;
/// frames per second at which the camera is sampled (plus every event and blend boundary); spans of
/// trouble less than one such frame apart count as one.
inline constexpr int kClearanceFps = 30;

/// Samples the camera over the whole shot and appends one warning per span in which it is
/// - inside the table: below the wood's top while over the table's outline (wooden rail included),
/// - below the floor anywhere else,
/// - closer than ball radius + kCameraBallClearance to a ball's centre (a ball on the table),
/// - inside the lamp's shade over the table.
void check_camera_clearance(const Scene& scene, const Timeline& timeline, const CameraScript& camera,
                            std::vector<Diagnostic>& diagnostics);

}  // namespace bsim
