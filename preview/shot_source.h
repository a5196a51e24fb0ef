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
};

SceneSource scene_source(const std::optional<std::string>& path, bool strict);

struct LoadedShot {
  std::unique_ptr<Shot> shot;  ///< null on any error
  /// The simulated shot without camera or cue when only its camera script failed (see ShotResult).
  std::unique_ptr<Shot> unscripted;
  std::vector<Diagnostic> diagnostics;
  std::string read_error;  ///< set when the file cannot be read
  /// Every problem as the lines a user sees: "PATH:LINE:COL: error: ...".
  std::vector<std::string> messages;
};

/// Reads and loads the scene. Never exits.
LoadedShot load_source(const SceneSource& source);

}  // namespace bsim
