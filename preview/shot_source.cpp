#include "shot_source.h"

#include <filesystem>

#include "builtin_scene.h"
#include "scene_file.h"

namespace bsim {

SceneSource scene_source(const std::optional<std::string>& path, bool strict) {
  SceneSource source;
  source.strict = strict;
  if (path) {
    source.path = *path;
    source.shown_path = *path;
    source.name = std::filesystem::path(*path).stem().string();
  } else {
    source.shown_path = "<built-in break.scn>";
    source.name = std::string(kBuiltinSceneName);
  }
  return source;
}

LoadedShot load_source(const SceneSource& source) {
  LoadedShot loaded;
  std::string text;
  if (source.path) {
    std::optional<std::string> read = read_scene_file(*source.path, loaded.read_error);
    if (!read) {
      loaded.messages.push_back(loaded.read_error);
      return loaded;
    }
    text = std::move(*read);
  } else {
    text = std::string(builtin_scene_text());
  }
  ShotResult result = load_shot(text, source.name, {.strict = source.strict},
                                source.auto_camera ? CameraChoice::automatic : CameraChoice::scene);
  loaded.shot = std::move(result.shot);
  loaded.diagnostics = std::move(result.diagnostics);
  for (const Diagnostic& d : loaded.diagnostics) loaded.messages.push_back(format_diagnostic(d, source.shown_path));
  return loaded;
}

}  // namespace bsim
