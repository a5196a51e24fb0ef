// billiards-preview: the shot drawn with OpenGL, headless (snapshots, the timeline picture, the
// animatic) or in a window with a scrub bar.
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "preview_options.h"
#include "script_as_written.h"
#include "shot_source.h"
#include "write_camera.h"
#include "write_scene.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  bsim::PreviewOptions options;
  std::string message;
  switch (bsim::parse_preview_options(args, options, message)) {
    case bsim::PreviewCommandLineOutcome::exit_success: std::cout << message; return 0;
    case bsim::PreviewCommandLineOutcome::exit_usage: std::cerr << "billiards-preview: " << message << "\n"; return 2;
    case bsim::PreviewCommandLineOutcome::run: break;
  }
  bsim::SceneSource source = bsim::scene_source(options.scene_path, options.strict);
  source.auto_camera = options.auto_camera;
  source.replay = options.replay;
  const bool pictures = !options.at.empty() || options.timeline || options.movie;
  if (!pictures && !options.write_camera && !options.write_scene) return bsim::run_window(options, source);

  const bsim::LoadedShot loaded = bsim::load_source(source);
  for (const std::string& line : loaded.messages) std::cerr << line << "\n";
  if (options.timeline && loaded.shot && !loaded.scripted()) {
    // The camera script failed: the picture of the real events shows why, but the run still fails.
    const std::string file = std::filesystem::path(source.shown_path).filename().string();
    bsim::run_timeline_picture(options, bsim::unscripted_timeline_data(*loaded.shot, loaded.diagnostics, file));
    return 1;
  }
  if (!loaded.scripted()) return 1;
  if (options.write_camera) {
    const int status = bsim::run_write_camera(*options.write_camera, *loaded.shot, options.quiet);
    if (status != 0 || (!pictures && !options.write_scene)) return status;
  }
  if (options.write_scene) {
    const int status = bsim::run_write_scene(*options.write_scene, loaded.text, *loaded.shot, options.quiet);
    if (status != 0 || !pictures) return status;
  }
  if (!options.at.empty()) return bsim::run_snapshot(options, *loaded.shot);
  if (options.timeline) {
    bsim::TimelineData data = bsim::timeline_data(*loaded.shot);
    if (options.auto_camera) data.title += "  \xE2\x80\x94  camera: the automatic director";
    return bsim::run_timeline_picture(options, data);
  }
  return bsim::run_animatic(options, *loaded.shot);
}
