#pragma once
// Where the scene comes from (a file or the built-in break, scene_file.h) and turning it into a Shot.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "diagnostics.h"
#include "scene_file.h"
#include "shot.h"

namespace bsim {

/// The scene's origin (scene_file.h: its path, how it is shown, its name) and how to load it.
struct SceneSource : SceneOrigin {
  bool strict = false;
  bool auto_camera = false;  ///< --camera auto: film with the automatic director's script
  bool replay = true;        ///< --replay off: a game's movie without its winning shot again
};

SceneSource scene_source(const std::optional<std::string>& path, bool strict);

struct LoadedShot {
  /// Null when the scene does not load; without camera or cue when only its camera script failed (see Shot).
  std::unique_ptr<Shot> shot;
  std::vector<Diagnostic> diagnostics;
  std::string read_error;  ///< set when the file cannot be read
  std::string text;        ///< the scene as read
  /// Every problem as the lines a user sees: "PATH:LINE:COL: error: ...".
  std::vector<std::string> messages;
  /// The shot ready to film (scripted), else null.
  const Shot* scripted() const { return shot && shot->camera ? shot.get() : nullptr; }
};

/// Reads and loads the scene. Never exits.
LoadedShot load_source(const SceneSource& source);

}  // namespace bsim
