#pragma once
// The command line of billiards-preview (see README and --help).
#include <optional>
#include <string>
#include <vector>

#include "command_line.h"

namespace bsim {

/// What the user asked to see: a time in seconds, the instant of event N or shot K's strike.
struct TimeSpec {
  double seconds = 0;
  int event = -1;  ///< >= 0 when given as `event:N`
  int shot = 0;    ///< >= 1 when given as `shot:K` (counted from 1, as in `shot K` camera keys)
};

/// How a time names its picture when -o is a directory or a pattern: the seconds to three decimals
/// ("2.500"), "event_N" or "shot_K".
std::string time_label(const TimeSpec& at);

struct PreviewOverlays {
  bool paths = false;   ///< every ball's path
  bool events = false;  ///< event markers
  bool camera = false;  ///< the camera's own path seen from above
  bool table = false;   ///< the rails', pockets' and balls' numbers
  bool aim = false;     ///< for a `cue I pot B P` shot: the ghost ball, the aim line, the ball's path to the pocket
  /// Whether any overlay is asked for (a picture with none skips the 2D pass).
  bool any() const { return paths || events || camera || table || aim; }
};

/// fps, width, height, size_given and strict are the options both programs share (SharedOptions).
struct PreviewOptions : SharedOptions {
  std::optional<std::string> scene_path;   ///< none: the built-in break
  std::optional<std::string> output;       ///< -o FILE.png, DIR/ or a pattern with %t (for --at)
  std::vector<TimeSpec> at;                ///< each --at SECONDS | event:N | shot:K, in command-line order
  std::vector<std::string> pictures;       ///< set by the parser: the file each --at writes, in the same order
  std::optional<std::string> picture_dir;  ///< set by the parser when -o names a directory (made if missing)
  bool timeline = false;                   ///< --timeline
  std::optional<std::string> movie;        ///< --movie FILE.mp4 (the animatic)
  PreviewOverlays overlays;
  double quit_after = 0;                    ///< s; > 0 closes the interactive window by itself (smoke tests)
  std::optional<std::string> screenshot;    ///< interactive: write the last frame here on quit
  std::optional<std::string> write_camera;  ///< --write-camera FILE: the director's script as text ("-": stdout)
  std::optional<std::string> write_scene;   ///< --write-scene FILE: the scene with `pot` resolved ("-": stdout)
  bool replay = true;  ///< --replay off: a game's movie without its winning shot again (window, animatic, timeline)
};

/// The program's option table (command_line.h): every option in --help's order, with what it does
/// to `options`; it drives the dispatch, the usage and the "did you mean" suggestions.
OptionTable preview_option_table(PreviewOptions& options);

enum class PreviewCommandLineOutcome { run, exit_success, exit_usage };

/// Parses argv[1..]. exit_success: print `message` on stdout (help, version);
/// exit_usage: `message` is the one-line reason for stderr (exit 2).
PreviewCommandLineOutcome parse_preview_options(const std::vector<std::string>& args, PreviewOptions& options,
                                                std::string& message);

}  // namespace bsim
