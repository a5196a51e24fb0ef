#include "render_jobs.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "child_process.h"
#include "pov_frame.h"
#include "progress_reporter.h"

namespace bsim {

namespace {

std::string temp_png(int frame) { return "." + frame_name(frame) + ".tmp.png"; }
std::string log_name(int frame) { return "." + frame_name(frame) + ".log"; }

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void remove_quietly(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

}  // namespace

std::vector<std::string> povray_arguments(const RenderSettings& settings, int frame) {
  // -D: no display (with one asked for and none there, POV-Ray draws ASCII art on stdout).
  // +WT1: one render thread a process; parallelism comes from running several processes.
  std::vector<std::string> args = {settings.povray,
                                   "-D",
                                   "+FN",
                                   "+WT1",
                                   "+I" + frame_name(frame) + ".pov",
                                   "+O" + temp_png(frame),
                                   "+W" + std::to_string(settings.width),
                                   "+H" + std::to_string(settings.height)};
  if (settings.quality == Quality::final) {
    args.insert(args.end(), {"+Q9", "+A0.3"});
  } else {
    args.insert(args.end(), {"+Q9", "-A"});
  }
  return args;
}

RunOutcome render_frames(const std::string& frames_dir, const std::vector<FrameJob>& jobs, int total,
                         const RenderSettings& settings, FrameCache& cache, std::string& error) {
  ProgressReporter progress("billiards-export", "rendering", total, total - static_cast<int>(jobs.size()),
                            progress_style(settings.quiet));
  std::map<pid_t, FrameJob> running;
  std::size_t next = 0;
  RunOutcome outcome = RunOutcome::done;

  auto cleanup = [&](int frame) {
    remove_quietly(frames_dir + "/" + temp_png(frame));
    remove_quietly(frames_dir + "/" + log_name(frame));
  };
  auto stop_all = [&] {
    for (const auto& [pid, job] : running) {
      stop_process(pid);
      cleanup(job.frame);
    }
    running.clear();
  };

  while (next < jobs.size() || !running.empty()) {
    while (outcome == RunOutcome::done && next < jobs.size() &&
           static_cast<int>(running.size()) < std::max(settings.processes, 1) && !InterruptGuard::interrupted()) {
      const FrameJob& job = jobs[next++];
      const pid_t pid = start_process(povray_arguments(settings, job.frame), frames_dir,
                                      frames_dir + "/" + log_name(job.frame), error);
      if (pid < 0) {
        outcome = RunOutcome::failed;
        break;
      }
      running[pid] = job;
    }
    if (running.empty()) break;
    bool success = false;
    const pid_t pid = wait_any(success, std::chrono::seconds(1));
    if (pid == 0) {  // still rendering
      progress.tick();
      continue;
    }
    if (pid < 0) {  // Ctrl-C
      stop_all();
      outcome = RunOutcome::interrupted;
      break;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const FrameJob job = it->second;
    running.erase(it);
    const std::string dir = frames_dir + "/";
    const std::string png = frame_name(job.frame) + ".png";
    std::error_code ec;
    if (success && std::filesystem::exists(dir + temp_png(job.frame)))
      std::filesystem::rename(dir + temp_png(job.frame), dir + png, ec);
    if (!success || ec || !std::filesystem::exists(dir + png)) {
      if (outcome == RunOutcome::done) {
        const std::string said =
            success ? "POV-Ray wrote no picture" : error_from_log(read_text(dir + log_name(job.frame)));
        error = "frame " + std::to_string(job.frame) + " (" + frame_name(job.frame) + ".pov) failed to render: " + said;
        outcome = RunOutcome::failed;
        stop_all();  // no point finishing the others: the movie cannot be made
      }
      cleanup(job.frame);
      continue;
    }
    cleanup(job.frame);
    cache.set(png, job.key);
    cache.save();
    progress.advance();
  }
  progress.finish();
  if (outcome == RunOutcome::done && InterruptGuard::interrupted()) outcome = RunOutcome::interrupted;
  return outcome;
}

}  // namespace bsim
