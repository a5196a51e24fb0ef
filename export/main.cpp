// billiards-export: scene -> events, trajectories, camera path, POV-Ray frames, sound, movie.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "builtin_scene.h"
#include "export_options.h"
#include "movie_export.h"
#include "output_stage.h"
#include "outputs.h"
#include "scene_file.h"
#include "shot.h"

namespace {

template <class Writer>
bool write_staged(const bsim::OutputStage& stage, const std::string& name, Writer&& writer) {
  std::ofstream out(stage.path(name), std::ios::binary);
  writer(out);
  out.flush();
  if (!out) {
    std::cerr << "billiards-export: error: cannot write " << stage.path(name) << "\n";
    return false;
  }
  return true;
}

int run(const bsim::ExportOptions& options) {
  std::string text, name, shown_path;
  if (options.scene_path) {
    shown_path = *options.scene_path;
    std::string error;
    std::optional<std::string> read = bsim::read_scene_file(shown_path, error);
    if (!read) {
      std::cerr << error << "\n";
      return 1;
    }
    text = std::move(*read);
    name = std::filesystem::path(shown_path).stem().string();
  } else {
    text = std::string(bsim::builtin_scene_text());
    name = std::string(bsim::kBuiltinSceneName);
    shown_path = "<built-in break.scn>";
  }

  bsim::ShotResult loaded = bsim::load_shot(text, name, {.strict = options.strict});
  for (const bsim::Diagnostic& d : loaded.diagnostics) std::cerr << bsim::format_diagnostic(d, shown_path) << "\n";
  if (!loaded.shot) return 1;
  const bsim::Shot& shot = *loaded.shot;

  const std::string dir = options.out_dir ? *options.out_dir : "out/" + name;
  bsim::OutputStage stage;
  std::string error;
  if (!stage.open(dir, error)) {
    std::cerr << "billiards-export: error: " << error << "\n";
    return 1;
  }
  if (!write_staged(stage, "events.json", [&](std::ostream& o) { bsim::write_events_json(shot, o); }) ||
      !write_staged(stage, "trajectory.csv",
                    [&](std::ostream& o) { bsim::write_trajectory_csv(shot, options.fps, o); }) ||
      !write_staged(stage, "camera.csv", [&](std::ostream& o) { bsim::write_camera_csv(shot, options.fps, o); }))
    return 1;
  if (!options.events_only && !bsim::write_frames_and_sound(shot, options, stage, error)) {
    std::cerr << "billiards-export: error: " << error << "\n";
    return 1;
  }
  if (!stage.commit(error)) {
    std::cerr << "billiards-export: error: " << error << "\n";
    return 1;
  }
  if (!options.events_only && !options.no_render) {
    if (!bsim::render_movie(shot, options, dir, error)) {
      std::cerr << "billiards-export: error: " << error << "\n";
      return 1;
    }
    std::cerr << "wrote " << dir << "/movie.mp4\n";
  } else {
    std::cerr << "wrote " << dir << "/ (" << shot.timeline.events().size() << " events, " << shot.timeline.duration()
              << " s)\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  bsim::ExportOptions options;
  std::string message;
  switch (bsim::parse_export_options(args, options, message)) {
    case bsim::CommandLineOutcome::exit_success: std::cout << message; return 0;
    case bsim::CommandLineOutcome::exit_usage: std::cerr << "billiards-export: " << message << "\n"; return 2;
    case bsim::CommandLineOutcome::run: break;
  }
  return run(options);
}
