#include "movie_export.h"

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "child_process.h"
#include "ffmpeg_assemble.h"
#include "frame_cache.h"
#include "frames.h"
#include "output_stage.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "render_jobs.h"
#include "shot.h"
#include "soundtrack.h"

namespace bsim {

namespace {

/// The README's one command that installs POV-Ray and ffmpeg, builds and renders.
constexpr const char* kSetUpCommand = "bash .ci/make-movie";

/// Frames this small take less time to render than POV-Ray takes to start (~0.6 s of mostly
/// idle wall time), so by default more processes than cores run at once.
constexpr long kSmallFramePixels = 320L * 180L;
constexpr int kSmallFrameProcessesPerCore = 3;

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

template <class Writer>
bool write_file(const std::string& path, Writer&& writer, std::string& error) {
  std::ofstream out(path, std::ios::binary);
  writer(out);
  out.flush();
  if (!out) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

int cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

int process_count(const ExportOptions& options) {
  if (options.jobs > 0) return options.jobs;
  const long pixels = static_cast<long>(options.width) * options.height;
  return pixels <= kSmallFramePixels ? cores() * kSmallFrameProcessesPerCore : cores();
}

std::string quality_name(Quality quality) { return quality == Quality::final ? "final" : "draft"; }

/// Removes what a run into this directory left that no longer belongs: frame files and pictures
/// past the shot's end, half-written pictures and logs of a run that was killed outright.
void remove_stale(const std::string& frames_dir, int frames, FrameCache& cache) {
  std::error_code ec;
  std::vector<std::filesystem::path> stale;
  for (const auto& entry : std::filesystem::directory_iterator(frames_dir, ec)) {
    const std::string name = entry.path().filename().string();
    int frame = -1;
    const bool numbered = name.size() == 15 && name.rfind("frame_", 0) == 0 &&
                          (name.ends_with(".png") || name.ends_with(".pov")) &&
                          std::sscanf(name.c_str(), "frame_%5d.", &frame) == 1;
    const bool leftover = name.rfind(".frame_", 0) == 0 && (name.ends_with(".tmp.png") || name.ends_with(".log"));
    if ((numbered && frame >= frames) || leftover) stale.push_back(entry.path());
  }
  for (const auto& path : stale) {  // removed after listing: removing while iterating is unspecified
    std::filesystem::remove(path, ec);
    cache.erase(path.filename().string());
  }
}

}  // namespace

bool write_frames_and_sound(const Shot& shot, const ExportOptions& options, const OutputStage& stage,
                            std::string& error) {
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(stage.path("frames/x")).parent_path(), ec);
  if (ec) {
    error = "cannot create " + stage.path("frames") + ": " + ec.message();
    return false;
  }
  if (!write_file(
          stage.path("frames/" + std::string(kPovIncludeName)),
          [&](std::ostream& out) { write_pov_include(shot.scene, options.quality, out); }, error))
    return false;
  const int frames = frame_count(shot.timeline.duration(), options.fps);
  for (int k = 0; k < frames; ++k) {
    if (!write_file(
            stage.path("frames/" + frame_name(k) + ".pov"),
            [&](std::ostream& out) { write_pov_frame(shot, k, options.fps, out); }, error))
      return false;
  }

  // Exactly as long as the shot; the duration is a whole number of seconds, so of frames too.
  const auto samples = static_cast<std::size_t>(std::llround(shot.timeline.duration() * kSampleRate));
  AudioBuffer audio;
  if (!mix_soundtrack({shot.scene, shot.timeline, *shot.camera},
                      {.lead = options.audio_lead, .music_path = options.music_path}, samples, audio, error))
    return false;
  return write_wav(stage.path("soundtrack.wav"), audio, error);
}

bool render_movie(const Shot& shot, const ExportOptions& options, const std::string& dir, std::string& error) {
  const std::string povray = find_program("povray"), ffmpeg = find_program("ffmpeg");
  for (const auto& [program, path] : {std::pair{"povray", povray}, std::pair{"ffmpeg", ffmpeg}}) {
    if (path.empty()) {
      error = std::string(program) + " is not installed; run `" + kSetUpCommand +
              "` (see README) to set up, or pass --no-render";
      return false;
    }
  }

  const std::string frames_dir = dir + "/frames";
  const int frames = frame_count(shot.timeline.duration(), options.fps);
  const std::string settings =
      std::to_string(options.width) + "x" + std::to_string(options.height) + " " + quality_name(options.quality);
  const std::uint64_t common = fnv1a(settings, fnv1a(read_text(frames_dir + "/" + std::string(kPovIncludeName))));
  FrameCache cache(frames_dir);
  remove_stale(frames_dir, frames, cache);
  std::vector<FrameJob> jobs;
  for (int k = 0; k < frames; ++k) {
    const std::uint64_t key = fnv1a(read_text(frames_dir + "/" + frame_name(k) + ".pov"), common);
    if (!cache.up_to_date(frame_name(k) + ".png", key)) jobs.push_back({k, key});
  }
  // A movie left from before no longer matches these frames.
  std::error_code ec;
  std::filesystem::remove(dir + "/movie.mp4", ec);

  InterruptGuard guard;
  RenderSettings render{povray, options.width, options.height, options.quality, process_count(options)};
  render.quiet = options.quiet;
  RunOutcome outcome = render_frames(frames_dir, jobs, frames, render, cache, error);
  if (outcome == RunOutcome::done) {
    const MovieSettings movie{ffmpeg, options.fps, shot.timeline.duration(), options.quiet};
    outcome = assemble_movie(dir, movie, error);
  }
  if (outcome == RunOutcome::interrupted) {
    guard.finish();  // dies of the signal, as the user asked, now that nothing half-written is left
    error = "interrupted";
  }
  cache.save();
  return outcome == RunOutcome::done;
}

}  // namespace bsim
