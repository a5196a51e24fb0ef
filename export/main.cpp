// billiards-export: scene -> events, trajectories, camera path, POV-Ray frames, sound, movie.
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>

#include "child_process.h"
#include "export_options.h"
#include "farm_slurm.h"
#include "frame_cache.h"
#include "frames.h"
#include "movie_export.h"
#include "output_stage.h"
#include "outputs.h"
#include "run_summary.h"
#include "scene_file.h"
#include "shot.h"

namespace {

template <class Writer>
bool write_staged(const bsim::OutputStage& stage, const std::string& name, Writer&& writer, std::string& error) {
  std::ofstream out(stage.path(name), std::ios::binary);
  writer(out);
  out.flush();
  if (!out) {
    error = "cannot write " + stage.path(name) + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

/// Every name a run may write into its output directory. A run replaces those it writes and keeps the
/// others an earlier run left (its closing line names them): an `--events-only` run after a render
/// keeps the movie.
const std::vector<std::string> kRunOutputs = {"events.json", "trajectory.csv", "camera.csv",          "frames",
                                              "movie.mp4",   "soundtrack.wav", bsim::kRunSummaryName, "farm"};

/// Whether the file `name` in `dir` holds other bytes than the staged one (false when either is missing).
bool changed_since(const std::string& dir, const bsim::OutputStage& stage, const std::string& name) {
  std::error_code ec;
  const std::filesystem::path older = std::filesystem::path(dir) / name, newer = stage.staging() + "/" + name;
  if (!std::filesystem::is_regular_file(older, ec) || !std::filesystem::is_regular_file(newer, ec)) return false;
  std::ifstream a(older, std::ios::binary), b(newer, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(a), {}) != std::string(std::istreambuf_iterator<char>(b), {});
}

/// The closing line's tail for what an earlier run left: "; kept from an earlier run: movie.mp4, frames/",
/// saying so when they show the shot as it was before (this run's events differ).
std::string kept_note(const std::vector<std::string>& kept, bool outdated) {
  if (kept.empty()) return "";
  std::string note = "; kept from an earlier run: ";
  for (std::size_t i = 0; i < kept.size(); ++i) note += (i ? ", " : "") + kept[i];
  if (outdated) note += " (made before the shot changed; render again to bring them up to date)";
  return note;
}

/// Ctrl-C: what the user keeps. The output directory is as it was; the frames finished (rendered or
/// taken from the store) wait in the frame store for the next run.
void report_interrupted(const bsim::OutputStage& stage, const std::string& dir) {
  int finished = 0;
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(stage.path("frames"), ec);
       !ec && it != std::filesystem::directory_iterator(); it.increment(ec))
    finished += it->path().extension() == ".png";
  std::cerr << "billiards-export: interrupted; "
            << (std::filesystem::exists(dir, ec) ? dir + " is left as it was" : "nothing was written to " + dir);
  const std::string store = bsim::default_frame_cache_dir();
  if (finished > 0 && !store.empty())
    std::cerr << "; the " << finished << " frame" << (finished == 1 ? "" : "s")
              << " finished are kept in the frame store (" << store << ") and the next run reuses them";
  else if (finished > 0)
    std::cerr << "; the frame store is off (BSIM_CACHE_DIR=off), so the next run renders every frame again";
  std::cerr << "\n";
}

/// The closing line's note on a game's replay: "; the movie 92 s with the replay, 5 s of balls only
/// spinning cut" (empty without one).
std::string replay_note(const bsim::Shot& shot) {
  if (!shot.movie.replay()) return "";
  double seconds_cut = 0;
  for (const auto& [from, to] : shot.movie.cuts(shot.timeline.duration())) seconds_cut += to - from;
  const long cut = std::lround(seconds_cut);
  std::ostringstream note;
  note << "; the movie " << std::lround(shot.movie.duration()) << " s with the replay";
  if (cut > 0) note << ", " << cut << " s of balls only spinning cut";
  return note.str();
}

/// Everything a run writes, into the stage: the data files, then (unless --events-only) the frames'
/// .pov files and the sound track, then (unless --no-render) the rendered frames and the movie, and
/// run.json. Interrupted when Ctrl-C came.
bsim::RunOutcome produce(const bsim::Shot& shot, const bsim::ExportOptions& options, const bsim::RunPrograms& programs,
                         const bsim::OutputStage& stage, bsim::StagedFrames& frames, bsim::RunSummary& summary,
                         std::string& error) {
  using bsim::RunOutcome;
  const auto start = std::chrono::steady_clock::now();
  if (!write_staged(
          stage, "events.json", [&](std::ostream& o) { bsim::write_events_json(shot, o); }, error) ||
      !write_staged(
          stage, "trajectory.csv", [&](std::ostream& o) { bsim::write_trajectory_csv(shot, options.fps, o); }, error) ||
      !write_staged(
          stage, "camera.csv", [&](std::ostream& o) { bsim::write_camera_csv(shot, options.fps, o); }, error))
    return RunOutcome::failed;
  if (options.events_only) return RunOutcome::done;
  if (!bsim::write_frames_and_sound(shot, options, stage, frames, summary, error)) return RunOutcome::failed;
  summary.writing = bsim::seconds_since(start);
  if (bsim::InterruptGuard::interrupted()) return RunOutcome::interrupted;
  summary.frames_total = shot.movie.frame_count(options.fps);
  if (!options.no_render) {
    const RunOutcome rendered = bsim::render_movie(shot, options, programs, stage, frames, summary, error);
    if (rendered != RunOutcome::done) return rendered;
    summary.povray_version = bsim::program_version(programs.povray, "--version", "POV-Ray");
    summary.ffmpeg_version = bsim::program_version(programs.ffmpeg, "-version", "ffmpeg version");
  }
  if (!bsim::write_run_summary(summary, options, stage.staging(), error)) return RunOutcome::failed;
  return bsim::InterruptGuard::interrupted() ? RunOutcome::interrupted : RunOutcome::done;
}

int run(const bsim::ExportOptions& options) {
  const bool on_farm = options.farm == bsim::FarmMode::slurm;
  if (options.farm != bsim::FarmMode::none && !on_farm) return bsim::run_farm_command(options);
  const auto start = std::chrono::steady_clock::now();
  const bsim::SceneOrigin origin = bsim::scene_origin(options.scene_path);
  const std::string &name = origin.name, &shown_path = origin.shown_path;
  std::string error;
  const std::optional<std::string> text = bsim::read_scene_text(origin, error);
  if (!text) {
    std::cerr << error << "\n";
    return 1;
  }

  bsim::ShotResult loaded =
      bsim::load_shot(*text, name, {.strict = options.strict},
                      options.auto_camera ? bsim::CameraChoice::automatic : bsim::CameraChoice::scene,
                      options.replay ? bsim::ReplayChoice::on : bsim::ReplayChoice::off);
  for (const bsim::Diagnostic& d : loaded.diagnostics) std::cerr << bsim::format_diagnostic(d, shown_path) << "\n";
  if (!loaded.scripted()) return 1;
  const bsim::Shot& shot = *loaded.scripted();
  bsim::RunSummary summary;
  summary.scene = shown_path;
  summary.output = options.out_dir ? *options.out_dir : "out/" + name;
  summary.simulating = bsim::seconds_since(start);

  // Every program the run needs is found before any work, so a missing one costs nothing.
  bsim::RunPrograms programs;
  bsim::ExportOptions staged = options;  // on the farm, this run renders nothing itself
  staged.no_render = staged.no_render || on_farm;
  if (!bsim::find_run_programs(staged, programs, error)) {
    std::cerr << "billiards-export: error: " << error << "\n";
    return 1;
  }
  const std::string& dir = summary.output;
  bsim::SlurmSubmission farm;  // --farm slurm: the inputs here, the rendering on the cluster
  if (on_farm && !farm.prepare(options, dir, error)) {
    std::cerr << "billiards-export: error: " << error << "\n";
    return 1;
  }
  bsim::InterruptGuard guard;  // Ctrl-C from here on stops the children and discards the stage first
  bsim::OutputStage stage;
  if (!stage.open(dir, error)) {
    std::cerr << "billiards-export: error: " << error << "\n";
    return 1;
  }
  bsim::StagedFrames frames;  // what frames/ holds, each frame computed once
  bsim::RunOutcome outcome = produce(shot, staged, programs, stage, frames, summary, error);
  if (outcome == bsim::RunOutcome::done && on_farm && !farm.stage(shot, options, stage, frames, error))
    outcome = bsim::RunOutcome::failed;
  const bool outdated = changed_since(dir, stage, "events.json");
  // A farm submission's movie job makes the movie: an older one goes now, never to pass for the new one.
  const std::vector<std::string> made_later =
      on_farm ? std::vector<std::string>{"movie.mp4"} : std::vector<std::string>{};
  if (outcome == bsim::RunOutcome::done && !stage.commit(error, kRunOutputs, made_later))
    outcome = bsim::RunOutcome::failed;
  if (outcome == bsim::RunOutcome::interrupted) {
    report_interrupted(stage, dir);
    stage.discard();  // the output directory stays exactly as it was
    guard.finish();   // dies of the signal, as the user asked
  }
  if (outcome != bsim::RunOutcome::done) {
    stage.discard();  // the output directory stays exactly as it was
    std::cerr << "billiards-export: error: " << error << "\n";
    return 1;
  }
  if (on_farm) {
    const int status = farm.submit(error);
    if (status != 0) std::cerr << "billiards-export: error: " << error << "\n";
    return status;
  }
  if (options.quiet) return 0;  // --quiet: success is the exit status alone
  if (!options.events_only && !options.no_render)
    std::cerr << "wrote " << dir << "/movie.mp4 (" << summary.frames_rendered << " frames rendered, "
              << summary.frames_reused << " reused)";
  else
    std::cerr << "wrote " << dir << "/ (" << shot.timeline.events().size() << " events, " << shot.timeline.duration()
              << " s" << replay_note(shot) << ")";
  std::cerr << kept_note(stage.kept(), outdated) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // A file grown past the size limit fails its write (reported, the run undone) rather than killing
  // the program with half its outputs staged.
  std::signal(SIGXFSZ, SIG_IGN);
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
