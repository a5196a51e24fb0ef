#include "shot_source.h"

namespace bsim {

SceneSource scene_source(const std::optional<std::string>& path, bool strict) {
  SceneSource source;
  static_cast<SceneOrigin&>(source) = scene_origin(path);
  source.strict = strict;
  return source;
}

LoadedShot load_source(const SceneSource& source) {
  LoadedShot loaded;
  const std::optional<std::string> text = read_scene_text(source, loaded.read_error);
  if (!text) {
    loaded.messages.push_back(loaded.read_error);
    return loaded;
  }
  loaded.text = *text;
  ShotResult result = load_shot(*text, source.name, {.strict = source.strict},
                                source.auto_camera ? CameraChoice::automatic : CameraChoice::scene,
                                source.replay ? ReplayChoice::on : ReplayChoice::off);
  loaded.shot = std::move(result.shot);
  loaded.diagnostics = std::move(result.diagnostics);
  for (const Diagnostic& d : loaded.diagnostics) loaded.messages.push_back(format_diagnostic(d, source.shown_path));
  return loaded;
}

}  // namespace bsim
