#pragma once
// Everything downstream of one scene text, built together so the pieces' references stay valid:
// scene -> timeline -> camera script -> cue script. Both front ends start here.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "camera_script.h"
#include "cue_script.h"
#include "diagnostics.h"
#include "director.h"
#include "frames.h"
#include "game.h"
#include "scene.h"
#include "scene_parse.h"
#include "timeline.h"

namespace bsim {

/// The scripts point into the scene and timeline beside them, so a Shot stays where it was built:
/// it can be neither copied nor moved (hold it by the unique_ptr load_shot returns). A shot whose
/// camera script does not fit it (an event number the shot lacks, say) has neither script: the scene
/// and timeline alone, so a picture of the shot's events can show the user why.
struct Shot {
  Shot() = default;
  Shot(const Shot&) = delete;
  Shot& operator=(const Shot&) = delete;
  Shot(Shot&&) = delete;
  Shot& operator=(Shot&&) = delete;

  Scene scene;
  Timeline timeline;
  std::optional<CameraScript> camera;  ///< none when the camera script does not fit the shot
  std::optional<CueScript> cue;        ///< set with `camera`
  /// The automatic director's script (its text, comments and lines of action too) when it films the
  /// shot (CameraChoice::automatic); its shots are then scene.camera.
  std::optional<DirectedCamera> directed;
  /// A scene with a `game` line: the rules' record of the game played (`scene` is then the game as an
  /// explicit scene, one `cue` per shot).
  std::optional<GameRecord> game;
  /// The movie's frames (frames.h): the simulation as it plays; for a game with a winner (unless the
  /// replay is off), its broadcast_edit() when the director films it, then the winning shot again at
  /// half speed filmed by `replay_camera`.
  MovieTimeline movie;
  /// The replay's camera, the director's second camera (replay_camera.h): set when `movie` has a replay.
  std::optional<CameraScript> replay_camera;
  std::string replay_what;  ///< the replay's camera in words ("a camera low behind the top-right corner (pocket 2)")

  /// The camera that films `frame`: the replay's on a replay frame, else the shot's script.
  const CameraScript& camera_at(const MovieFrame& frame) const {
    return frame.replay && replay_camera ? *replay_camera : *camera;
  }
};

struct ShotResult {
  std::unique_ptr<Shot> shot;           ///< null when the scene does not parse; without scripts when they do not fit
  std::vector<Diagnostic> diagnostics;  ///< parse and post-simulation errors and warnings
  /// The shot ready to film (scripted), else null.
  const Shot* scripted() const { return shot && shot->camera ? shot.get() : nullptr; }
};

/// Whose camera script a shot is filmed with: the scene's own (`--camera scene`, the default) or the
/// automatic director's, written from the simulated shot in place of the scene's (`--camera auto`).
enum class CameraChoice { scene, automatic };

/// What the rules tell the director of a game (`scene` its explicit scene): it opens on the table, and
/// a safety's or a foul's point (when no ball was made) is the cue ball's path: where it hides, what it
/// met first, where it stopped.
FilmingNotes game_filming_notes(const Scene& scene, const GameRecord& record);

/// A game's movie cut as a broadcast cuts it (frames.h): each shot from its start until it has
/// settled (Timeline::settled) and been held on a moment, then the next shot's start; the stretches
/// where the balls only spin in place are cut out. The last shot is held longer (its winner's call).
MovieTimeline broadcast_edit(const Timeline& timeline);

/// Whether a game with a winner is followed by its winning shot again, slowed (`--replay on|off`).
enum class ReplayChoice { on, off };

/// Parses, simulates and scripts a scene. Never exits; user errors come back as diagnostics. With
/// CameraChoice::automatic the scene's camera script is replaced by direct_camera()'s (its own is
/// parsed but never checked against the shot). The movie (Shot::movie) has the replay unless
/// ReplayChoice::off.
ShotResult load_shot(std::string_view text, std::string_view name, const ParseOptions& options = {},
                     CameraChoice camera = CameraChoice::scene, ReplayChoice replay = ReplayChoice::on);

}  // namespace bsim
