#pragma once
// One POV-Ray file per frame: the camera, every ball on the table or dropping into a pocket (its
// orientation as a matrix), and the cue stick while it is in the scene. The models live in the
// shared include (pov_table.h).
//
// Motion blur (the photographic look): a ball or the stick that moves more than kBlurPixels across
// the picture while the shutter is open (half the frame's time, a film camera's 180-degree shutter)
// is drawn as sub-frame copies that each let some of the background through, so together they read
// as a streak; everything else is drawn once. The decision is the frame's own, from the timeline and
// the camera, so a frame with nothing fast in it is exactly the plain frame.
#include <ostream>
#include <string>

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

/// Writes frame `frame` of the shot, which shows t = frame / fps. The classic look draws no blur and
/// leaves pocketed balls out; the photographic one shows them lying in their pockets.
void write_pov_frame(const Shot& shot, int frame, int fps, std::ostream& out, Look look = Look::photo);

/// How many sub-frame copies frame `frame` draws of its fastest object: 1 when nothing in it moves
/// more than kBlurPixels while the shutter is open (the frame is rendered once, as it is).
int blur_samples(const Shot& shot, int frame, int fps);

}  // namespace bsim
