#pragma once
// What the interactive window keeps between frames: the loaded shot (and the last problems), the
// time and play state, the camera choice with the free orbit camera, the overlays, and the watch
// on the scene file for hot reload.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "camera_edit.h"
#include "overlays.h"
#include "preview_options.h"
#include "shot_source.h"
#include "timeline_picture.h"
#include "view.h"

namespace bsim {

struct OrbitCamera {
  Vec3 target{0, 0, 0};
  double yaw_deg = -60;   ///< around z, from +x
  double pitch_deg = 40;  ///< above the table plane
  double distance = 4.2;  ///< m

  ViewCamera view() const;
  void orbit(double dx_px, double dy_px);
  void pan(double dx_px, double dy_px, double view_height_px);
  void zoom(double wheel_steps);
};

struct ViewerState {
  SceneSource source;
  std::unique_ptr<Shot> shot;         ///< the last scene that loaded; null until one does
  std::vector<std::string> messages;  ///< errors and warnings of the last load, as printed
  bool load_failed = false;           ///< the last load had errors (the previous shot stays shown)
  int reloads = 0;
  TimelineData timeline;  ///< the scrub bar's contents, for the current shot
  OverlayPaths paths;     ///< the overlays' paths, for the current shot

  double time = 0;      ///< s, the simulation's
  bool replay = false;  ///< the time is shown in the game's replay (Shot::movie), from the replay's camera
  bool playing = false;
  double speed = 1.0;
  int fps = 30;  ///< step size of the frame keys
  bool free_camera = false;
  OrbitCamera orbit;
  PreviewOverlays overlays;
  bool antialias = false;
  SceneEdits edits;    ///< the window's own changes to the scene file, for undo
  std::string notice;  ///< what the last camera placement or undo did, shown under the picture
  bool notice_is_error = false;

  double duration() const;
  /// Shows simulation time t (out of the replay).
  void set_time(double t);
  /// The movie's frame shown: the time, in the replay or not (frames.h).
  MovieFrame shown() const;
  /// s of the movie: the simulation, then a game's replay at half speed.
  double movie_duration() const;
  /// s into the movie where the window is.
  double movie_time() const;
  /// Shows what the movie shows `t` s into it: past the game's end, the replay.
  void set_movie_time(double t);
  /// Steps by frames of the movie (into and through the replay).
  void step_frames(int frames);
  /// Jumps to the next (+1) or previous (-1) event.
  void step_event(int direction);
  /// Jumps to the next (+1) or previous (-1) shot's strike (its cue event), as `--at shot:K` shows it.
  void step_shot(int direction);
  /// The shot in play at the current time, from 0 (Timeline::shot_at); 0 without a shot.
  int shot_in_play() const;
  /// How many shots the scene has (1 without a shot loaded).
  int shot_count() const;
};

/// Loads the source into the state; on errors keeps the previous shot and records the messages.
/// Returns true when a new shot replaced the old one.
bool load_into(ViewerState& state);

/// Writes a camera description at the current time into the scene file (see place_camera), from
/// the free camera, after reading the file afresh from disk; the previous version goes to its
/// backup. Sets the notice. Returns true when the file changed (reload it).
bool write_camera_key(ViewerState& state, const CameraPlacement& placement);

/// Puts back the scene file as it was before the window's last change to it. Sets the notice.
/// Returns true when the file changed (reload it).
bool undo_camera_key(ViewerState& state);

/// Notices when the scene file changes on disk (by time stamp and size).
class FileWatch {
 public:
  explicit FileWatch(std::optional<std::string> path);
  /// True once per change since the last call.
  bool changed();

 private:
  std::optional<std::filesystem::path> path_;
  std::filesystem::file_time_type stamp_{};
  std::uintmax_t size_ = 0;
  bool exists_ = false;
};

}  // namespace bsim
