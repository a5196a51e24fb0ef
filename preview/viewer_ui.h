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

/// px a window manager may add around the window (frame, title bar), left out of the work area.
inline constexpr int kDecorationsWidth = 16, kDecorationsHeight = 48;

struct PictureSize {
  int width = 0, height = 0;  ///< px
};

/// The picture size of a window opened without --size: 1280x720, or smaller at 16:9 so that the
/// window (the picture, the controls below it and the decorations) fits a screen's work area of
/// `area_width` x `area_height` (never below 320x180). Without a work area (0 x 0): 768x432, a window of
/// 768x672 that fits a 1366x768 screen with its task bar.
PictureSize default_window_picture(int area_width, int area_height);

/// Where the 3D picture goes in the window (window units, origin top-left).
struct ViewRect {
  float x = 0, y = 0, width = 0, height = 0;
};

/// The area above the controls, letterboxed to the movie's aspect so the framing is the movie's.
ViewRect view_rect(float window_width, float window_height, int picture_width, int picture_height);

/// Overlays over the picture (and, with the free camera, the scripted camera as a frustum).
void draw_view_overlays(const ViewerState& state, const ViewCamera& camera, const ViewRect& view, const UiFonts& fonts);

/// A scene with a game: the game panel at the window's top right (the rules, the players with the one
/// at the table marked, ball in hand, the plan and the rules' call of the turn at time t, the balls
/// left as discs, the winner). Nothing without a game. Call between ImGui's NewFrame and Render.
void draw_game_panel(const Shot& shot, double t, const UiFonts& fonts, float window_width);

/// Every panel; changes the state when the user clicks.
void draw_controls(ViewerState& state, const UiFonts& fonts, float window_width, float window_height);

}  // namespace bsim
