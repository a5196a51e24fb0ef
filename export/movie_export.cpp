#include "movie_export.h"

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "changed_region.h"
#include "child_process.h"
#include "develop.h"
#include "ffmpeg_assemble.h"
#include "frame_cache.h"
#include "frame_captions.h"
#include "frame_lens.h"
#include "frames.h"
#include "loudness.h"
#include "output_stage.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "render_jobs.h"
#include "run_summary.h"
#include "scene_file.h"
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

/// A frame's text without its `//` comment lines (its number and time): what the picture depends on.
std::string without_comment_lines(const std::string& text) {
  std::string kept;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    end = end == std::string::npos ? text.size() : end + 1;
    if (text.compare(start, 2, "//") != 0) kept.append(text, start, end - start);
    start = end;
  }
  return kept;
}

/// Frames whose inputs are all the same (balls at rest under a still camera) are rendered once.
struct FramePlan {
  std::vector<FrameJob> jobs;                   ///< to render
  std::vector<std::pair<int, int>> duplicates;  ///< (frame, the earlier frame it copies)
  int fetched = 0;                              ///< copied from the store
};

FramePlan plan_frames(const std::vector<std::uint64_t>& keys, const FrameCache& cache) {
  FramePlan plan;
  std::map<std::uint64_t, int> first;
  for (int k = 0; k < static_cast<int>(keys.size()); ++k) {
    const std::uint64_t key = keys[k];
    const auto [it, fresh] = first.emplace(key, k);
    if (!fresh)
      plan.duplicates.emplace_back(k, it->second);
    else if (cache.fetch(frame_name(k) + ".png", key))
      ++plan.fetched;
    else
      plan.jobs.push_back({k, key, -1, {}});
  }
  return plan;
}

/// frames/captions.txt for a game's movie with captions (frame_captions.h). The fonts are looked for
/// only where the frames are rendered.
bool write_captions(const Shot& shot, const ExportOptions& options, const std::string& frames_dir, std::string& error) {
  if (!options.captions || !shot.game) return true;
  if (!options.no_render && !lower_third_fonts(error)) return false;
  const std::vector<FrameCaption> captions =
      frame_captions(shot, movie_frame_moments(shot, options.fps), options.width, options.height);
  return write_file(
      frames_dir + "/" + kCaptionsName, [&](std::ostream& out) { out << captions_text(captions); }, error);
}

/// frames/lens.txt: each frame's lens and what it sees, for the develop stage (frame_lens.h).
bool write_lens(const Shot& shot, const ExportOptions& options, const std::string& frames_dir, std::string& error) {
  const std::string text = lens_text(depth_scene(shot.scene), frame_lenses(shot, options.fps));
  return write_file(
      frames_dir + "/" + kLensName, [&](std::ostream& out) { out << text; }, error);
}

bool copy_duplicates(const std::string& frames_dir, const FramePlan& plan, std::string& error) {
  for (const auto& [frame, source] : plan.duplicates) {
    std::error_code ec;
    const std::string to = frames_dir + "/" + frame_name(frame) + ".png";
    std::filesystem::copy_file(frames_dir + "/" + frame_name(source) + ".png", to,
                               std::filesystem::copy_options::overwrite_existing, ec);
    if (ec) {
      error = "cannot write " + to + ": " + ec.message();
      return false;
    }
  }
  return true;
}

}  // namespace

void plan_partial_frames(const Shot& shot, const ExportOptions& options, std::vector<FrameJob>& jobs) {
  const RegionScene scene = region_scene(shot.scene);
  std::map<std::string, std::pair<int, FrameContent>> last;  // camera -> the latest job's frame and content
  for (FrameJob& job : jobs) {
    FrameContent content = frame_content(shot, job.frame, options.fps);
    const auto before = last.find(content.camera);
    if (before != last.end()) {
      const auto region = changed_region(before->second.second, content, scene, options.width, options.height);
      if (region) {
        job.reference = before->second.first;
        job.rects = *region;
      }
    }
    const std::string camera = content.camera;
    last.insert_or_assign(camera, std::pair<int, FrameContent>(job.frame, std::move(content)));
  }
}

