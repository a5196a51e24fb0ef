#pragma once
// Writing a camera description into a scene's text from the interactive window: the camera asked
// for, its place in the camera block, the ball under the cursor, and replacing the scene file safely
// with a backup for undo. The moment's name and the description's text are the core's
// (script/camera_moment.h), as the director's are. No GL here: all of it is tested directly.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene.h"
#include "timeline.h"
#include "view.h"

namespace bsim {

/// s: a description written within this of an event or pocket drop starts at that moment's key
/// (`hit 0 5`, `drop 3`, ...); further from every one it starts at `at T` (name_moment()). About a
/// quarter of a second: a few frames either side of a contact, where a person pausing "on" it usually is.
inline constexpr double kKeySnap = 0.25;

/// The blend windows (`pre`, `post`) of a description the window writes: the camera glides in over
/// the last 30% of the time since the description before, and arrives at the framing it was given
/// exactly at its moment (no blend after it), so the scripted camera then shows what the free camera showed.
inline constexpr double kWrittenPre = 0.3, kWrittenPost = 0;

/// What the window asks for at a moment.
struct CameraPlacement {
  enum class Kind { hover, ball };
  Kind kind = Kind::hover;
  Vec3 eye{0, 0, 1};      ///< m, the free camera's location
  Vec3 look_at{0, 0, 0};  ///< m, the free camera's look point (hover)
  int ball = -1;          ///< Kind::ball: the ball to look at or follow
};

/// The outcome of placing a camera in a scene's text.
struct CameraEdit {
  std::string text;         ///< the new scene text (empty when there is an error)
  std::string description;  ///< the description as it now reads in the file
  int line = 0;             ///< its line, 1-based
  bool replaced = false;    ///< it took the place of a description starting at the same moment
  std::string error;        ///< why nothing could be written
};

/// Writes a description at time `t` into `text` (the scene file as it is on disk; `shown_path`
/// names it in an error). The text is parsed and simulated afresh to name the moment and order the
/// descriptions, so an edit made in an editor since the last reload is kept.
/// - Kind::hover: a `hover` at the eye, looking at the look point.
/// - Kind::ball: a `look` at the ball from the eye; if a description at this moment already looks at
///   that ball, a `follow` of it (the eye as an offset in the ball's frame), and back to `look`.
/// A description already starting at the same moment is replaced in place, keeping its key as
/// written, its windows and its comment; otherwise the new one goes in the camera block before the
/// first description that starts later (a block is added at the end of a scene without one).
CameraEdit place_camera(std::string_view text, const std::string& shown_path, double t,
                        const CameraPlacement& placement);

/// The ball whose sphere the ray through a point of the picture meets first, if any. `x`, `y` in
/// the picture's pixels (origin top-left), `width` x `height` the picture. Balls dropped out of sight
/// are left out; the spheres are widened a little (1.25 radii) so that a small ball is easy to hit.
std::optional<int> ball_at_pixel(const Timeline& timeline, double t, const ViewCamera& camera, double width,
                                 double height, double x, double y);

/// Where a scene file's backup goes: the file's path with `.bak` added (`shot.scn.bak`).
std::string backup_path(const std::string& path);

/// Replaces the file at `path` with `text` without a moment where it is half written (a temporary
/// file in the same directory, renamed over it), keeping its permissions, after saving `previous`
/// (its content now) to backup_path(path) the same way. A symbolic link is followed: its target is
/// replaced. Returns the error to show, empty on success.
std::string replace_scene_file(const std::string& path, const std::string& previous, const std::string& text);

/// The window's changes to one scene file, for undo.
class SceneEdits {
 public:
  /// Records a change the window has written: the file was `before` and is now `after`.
  void record(std::string before, std::string after);
  bool empty() const { return changes_.empty(); }
  /// Puts back the file as it was before the window's last change to it (the undone version goes
  /// to the backup). Refuses, with the error returned, when the file on disk is no longer what the
  /// window wrote (edited since): nothing is lost, the previous version stays in the backup.
  std::string undo(const std::string& path);

 private:
  struct Change {
    std::string before, after;
  };
  std::vector<Change> changes_;
};

}  // namespace bsim
