#pragma once
// The window's panels (Dear ImGui): transport buttons and the scrub bar with event ticks and shaded
// interpolation windows, the event list (click to jump), the camera and overlay switches, the key
// help, and the scene's errors with their line and column after a failed reload.
#include "fonts.h"
#include "view.h"
#include "viewer_state.h"

namespace bsim {

/// px of window height below the picture for the controls.
inline constexpr int kControlsHeight = 240;

/// Where the 3D picture goes in the window (window units, origin top-left).
struct ViewRect {
  float x = 0, y = 0, width = 0, height = 0;
};

/// The area above the controls, letterboxed to the movie's aspect so the framing is the movie's.
ViewRect view_rect(float window_width, float window_height, int picture_width, int picture_height);

/// Overlays over the picture (and, with the free camera, the scripted camera as a frustum).
void draw_view_overlays(const ViewerState& state, const ViewCamera& camera, const ViewRect& view, const UiFonts& fonts);

/// Every panel; changes the state when the user clicks.
void draw_controls(ViewerState& state, const UiFonts& fonts, float window_width, float window_height);

}  // namespace bsim
