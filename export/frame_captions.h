#pragma once
// Each frame's caption, written into the frames folder beside the .pov frames (frames/captions.txt)
// and read by the develop stage wherever the frame is developed: here, or on a render farm's node, so
// a frame is the same picture either way. A frame's caption line is part of its key in the frame
// store, so a captioned picture is never served for a frame with another caption; a frame whose
// caption changed and whose .pov did not is developed again from the traced picture of the same .pov
// (a partial frame with nothing to trace, changed_region.h).
//
// captions.txt: `#` comment lines, then one line per captioned frame, its fields separated by tabs:
//   FRAME  left|right  8ball|9ball|10ball  AT_TABLE  SHOT  PLAYER1  PLAYER2  RACK  ON_TABLE  replay|-
//   then KIND TITLE TEXT for each call (KIND foul, push-out, winner or stopped)
// RACK and ON_TABLE are painted numbers separated by commas, `-` for none. A frame with no line has
// no caption.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "camera_view.h"
#include "lower_third.h"

namespace bsim {

struct Shot;

/// The file in the frames folder.
inline constexpr const char* kCaptionsName = "captions.txt";

/// A moment of the movie a frame shows: the simulation time, whether it is the replay's, and the
/// camera it is filmed with.
struct FrameMoment {
  double time = 0;
  bool replay = false;
  CameraPose pose;
};

/// Each movie frame's moment (Shot::movie: the simulation, then a game's replay, from its own camera).
std::vector<FrameMoment> movie_frame_moments(const Shot& shot, int fps);

/// The caption of each frame: none (empty) unless the shot is a game. Each shot's caption sits in one
/// lower corner, the left unless the shot's cue ball or the ball it is played at is seen under the
/// caption there more often than in the right.
std::vector<FrameCaption> frame_captions(const Shot& shot, const std::vector<FrameMoment>& moments, int width,
                                         int height);

/// captions.txt's text for `captions` (frame k is captions[k]).
std::string captions_text(const std::vector<FrameCaption>& captions);

/// The caption line of each frame in `frames_dir`'s captions.txt (without its frame number); none when
/// the file is missing.
std::map<int, std::string> read_caption_lines(const std::string& frames_dir);
/// The same from captions.txt's text.
std::map<int, std::string> caption_lines(const std::string& text);

/// A caption line (without its frame number) read back; false when it is not one.
bool parse_caption(const std::string& line, FrameCaption& caption);

/// Folds each captioned frame's caption line and the drawing's signature into its frame store key.
void add_caption_keys(const std::string& frames_dir, std::vector<std::uint64_t>& keys);
/// The same from the caption lines (caption_lines of the text written).
void add_caption_keys(const std::map<int, std::string>& lines, std::vector<std::uint64_t>& keys);

}  // namespace bsim
