#pragma once
// --write-scene FILE: the scene as written, with a `cue I pot B P` resolved to the numbers the shot was
// played with, for a reader who wants the seed's form.
#include <string>
#include <string_view>

namespace bsim {

struct Scene;
struct Shot;

/// `text` (the scene as written) with each `cue I pot B P` replaced by `cue I HEADING`, the heading `played`
/// struck that shot at (with several shots, each aimed from where the shot before left the balls), and
/// for a first shot without a stroke the struck ball's `ball`-line velocity and `spin`-line spin replaced by the ones
/// that heading gave it (aim.h: strike_heading), every number in its shortest exact form: the text written plays the
/// same shot to the bit. Everything else (comments, spacing, order) is kept. A scene without `pot` comes back
/// unchanged.
std::string scene_text_resolved(std::string_view text, const Scene& played);

/// A game (`game` line) as an explicit scene: the scene's own table lines (`param`, `rail`, `pocket`) and
/// camera description kept as written, then its `game` and `player` lines, every ball where the game
/// started it (the cue ball where it broke from), and each shot played as a `cue` line with its
/// heading and call, its `stroke` and its `place` lines. It replays to the same events: the way to take
/// a played game and edit one shot.
std::string game_scene_text(std::string_view text, const Shot& shot);

/// Writes scene_text_resolved (game_scene_text for a game) into `path` ("-": standard output), in place atomically.
/// Returns the exit status; reports on stderr.
int run_write_scene(const std::string& path, std::string_view text, const Shot& shot, bool quiet = false);

}  // namespace bsim
