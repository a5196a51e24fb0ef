#pragma once
// One POV-Ray file per frame: the camera, every ball on the table or dropping into a pocket (its
// orientation as a matrix), and the cue stick while it is in the scene. The models live in the
// shared include (pov_table.h).
//
// Motion blur: a ball or the stick that moves more than kBlurPixels across
// the picture while the shutter is open (half the frame's time, a film camera's 180-degree shutter)
// is drawn blurred; everything else is drawn once. A ball is drawn as its streak: the solid its
// sphere sweeps while the shutter is open (a capsule, or a few for a path that bends), seen from
// its front only, letting through at each point the share of the shutter's time the ball does not
// cover it. That is the time average of the ball's picture over the shutter, a box filter in time,
// as distributed ray tracing takes it with many samples (Cook, Porter & Carpenter 1984,
// "Distributed ray tracing", SIGGRAPH; Potmesil & Chakravarty 1983, "Modeling motion blur in
// computer-generated images"), here in closed form for one ray a pixel, so the streak is smooth
// and costs one object. The stick, moving along its own axis in a stroke, is drawn the same way: one
// stick stretched over the way its tip goes while the shutter is open, letting through at each point
// the share of the shutter's time the stick does not cover it (solid where it is all the time, its
// two ends fading over their travel, a tip that stops or turns back within the shutter left where it
// rested as long); its colours are averaged over the shutter's instants. Only a stick that also
// moves sideways (swung up or down) by more than kStickSidePixels is drawn as sub-frame copies that
// each let some of the background through. The decision is the frame's own, from the timeline and
// the camera, so a frame with nothing fast in it is exactly the plain frame.
#include <ostream>
#include <string>
#include <vector>

#include "camera_view.h"
#include "pov_table.h"

namespace bsim {

struct Shot;

/// "frame_00012": the frame's file name without extension.
std::string frame_name(int frame);

/// Pixels, on a 1280-pixel-wide picture, that something must move while the shutter is open before
/// it is drawn blurred.
inline constexpr double kBlurPixels = 4.0;
/// The share of a frame's time the shutter is open.
inline constexpr double kShutter = 0.5;

/// The least length (m) a streak's piece is taken to have, so a ball at rest for part of the shutter
/// still has its share of it.
inline constexpr double kStreakLeast = 1e-4;

/// Pixels the stick may move across its own axis while the shutter is open and still be drawn swept
/// along it; beyond that it is drawn as copies.
inline constexpr double kStickSidePixels = 1.0;

/// A piece of the stick's way along its own axis while the shutter is open: its tip goes from `from`
/// to `to` (m along the axis from the tip at the frame's instant, + towards the butt) at an even
/// speed during `share` of the shutter's time.
struct StickTravel {
  double from = 0, to = 0, share = 1;
};

/// The stick's way as pieces, from its tip's places `along` (m, as in StickTravel) at evenly spaced
/// instants across the open shutter: one piece between each two, and consecutive pieces of the same
/// speed (within 3 %) joined into one.
std::vector<StickTravel> stick_travel(const std::vector<double>& along);

/// m, added to every bound's radius: the files' numbers are rounded to a micrometre, and the models'
/// parts reach a hair past their nominal ends (the stick's tip 0.5 mm behind its face).
inline constexpr double kBoundSlack = 0.002;

/// A sphere (m) in a bound: a convex set holds what it bounds when it holds every sphere of the bound.
struct BoundSphere {
  Vec3 centre{0, 0, 0};
  double radius = 0;
};

/// Two spheres whose convex hull (a capsule, one sphere when they are the same) holds a piece of a
/// bound.
struct BoundCapsule {
  BoundSphere a, b;
};

/// One thing a frame draws, a ball or the stick: its lines in the frame's file (empty when it is not
/// drawn) and capsules whose union holds all that is seen of it (`seen`: each piece of a ball's
/// streak, the stick or each of its copies) and all that casts its shadow (`casts`); `mirrors` when
/// its surface reflects what is round it (a ball's clear coat).
struct FramePart {
  std::string text;
  std::vector<BoundCapsule> seen, casts;
  bool mirrors = false;
};

/// What a frame's file holds: its first lines (the frame's number and time, the include), the camera
/// and its pose (as POV-Ray gets it), then every ball in the timeline's order and last the stick.
struct FrameContent {
  std::string header;
  std::string camera;
  CameraPose camera_pose;
  std::vector<FramePart> parts;
};

/// Movie frame `frame` of the shot (Shot::movie: for a plain shot t = frame / fps; a replay's frame
/// shows its time from the replay's camera): what write_pov_frame writes, with bounds.
FrameContent frame_content(const Shot& shot, int frame, int fps);

/// How many frames' contents frame_content has computed in this process: the exporter computes
/// each frame's once (movie_export.h), whatever it then writes, keys and plans from it.
long frame_contents_computed();

/// The frame's file: its header, the camera, then its parts in a light group of their own.
std::string pov_frame_text(const FrameContent& content);

/// Writes movie frame `frame` of the shot (pov_frame_text of its frame_content). Pocketed balls lie
/// in their pockets.
void write_pov_frame(const Shot& shot, int frame, int fps, std::ostream& out);

}  // namespace bsim
