// Submitting a farm run (`--farm slurm`): the frames to render and their chunks, the run's files
// staged into DIR/farm/, and the job array and the movie job handed to sbatch.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>

#include "atomic_file.h"
#include "child_process.h"
#include "farm_files.h"
#include "farm_slurm.h"
#include "frame_cache.h"
#include "frames.h"
#include "movie_export.h"
#include "output_stage.h"
#include "pov_frame.h"
#include "render_jobs.h"
#include "shot.h"
#include "slurm_client.h"

namespace fs = std::filesystem;

namespace bsim {

namespace {

using namespace farm;

/// POV-Ray's start-up and its cost a pixel (s), fitted to README's render-time table: draft 1.3 s
/// at 640x360 and 5.1 s at 1280x720, final 2.8 s and 9.0 s.
constexpr double kStartSeconds = 0.6;
constexpr double kDraftPixelSeconds = 5.5e-6;
constexpr double kFinalPixelSeconds = 9.0e-6;

/// What the jobs of a submission must do: the frames that are the same as an earlier one, and the
/// frames still to render.
struct SubmissionPlan {
  FrameCopies copies;
  std::vector<int> missing;
  int copies_to_make = 0;  ///< copies whose picture the tasks make (their frame is still to render)
};

/// Stages every picture that is there already (an earlier submission's whose inputs are unchanged,
/// one the frame store holds, a copy of one of those) and returns what is left to the jobs.
SubmissionPlan plan_submission(const std::string& dir, const FarmConf& conf, const ExportOptions& options,
                               const OutputStage& stage, const StagedFrames& staged) {
  const int frames = conf.frames;
  // The others may be in this machine's frame store, from a local run or an earlier farm run.
  const FrameCache store(default_frame_cache_dir(), stage.path("frames"));
  const std::vector<std::uint64_t> keys = frame_store_keys(staged, options);
  // Frames an earlier submission finished are kept when everything they depend on is unchanged: the
  // same size and quality, and the same frame store key (their .pov text, the shared include).
  FarmConf earlier;
  std::string ignored;
  std::vector<std::uint64_t> earlier_keys;
  if (read_conf(dir, earlier, ignored) && earlier.width == conf.width && earlier.height == conf.height &&
      earlier.quality == conf.quality)
    earlier_keys = frame_store_keys(dir + "/frames", std::min(earlier.frames, frames), options);
  // A frame whose inputs are an earlier frame's is that frame's picture: rendered once, then copied
  // by the task that renders it (and by the movie job, whatever happened to the task).
  SubmissionPlan plan;
  std::map<std::uint64_t, int> first;
  for (int k = 0; k < frames; ++k) {
    const auto found = first.emplace(keys[static_cast<std::size_t>(k)], k);
    if (!found.second) plan.copies.add(k, found.first->second);
  }
  for (int k = 0; k < frames; ++k) {
    const std::string png = "frames/" + frame_name(k) + ".png";
    const auto i = static_cast<std::size_t>(k);
    if (i < earlier_keys.size() && earlier_keys[i] == keys[i] && picture_there(dir, k) &&
        link_or_copy(dir + "/" + png, stage.path(png)))
      continue;
    if (const auto it = plan.copies.source.find(k); it != plan.copies.source.end()) {
      const std::string from = stage.path("frames/" + frame_name(it->second) + ".png");
      std::error_code ec;
      if (!(fs::file_size(from, ec) > 0 && !ec && link_or_copy(from, stage.path(png)))) ++plan.copies_to_make;
      continue;
    }
    if (store.fetch(frame_name(k) + ".png", keys[i])) continue;
    plan.missing.push_back(k);
  }
  return plan;
}

/// Stages DIR/farm/: the logs of earlier submissions, the run's files, the job scripts and this
/// program, executable.
bool stage_farm_files(const std::string& dir, const OutputStage& stage, const FarmConf& conf,
                      const std::vector<std::pair<int, int>>& chunks, const FrameCopies& copies,
                      const std::map<int, PartialPlan>& partial, std::string& error) {
  std::error_code ec;
  fs::create_directories(stage.path(kLogs), ec);
  if (ec) {
    error = "cannot create " + stage.path(kLogs) + ": " + ec.message();
    return false;
  }
  // The logs of earlier submissions stay: a frame that failed is explained there.
  for (auto it = fs::directory_iterator(dir + "/" + kLogs, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
    link_or_copy(it->path().string(), stage.path(std::string(kLogs) + "/" + it->path().filename().string()));
  if (!write_file_atomically(stage.path(kConf), conf_text(conf), error) ||
      !write_file_atomically(stage.path(kChunks), chunks_text(chunks), error) ||
      !write_file_atomically(stage.path(kCopies), copies_text(copies), error) ||
      !write_file_atomically(stage.path(kPartial), partial_text(partial), error) ||
      !write_file_atomically(stage.path(kTaskScript), task_script(dir), error) ||
      !write_file_atomically(stage.path(kMovieScript), movie_script(dir), error))
    return false;
  // The jobs run the billiards-export installed on the node when it is this version, otherwise this
  // copy: then nothing on the nodes but povray and ffmpeg is assumed.
  const std::string self = fs::read_symlink("/proc/self/exe", ec).string();
  if (ec || !fs::copy_file(self, stage.path(kProgram), ec) || ec) {
    error = "cannot copy billiards-export into " + stage.path(kProgram) + (ec ? ": " + ec.message() : "");
    return false;
  }
  for (const char* script : {kTaskScript, kMovieScript, kProgram}) {
    fs::permissions(stage.path(script),
                    fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                        fs::perms::others_exec,
                    ec);
    if (ec) {
      error = "cannot make " + stage.path(script) + " executable: " + ec.message();
      return false;
    }
  }
  return true;
}

}  // namespace

double estimated_frame_seconds(int width, int height, Quality quality) {
  const double pixel = quality == Quality::final ? kFinalPixelSeconds : kDraftPixelSeconds;
  return kStartSeconds + pixel * width * height;
}

int default_farm_chunk(int width, int height, Quality quality) {
  const double frames = std::floor(kFarmTaskSeconds / estimated_frame_seconds(width, height, quality));
  return static_cast<int>(std::clamp(frames, 1.0, static_cast<double>(kMaxFarmChunk)));
}

std::vector<std::pair<int, int>> farm_chunks(const std::vector<int>& missing, int chunk) {
  std::vector<std::pair<int, int>> runs;  // contiguous runs of missing frames
  for (int frame : missing) {
    if (!runs.empty() && runs.back().second == frame - 1)
      runs.back().second = frame;
    else
      runs.emplace_back(frame, frame);
  }
  // Each run in as few chunks as --chunk allows, of sizes that differ by one at most, so that no
  // task is left with a short tail.
  std::vector<std::pair<int, int>> chunks;
  for (const auto& run : runs) {
    const int length = run.second - run.first + 1, pieces = (length + chunk - 1) / chunk;
    int first = run.first;
    for (int i = 0; i < pieces; ++i) {
      const int size = length / pieces + (i < length % pieces ? 1 : 0);
      chunks.emplace_back(first, first + size - 1);
      first += size;
    }
  }
  return chunks;
}

bool SlurmSubmission::prepare(const ExportOptions& options, const std::string& dir, std::string& error) {
  sbatch_ = find_program("sbatch");
  if (sbatch_.empty()) {
    error =
        "sbatch is not on PATH: --farm slurm submits jobs with Slurm's sbatch; run it on a machine of the "
        "cluster (a login node), or install Slurm's client programs (Debian: slurm-client)";
    return false;
  }
  squeue_ = find_program("squeue");
  scancel_ = find_program("scancel");
  dir_ = fs::absolute(dir).lexically_normal().string();
  while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
  name_ = "bsim-" + (options.scene_path ? fs::path(*options.scene_path).stem().string() : std::string("break"));
  user_options_ = options.sbatch_options;
  FarmConf earlier;
  std::string ignored;
  if (read_conf(dir, earlier, ignored)) {
    const std::string queued = jobs_in_queue(squeue_, earlier);
    if (!queued.empty()) {
      error = "job " + queued + " of the earlier submission into " + dir +
              " is still queued or running (see `billiards-export " + dir +
              " --farm status`); wait for it, or cancel it with `scancel " + queued + "`";
      return false;
    }
  }
  return true;
}

bool SlurmSubmission::stage(const Shot& shot, const ExportOptions& options, const OutputStage& stage,
                            const StagedFrames& frames, std::string& error) {
  FarmConf conf;
  conf.fps = options.fps;
  conf.width = options.width;
  conf.height = options.height;
  conf.quality = options.quality;
  conf.duration = shot.movie.duration();  // the movie's, its replay included
  conf.frames = frames_ = frame_count(conf.duration, conf.fps);
  const SubmissionPlan plan = plan_submission(dir_, conf, options, stage, frames);
  missing_ = static_cast<int>(plan.missing.size());
  copies_ = plan.copies_to_make;
  chunk_ = options.chunk > 0 ? options.chunk : default_farm_chunk(conf.width, conf.height, conf.quality);
  chunks_ = farm_chunks(plan.missing, chunk_);
  // Each chunk traces only what changed against its own earlier frames, so a task has every frame
  // it reuses (and a chunk starting within a still camera's run renders its first frame whole).
  std::map<int, PartialPlan> partial;
  for (const auto& [first, last] : options.whole_frames ? std::vector<std::pair<int, int>>{} : chunks_) {
    std::vector<FrameJob> jobs;
    for (int k : plan.missing)
      if (k >= first && k <= last) jobs.push_back({k, 0});
    plan_partial_frames(shot.scene, frames, options, jobs);
    for (const FrameJob& job : jobs)
      if (job.reference >= 0) partial[job.frame] = {job.reference, job.rects};
  }
  if (!stage_farm_files(dir_, stage, conf, chunks_, plan.copies, partial, error)) return false;

  // Slurm checks the options (partition, account, time limit) now, before anything is submitted.
  std::vector<std::string> test = {sbatch_, "--test-only", "--job-name=" + name_ + "-movie"};
  test.insert(test.end(), user_options_.begin(), user_options_.end());
  test.push_back(stage.path(kMovieScript));
  std::string output;
  if (!run_captured(test, output, error)) {
    // `error` alone when sbatch could not be run at all (no temporary file, no process).
    if (!output.empty() || error.empty()) error = "sbatch would not take the jobs: " + output;
    return false;
  }
  return true;
}

int SlurmSubmission::submit(std::string& error) {
  auto sbatch = [&](const std::vector<std::string>& own, const std::string& script, std::string& id) {
    std::vector<std::string> argv = {sbatch_, "--parsable", "--chdir=" + dir_};
    argv.insert(argv.end(), own.begin(), own.end());
    argv.insert(argv.end(), user_options_.begin(), user_options_.end());
    argv.push_back(dir_ + "/" + script);
    std::string output;
    if (!run_captured(argv, output, error) || (id = job_id(output)).empty()) {
      error = "sbatch failed: " + (output.empty() ? error : output);
      return false;
    }
    return true;
  };
  FarmConf conf;
  if (!read_conf(dir_, conf, error)) return 1;
  std::string frames_job, movie_job;
  if (!chunks_.empty() && !sbatch({"--job-name=" + name_ + "-frames", "--array=0-" + std::to_string(chunks_.size() - 1),
                                   "--output=" + dir_ + "/" + kLogs + "/frames-%A_%a.log"},
                                  kTaskScript, frames_job))
    return 1;
  std::vector<std::string> movie_options = {"--job-name=" + name_ + "-movie",
                                            "--output=" + dir_ + "/" + kLogs + "/movie-%j.log"};
  // afterany, not afterok: the movie job runs even when a task failed, and names the missing frames.
  if (!frames_job.empty())
    movie_options.insert(movie_options.end(), {"--dependency=afterany:" + frames_job, "--kill-on-invalid-dep=no"});
  if (!sbatch(movie_options, kMovieScript, movie_job)) {
    if (!frames_job.empty() && !scancel_.empty()) {
      std::string ignored_output, ignored;
      run_captured({scancel_, frames_job}, ignored_output, ignored);  // no frames without the movie job
    }
    return 1;
  }
  conf.frames_job = frames_job;
  conf.movie_job = movie_job;
  if (!write_file_atomically(dir_ + "/" + kConf, conf_text(conf), error)) return 1;
  int largest = 0;
  for (const auto& c : chunks_) largest = std::max(largest, c.second - c.first + 1);
  if (!frames_job.empty())
    std::cout << "submitted job " << frames_job << ": " << chunks_.size() << (chunks_.size() == 1 ? " task" : " tasks")
              << " render " << missing_ << " of " << frames_ << " frames, up to " << largest << " a task"
              << (copies_ == 0 ? ""
                  : copies_ == 1
                      ? "; 1 more frame is the same as one of them and is copied"
                      : "; " + std::to_string(copies_) + " more frames are the same as some of them and are copied")
              << "\n";
  else
    std::cout << "all " << frames_ << " frames are rendered already\n";
  std::cout << "submitted job " << movie_job << ": checks every frame and writes " << dir_
            << "/movie.mp4 when the frames are done\n"
            << "follow them with: billiards-export " << dir_ << " --farm status\n";
  return 0;
}

}  // namespace bsim
