#include "movie_export.h"

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
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

bool write_text(const std::string& path, const std::string& text, std::string& error) {
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.flush();
  if (!out) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

/// soundtrack.wav, exactly as long as the movie; `summary` gets its measured loudness.
bool write_sound(const Shot& shot, const ExportOptions& options, const OutputStage& stage, RunSummary& summary,
                 std::string& error) {
  // The movie's duration is a whole number of seconds, so of frames too.
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

/// frames/captions.txt's text for a game's movie with captions (frame_captions.h), empty for none. The
/// fonts are looked for only where the frames are rendered.
bool captions_text_for(const Shot& shot, const ExportOptions& options, std::string& text, std::string& error) {
  text.clear();
  if (!options.captions || !shot.game) return true;
  if (!options.no_render && !lower_third_fonts(error)) return false;
  text = captions_text(frame_captions(shot, movie_frame_moments(shot, options.fps), options.width, options.height));
  return true;
}

/// frames/lens.txt's text: each frame's lens and what it sees, for the develop stage (frame_lens.h),
/// the camera poses from the frames' contents.
std::string lens_text_for(const Shot& shot, const ExportOptions& options, const std::vector<FrameContent>& contents) {
  std::vector<CameraPose> poses;
  poses.reserve(contents.size());
  for (const FrameContent& content : contents) poses.push_back(content.camera_pose);
  return lens_text(depth_scene(shot.scene), frame_lenses(shot, options.fps, poses));
}

/// What every picture depends on besides its own .pov text, caption and lens: the shared include,
/// the size, the quality (and POV-Ray's options for it) and how the picture is developed; "v3" names
/// the store's key format.
std::uint64_t common_key(const std::string& include, const ExportOptions& options) {
  std::string settings = "v3 " + std::to_string(options.width) + "x" + std::to_string(options.height) + " " +
                         std::string(quality_name(options.quality)) + " " + develop_signature();
  for (const std::string& flag : povray_quality_arguments(options.quality)) settings += " " + flag;
  return fnv1a(settings, fnv1a(include));
}

/// The frames' partial renders, each job's content from `content_of(frame)` (alive until the end).
template <class ContentOf>
void plan_partial(const Scene& scene, const ExportOptions& options, std::vector<FrameJob>& jobs,
                  ContentOf&& content_of) {
  const RegionScene region = region_scene(scene);
  std::map<std::string_view, std::pair<int, const FrameContent*>> last;  // camera -> the latest job's frame
  for (FrameJob& job : jobs) {
    const FrameContent& content = content_of(job.frame);
    const auto before = last.find(content.camera);
    if (before != last.end()) {
      const auto rects = changed_region(*before->second.second, content, region, options.width, options.height);
      if (rects) {
        job.reference = before->second.first;
        job.rects = *rects;
      }
    }
    last.insert_or_assign(content.camera, std::pair<int, const FrameContent*>(job.frame, &content));
  }
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

void plan_partial_frames(const Scene& scene, const StagedFrames& frames, const ExportOptions& options,
                         std::vector<FrameJob>& jobs) {
  plan_partial(scene, options, jobs,
               [&](int frame) -> const FrameContent& { return frames.contents.at(static_cast<std::size_t>(frame)); });
}

void plan_partial_frames(const Shot& shot, const ExportOptions& options, std::vector<FrameJob>& jobs) {
  std::map<int, FrameContent> contents;
  plan_partial(shot.scene, options, jobs, [&](int frame) -> const FrameContent& {
    auto it = contents.find(frame);
    if (it == contents.end()) it = contents.emplace(frame, frame_content(shot, frame, options.fps)).first;
    return it->second;
  });
}

std::vector<std::uint64_t> frame_store_keys(const std::string& frames_dir, int frames, const ExportOptions& options) {
  const std::uint64_t common = common_key(read_text_file(frames_dir + "/" + std::string(kPovIncludeName)), options);
  std::vector<std::uint64_t> keys;
  for (int k = 0; k < frames; ++k)
    keys.push_back(fnv1a(without_comment_lines(read_text_file(frames_dir + "/" + frame_name(k) + ".pov")), common));
  add_caption_keys(frames_dir, keys);  // a frame's caption is part of its picture
  add_lens_keys(frames_dir, keys);     // and its lens, focus and grain
  return keys;
}

std::vector<std::uint64_t> frame_store_keys(const StagedFrames& frames, const ExportOptions& options) {
  const std::uint64_t common = common_key(frames.include, options);
  std::vector<std::uint64_t> keys;
  keys.reserve(frames.contents.size());
  for (const FrameContent& content : frames.contents)
    keys.push_back(fnv1a(without_comment_lines(pov_frame_text(content)), common));
  add_caption_keys(caption_lines(frames.captions), keys);
  add_lens_keys(lens_file(frames.lens), keys);
  return keys;
}

bool write_frames_and_sound(const Shot& shot, const ExportOptions& options, const OutputStage& stage,
                            StagedFrames& frames, RunSummary& summary, std::string& error) {
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(stage.path("frames/x")).parent_path(), ec);
  if (ec) {
    error = "cannot create " + stage.path("frames") + ": " + ec.message();
    return false;
  }
  std::ostringstream include;
  write_pov_include(shot.scene, options.quality, include);
  frames = {include.str(), {}, {}, {}};
  if (!write_text(stage.path("frames/" + std::string(kPovIncludeName)), frames.include, error)) return false;
  // Each frame's content once: its file now, and its key and partial render later from memory.
  const int count = shot.movie.frame_count(options.fps);
  frames.contents.reserve(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    frames.contents.push_back(frame_content(shot, k, options.fps));
    if (!write_text(stage.path("frames/" + frame_name(k) + ".pov"), pov_frame_text(frames.contents.back()), error))
      return false;
  }
  if (!captions_text_for(shot, options, frames.captions, error)) return false;
  if (!frames.captions.empty() &&
      !write_text(stage.path("frames/" + std::string(kCaptionsName)), frames.captions, error))
    return false;
  frames.lens = lens_text_for(shot, options, frames.contents);
  if (!write_text(stage.path("frames/" + std::string(kLensName)), frames.lens, error)) return false;
  return write_sound(shot, options, stage, summary, error);
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
                        const OutputStage& stage, const StagedFrames& staged, RunSummary& summary, std::string& error) {
  const std::string frames_dir = stage.path("frames");
  const int frames = shot.movie.frame_count(options.fps);
  FrameCache cache(default_frame_cache_dir(), frames_dir);
  FramePlan plan = plan_frames(frame_store_keys(staged, options), cache);
  if (!options.whole_frames) plan_partial_frames(shot.scene, staged, options, plan.jobs);
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
