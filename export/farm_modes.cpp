// The job-side modes of a farm run: `billiards-export DIR --farm status|render|assemble`, run by the
// user (status) and by the jobs on the cluster's nodes (render, assemble).
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>

#include "child_process.h"
#include "farm_files.h"
#include "farm_slurm.h"
#include "ffmpeg_assemble.h"
#include "frame_cache.h"
#include "frames.h"
#include "movie_export.h"
#include "pov_frame.h"
#include "render_jobs.h"
#include "slurm_client.h"

namespace fs = std::filesystem;

namespace bsim {

namespace {

using namespace farm;

int farm_status(const std::string& dir, const FarmConf& conf) {
  std::string error;
  const int missing = static_cast<int>(missing_frames(dir, conf.frames, read_copies(dir)).size());
  std::error_code ec;
  const bool movie = fs::is_regular_file(dir + "/movie.mp4", ec);
  std::cout << dir << ": " << conf.frames - missing << " of " << conf.frames << " frames rendered (" << conf.width
            << "x" << conf.height << ", " << quality_name(conf.quality) << ", " << conf.fps << " fps); movie.mp4 "
            << (movie ? "is made" : "not made yet") << "\n";
  if (!conf.frames_job.empty() || !conf.movie_job.empty())
    std::cout << "jobs: " << (conf.frames_job.empty() ? "" : conf.frames_job + " (frames) ") << conf.movie_job
              << " (movie); logs in " << dir << "/" << kLogs << "\n";
  const std::string squeue = find_program("squeue");
  const std::string queued = jobs_in_queue(squeue, conf);
  if (!queued.empty()) {
    std::string ids = conf.frames_job + (conf.frames_job.empty() ? "" : ",") + conf.movie_job, output;
    run_captured({squeue, "--jobs=" + ids, "--format=%.20i %.10T %.10M %R"}, output, error);
    std::cout << output << "\n";
  } else if (!movie) {
    std::cout << (squeue.empty() ? "squeue is not on PATH: the queue is not shown\n"
                                 : "no job of this run is queued\n");
    if (missing > 0 && (squeue.empty() || !conf.movie_job.empty()))
      std::cout << "run the same `billiards-export SCENE --farm slurm -o " << dir
                << "` command again to render the missing frames\n";
  }
  return 0;
}

/// The frames FIRST to LAST of a task that are still to render (not copies), with the plan of those
/// traced only where they changed against an earlier one of them (farm/partial.txt); a frame whose
/// reference is not rendered here is traced whole.
std::vector<FrameJob> task_jobs(const std::string& dir, const FrameCopies& copies, int first, int last) {
  const std::map<int, PartialPlan> partial = read_partial(dir);
  std::vector<FrameJob> jobs;
  std::set<int> here;
  for (int k = first; k <= last; ++k) {
    if (copies.is_copy(k) || picture_there(dir, k)) continue;  // a copy: the task of its frame copies it
    FrameJob job{k, 0};
    const auto plan = partial.find(k);
    if (plan != partial.end() && here.count(plan->second.reference)) {
      job.reference = plan->second.reference;
      job.rects = plan->second.rects;
    }
    jobs.push_back(job);
    here.insert(k);
  }
  return jobs;
}

int farm_render(const ExportOptions& options, const std::string& dir, const FarmConf& conf) {
  std::string error;
  RenderSettings render{find_program("povray"), conf.width, conf.height, conf.quality, 1, dir + "/frames", true};
  if (render.povray.empty()) {
    char host[256] = "this node";
    ::gethostname(host, sizeof host - 1);
    std::cerr << "billiards-export: error: povray is not on PATH on " << host
              << ": load its module (or set PATH) before submitting, since sbatch passes your environment to "
                 "the jobs\n";
    return 1;
  }
  InterruptGuard guard;  // scancel's SIGTERM stops POV-Ray and removes its half-written picture
  FrameCache no_store("", dir + "/frames");
  const FrameCopies copies = read_copies(dir);
  const int last = options.last_frame < 0 ? conf.frames - 1 : std::min(options.last_frame, conf.frames - 1);
  // The frames to render, in order; one traced only where it changed reuses an earlier one of them.
  const std::vector<FrameJob> jobs = task_jobs(dir, copies, options.first_frame, last);
  std::vector<int> failed;
  int failed_frame = -1;
  if (!jobs.empty() &&
      render_frames(dir + "/frames", jobs, static_cast<int>(jobs.size()), render, no_store, error, &failed_frame) !=
          RunOutcome::done &&
      !InterruptGuard::interrupted()) {
    std::cerr << "billiards-export: error: " << error << "\n";
    failed.push_back(failed_frame);
    // The others of the chunk are still worth rendering: each missing one whole, on its own.
    for (const FrameJob& job : jobs) {
      if (job.frame == failed_frame || picture_there(dir, job.frame) || InterruptGuard::interrupted()) continue;
      error.clear();
      if (render_frames(dir + "/frames", {{job.frame, 0}}, 1, render, no_store, error) != RunOutcome::done &&
          !InterruptGuard::interrupted()) {
        std::cerr << "billiards-export: error: " << error << "\n";
        failed.push_back(job.frame);
      }
    }
  }
  int rendered = 0;
  for (const FrameJob& job : jobs) {
    if (!picture_there(dir, job.frame)) continue;
    ++rendered;
    std::cerr << "billiards-export: frame " << job.frame << " rendered\n";
  }
  // Copies are the same picture: the movie job would copy them too, but --farm status counts them
  // done from now on.
  for (int k = options.first_frame; k <= last && !InterruptGuard::interrupted(); ++k) {
    if (copies.is_copy(k) || !picture_there(dir, k)) continue;
    if (!copy_picture(dir + "/frames", copies, k))
      std::cerr << "billiards-export: warning: cannot copy frame " << k << " to its copies; the movie job will\n";
  }
  if (InterruptGuard::interrupted()) {
    std::cerr << "billiards-export: error: interrupted\n";
    guard.finish();
    return 1;
  }
  std::cerr << "billiards-export: frames " << options.first_frame << "-" << last << ": " << rendered << " rendered, "
            << failed.size() << " failed\n";
  return failed.empty() ? 0 : 1;
}

int farm_assemble(const ExportOptions& options, const std::string& dir, const FarmConf& conf) {
  std::string error;
  // Frames the same as an earlier one are that one's picture, copied.
  const FrameCopies copies = read_copies(dir);
  for (const auto& entry : copies.copies) {
    if (picture_there(dir, entry.first) && !copy_picture(dir + "/frames", copies, entry.first)) {
      std::cerr << "billiards-export: error: cannot copy " << shown_picture(entry.first) << " to its copies\n";
      return 1;
    }
  }
  const std::vector<int> missing = missing_frames(dir, conf.frames, copies);
  if (!missing.empty()) {
    // The frames to render are named; their copies are only counted.
    constexpr std::size_t kNamed = 10;
    std::size_t named = 0;
    for (std::size_t i = 0; i < missing.size() && named < kNamed; ++i) {
      if (copies.is_copy(missing[i])) continue;
      std::cerr << "billiards-export: error: " << shown_picture(missing[i]) << " was not rendered; see its task's log, "
                << task_log(dir, conf, missing[i]) << "\n";
      ++named;
    }
    if (missing.size() > named)
      std::cerr << "billiards-export: error: and " << missing.size() - named << " more frames\n";
    std::cerr << "billiards-export: error: no movie: " << missing.size() << " of " << conf.frames
              << " frames are missing; the frames done are kept, and submitting the same command again renders "
                 "only the missing ones\n";
    return 1;
  }
  const std::string ffmpeg = find_program("ffmpeg");
  if (ffmpeg.empty()) {
    std::cerr << "billiards-export: error: ffmpeg is not on PATH: load its module (or set PATH) before "
                 "submitting, since sbatch passes your environment to the jobs\n";
    return 1;
  }
  InterruptGuard guard;
  // The one encoding a local run does too (ffmpeg_assemble.h): the same movie, byte for byte.
  const MovieSettings movie{ffmpeg, conf.fps, conf.duration, options.quiet};
  if (assemble_movie(dir, movie, error) != RunOutcome::done) {
    std::cerr << "billiards-export: error: " << (InterruptGuard::interrupted() ? "interrupted" : error) << "\n";
    guard.finish();
    return 1;
  }
  // Kept in the frame store too, as a local run keeps its pictures (best effort).
  ExportOptions rendered;
  rendered.width = conf.width;
  rendered.height = conf.height;
  rendered.quality = conf.quality;
  const FrameCache store(default_frame_cache_dir(), dir + "/frames");
  const std::vector<std::uint64_t> keys = frame_store_keys(dir + "/frames", conf.frames, rendered);
  for (int k = 0; k < conf.frames; ++k) store.set(frame_name(k) + ".png", keys[k]);
  store.trim();
  std::cerr << "wrote " << dir << "/movie.mp4 (" << conf.frames << " frames)\n";
  return 0;
}

}  // namespace

int run_farm_command(const ExportOptions& options) {
  const std::string dir = options.scene_path.value_or(".");
  // Every mode on a submitted directory starts from its farm.conf.
  FarmConf conf;
  std::string error;
  if (!read_conf(dir, conf, error)) {
    std::cerr << "billiards-export: error: " << error << "\n";
    return 1;
  }
  switch (options.farm) {
    case FarmMode::status: return farm_status(dir, conf);
    case FarmMode::render: return farm_render(options, dir, conf);
    case FarmMode::assemble: return farm_assemble(options, dir, conf);
    case FarmMode::none:
    case FarmMode::slurm: break;
  }
  return 2;
}

}  // namespace bsim