std::vector<std::uint64_t> frame_store_keys(const std::string& frames_dir, int frames, const ExportOptions& options) {
  // What every picture depends on besides its own .pov text: the size, the quality (and POV-Ray's
  // options for it) and how the picture is developed; "v3" names the store's key format.
  std::string settings = "v3 " + std::to_string(options.width) + "x" + std::to_string(options.height) + " " +
                         std::string(quality_name(options.quality)) + " " + develop_signature();
  for (const std::string& flag : povray_quality_arguments(options.quality)) settings += " " + flag;
  const std::uint64_t common = fnv1a(settings, fnv1a(read_text_file(frames_dir + "/" + std::string(kPovIncludeName))));
  std::vector<std::uint64_t> keys;
  for (int k = 0; k < frames; ++k)
    keys.push_back(fnv1a(without_comment_lines(read_text_file(frames_dir + "/" + frame_name(k) + ".pov")), common));
  add_caption_keys(frames_dir, keys);  // a frame's caption is part of its picture
  add_lens_keys(frames_dir, keys);     // and its lens, focus and grain
  return keys;
}

bool write_frames_and_sound(const Shot& shot, const ExportOptions& options, const OutputStage& stage,
                            RunSummary& summary, std::string& error) {
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
  const int frames = shot.movie.frame_count(options.fps);
  for (int k = 0; k < frames; ++k) {
    if (!write_file(
            stage.path("frames/" + frame_name(k) + ".pov"),
            [&](std::ostream& out) { write_pov_frame(shot, k, options.fps, out); }, error))
      return false;
  }
  if (!write_captions(shot, options, stage.path("frames"), error)) return false;
  if (!write_lens(shot, options, stage.path("frames"), error)) return false;

  // Exactly as long as the movie; its duration is a whole number of seconds, so of frames too.
  const auto samples = static_cast<std::size_t>(std::llround(shot.movie.duration() * kSampleRate));
  AudioBuffer audio;
  const SoundOptions sound{.lead = options.audio_lead, .music_path = options.music_path, .level = options.level};
  const SoundMovie movie{&shot.movie, shot.replay_camera ? &*shot.replay_camera : nullptr};
  if (!mix_movie_soundtrack({shot.scene, shot.timeline, *shot.camera}, movie, sound, samples, audio, error))
    return false;
  summary.loudness_lufs = integrated_loudness(audio);
  summary.true_peak_dbtp = to_db(true_peak(audio));
  return write_wav(stage.path("soundtrack.wav"), audio, error);
}

bool find_run_programs(const ExportOptions& options, RunPrograms& programs, std::string& error) {
  programs = {};
  if (options.events_only || options.no_render) return true;
  programs.povray = find_program("povray");
  programs.ffmpeg = find_program("ffmpeg");
  for (const auto& [program, path] : {std::pair{"povray", programs.povray}, std::pair{"ffmpeg", programs.ffmpeg}}) {
    if (path.empty()) {
      error = std::string(program) + " is not installed; run `" + kSetUpCommand +
              "` (see README) to set up, or pass --no-render";
      return false;
    }
  }
  return true;
}

RunOutcome render_movie(const Shot& shot, const ExportOptions& options, const RunPrograms& programs,
                        const OutputStage& stage, RunSummary& summary, std::string& error) {
  const std::string frames_dir = stage.path("frames");
  const int frames = shot.movie.frame_count(options.fps);
  FrameCache cache(default_frame_cache_dir(), frames_dir);
  FramePlan plan = plan_frames(frame_store_keys(frames_dir, frames, options), cache);
  if (!options.whole_frames) plan_partial_frames(shot, options, plan.jobs);
  long traced = 0;
  for (const FrameJob& job : plan.jobs) {
    if (job.reference < 0) {
      traced += static_cast<long>(options.width) * options.height;
      continue;
    }
    ++summary.frames_partial;
    for (const PixelRect& r : job.rects) traced += r.area();
  }
  if (!plan.jobs.empty())
    summary.traced_share = static_cast<double>(traced) / (static_cast<double>(options.width) * options.height *
                                                          static_cast<double>(plan.jobs.size()));
  summary.frames_rendered = static_cast<int>(plan.jobs.size());
  summary.frames_reused = frames - summary.frames_rendered;

  auto start = std::chrono::steady_clock::now();
  RenderSettings render{
      programs.povray, options.width, options.height, options.quality, process_count(options), "", false};
  render.shown_frames_dir = summary.output + "/frames";  // where `--no-render` would put the file to look at
  render.quiet = options.quiet;
  RunOutcome outcome = render_frames(frames_dir, plan.jobs, frames, render, cache, error);
  if (outcome == RunOutcome::done && !copy_duplicates(frames_dir, plan, error)) outcome = RunOutcome::failed;
  summary.rendering = seconds_since(start);
  cache.trim();
  if (outcome != RunOutcome::done) return outcome;

  start = std::chrono::steady_clock::now();
  const MovieSettings movie{programs.ffmpeg, options.fps, shot.movie.duration(), options.quiet};
  outcome = assemble_movie(stage.staging(), movie, error);
  summary.encoding = seconds_since(start);
  return outcome;
}

}  // namespace bsim
