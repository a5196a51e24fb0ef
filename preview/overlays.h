#pragma once
// Drawn over the 3D picture in 2D: every ball's path, event markers, the camera seen from above,
// a line of text saying where in the shot the picture is, and the scripted camera as a frustum.
#include <string>
#include <vector>

#include <imgui.h>

#include "fonts.h"
#include "preview_options.h"
#include "view.h"

namespace bsim {

struct Shot;

/// Paths sampled once per shot (drawing them every frame from the timeline would cost more than the frame).
struct OverlayPaths {
  struct Point {
    double time;  ///< s
    Vec3 where;
  };
  std::vector<std::vector<Point>> balls;  ///< per ball, on the cloth, until it is pocketed
  std::vector<Point> eyes, targets;       ///< the scripted camera and the point it looks at
};
OverlayPaths overlay_paths(const Shot& shot);

struct OverlayFrame {
  const Shot& shot;
  double time = 0;               ///< s
  ViewCamera camera;             ///< the camera the picture is drawn from
  double width = 0, height = 0;  ///< px, the picture's size
  const UiFonts& fonts;
  double left = 0, top = 0;             ///< px, where the picture sits in the draw list (a window's view)
  const OverlayPaths* paths = nullptr;  ///< the shot's paths; sampled on the spot when null
};

void draw_ball_paths(ImDrawList& list, const OverlayFrame& frame);
void draw_event_markers(ImDrawList& list, const OverlayFrame& frame);
/// The scripted camera's path and view wedge over a top view of the table, in the top-right corner.
void draw_camera_map(ImDrawList& list, const OverlayFrame& frame);
/// A rectangle on the picture, px.
struct OverlayBox {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool overlaps(const OverlayBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

/// "t = 1.500 s · event 3 ball 0 – ball 5 · follow ball 0 · interpolating", wrapped to the picture's
/// width (in the small font below 400 px high), and where it goes: along the bottom, or the top.
struct StatusLine {
  std::string text;
  ImFont* font = nullptr;
  float size = 0, wrap = 0;  ///< px
  ImVec2 at;                 ///< px, the text's top left
  OverlayBox box;            ///< px, its dark band
  bool top = false;
};
StatusLine status_line_layout(const OverlayFrame& frame, bool top);
void draw_status_line(ImDrawList& list, const StatusLine& line);
/// The status line along the bottom.
void draw_status_line(ImDrawList& list, const OverlayFrame& frame);
/// The scripted camera at `time` as a frustum and its path, seen from the frame's (free) camera.
void draw_scripted_frustum(ImDrawList& list, const OverlayFrame& frame, double aspect);

/// The numbers a scene refers to, written on the table: each rail's and pocket's index (as events.json
/// and camera keys give them) and each ball's index in file order.
void draw_table_numbering(ImDrawList& list, const OverlayFrame& frame);

/// For a shot aimed by `cue I pot B P`, until the struck ball first touches the ball to pot: the ghost
/// ball (the struck ball where it touches it, as played), the aim line to it, and the ball's line to the
/// pocket's centre.
void draw_aim(ImDrawList& list, const OverlayFrame& frame);

/// Every overlay the options ask for (and the status line when any but the aim is on).
void draw_overlays(ImDrawList& list, const OverlayFrame& frame, const PreviewOverlays& overlays);

}  // namespace bsim
