#include "render_jobs.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>

#include "child_process.h"
#include "develop.h"
#include "pov_frame.h"
#include "progress_reporter.h"
#include "scene_file.h"

namespace bsim {

namespace {

/// POV-Ray's linear picture, while the frame is not yet whole (the PNG developed from it is written
/// whole, atomic_file.h).
std::string temp_hdr(int frame) { return "." + frame_name(frame) + ".tmp.hdr"; }
std::string log_name(int frame) { return "." + frame_name(frame) + ".log"; }

void remove_quietly(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

/// What POV-Ray 3.7 prints when it cannot start its render thread in time, as happens under load.
constexpr const char* kWorkerTimeout = "Timed out waiting for worker thread startup";

/// A frame waiting to be rendered, and which attempt at it this is (1 for the first).
struct Attempt {
  FrameJob job;
  int number = 1;
};

/// The frame's file as the messages name it, relative to the output directory.
std::string shown_frame(int frame) {
  return "frame " + std::to_string(frame) + " (frames/" + frame_name(frame) + ".pov)";
}

/// Why a failed attempt that is not a parse error failed, in a few words.
std::string failure_reason(bool exited_zero, int signal, bool picture_there, const std::string& log_text) {
  if (signal != 0) return "killed by signal " + std::to_string(signal) + ": " + strsignal(signal);
  if (exited_zero) return picture_there ? "wrote an empty picture" : "wrote no picture";
  if (log_text.find(kWorkerTimeout) != std::string::npos) return kWorkerTimeout;
  return error_from_log(log_text);
}

}  // namespace

std::optional<PovParseError> find_parse_error(const std::string& log_text) {
  // POV-Ray wraps long messages at 80 columns, breaking before a space: a line that starts with
  // one continues the message above.
  std::vector<std::string> messages;
  std::stringstream in(log_text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!messages.empty() && !line.empty() && line.front() == ' ')
      messages.back() += line;
    else
      messages.push_back(line);
  }
  static const std::regex located(R"(File '([^']*)' line ([0-9]+):\s*$)");
  const std::string marker = "Parse Error:", warning = "Possible ";
  for (const std::string& message : messages) {
    const std::size_t at = message.find(marker);
    if (at == std::string::npos) continue;
    if (at >= warning.size() && message.compare(at - warning.size(), warning.size(), warning) == 0) continue;
    PovParseError found;
    found.message = message.substr(at);
    std::smatch m;
    const std::string before = message.substr(0, at);
    if (std::regex_search(before, m, located) && m[2].length() <= 9) {
      found.file = m[1];
      found.line = std::stoi(m[2]);
    }
    return found;
  }
  return std::nullopt;
}

std::vector<std::string> povray_quality_arguments(Quality quality) {
  // Both trace reflections (+Q9). Final: adaptive antialiasing (+AM2) two levels deep, the same
  // edges as the default method on the balls' stripes and the rails at about a tenth less time.
  if (quality == Quality::final) return {"+Q9", "+A0.3", "+AM2", "+R2"};
  return {"+Q9", "-A"};
}

std::vector<std::string> povray_arguments(const RenderSettings& settings, int frame) {
  // -D: no display (with one asked for and none there, POV-Ray draws ASCII art on stdout).
  // +WT1: one render thread a process; parallelism comes from running several processes.
  // +FH: linear light, unclipped, in a Radiance .hdr (the include sets assumed_gamma 1), which the
  // develop stage turns into the PNG (develop.h).
  std::vector<std::string> args = {settings.povray,
                                   "-D",
                                   "+FH",
                                   "+WT1",
                                   "+I" + frame_name(frame) + ".pov",
                                   "+O" + temp_hdr(frame),
                                   "+W" + std::to_string(settings.width),
                                   "+H" + std::to_string(settings.height)};
  const std::vector<std::string> quality = povray_quality_arguments(settings.quality);
  args.insert(args.end(), quality.begin(), quality.end());
  return args;
}

RunOutcome render_frames(const std::string& frames_dir, const std::vector<FrameJob>& jobs, int total,
                         const RenderSettings& settings, FrameCache& cache, std::string& error) {
  ProgressReporter progress("billiards-export", "rendering", total, total - static_cast<int>(jobs.size()),
                            progress_style(settings.quiet));
  std::deque<Attempt> waiting;
  for (const FrameJob& job : jobs) waiting.push_back({job, 1});
  std::map<pid_t, Attempt> running;
  RunOutcome outcome = RunOutcome::done;
  const std::string dir = frames_dir + "/";

  auto cleanup = [&](int frame) {
    remove_quietly(dir + temp_hdr(frame));
    remove_quietly(dir + log_name(frame));
  };
  auto stop_all = [&] {
    for (const auto& [pid, attempt] : running) {
      stop_process(pid);
      cleanup(attempt.job.frame);
    }
    running.clear();
  };
  auto fail = [&](int frame, const std::string& message) {
    if (outcome == RunOutcome::done) {
      error = message;
      outcome = RunOutcome::failed;
      stop_all();  // no point finishing the others: the movie cannot be made
    }
    cleanup(frame);
  };

  while (!waiting.empty() || !running.empty()) {
    while (outcome == RunOutcome::done && !waiting.empty() &&
           static_cast<int>(running.size()) < std::max(settings.processes, 1) && !InterruptGuard::interrupted()) {
      const Attempt attempt = waiting.front();
      waiting.pop_front();
      const pid_t pid = start_process(povray_arguments(settings, attempt.job.frame), frames_dir,
                                      dir + log_name(attempt.job.frame), error);
      if (pid < 0) {
        outcome = RunOutcome::failed;
        break;
      }
      running[pid] = attempt;
    }
    if (running.empty()) break;
    bool success = false;
    int signal = 0;
    const pid_t pid = wait_any(success, std::chrono::seconds(1), &signal);
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
    const Attempt attempt = it->second;
    running.erase(it);
    const int frame = attempt.job.frame;
    const std::string png = frame_name(frame) + ".png";
    std::error_code ec;
    const auto size = std::filesystem::file_size(dir + temp_hdr(frame), ec);
    const bool picture_there = !ec;
    // POV-Ray's picture, read back whole: one it wrote but that cannot be read is a failed attempt.
    HdrImage image;
    std::string unreadable, develop_error;
    if (success && picture_there && size > 0 && !read_hdr(dir + temp_hdr(frame), image, unreadable)) {
      const std::string named = "cannot read " + dir + temp_hdr(frame) + ": ";
      if (unreadable.rfind(named, 0) == 0) unreadable.erase(0, named.size());
      unreadable = "wrote a picture that cannot be read: " + unreadable;
    }
    if (success && picture_there && size > 0 && unreadable.empty()) {
      if (!develop_to_png(std::move(image), dir + png, develop_error)) {
        fail(frame, shown_frame(frame) + " could not be developed: " + develop_error);
        continue;
      }
      cleanup(frame);
      cache.set(png, attempt.job.key);
      progress.advance();
      continue;
    }

    if (InterruptGuard::interrupted()) {
      // Ctrl-C reaches POV-Ray too, which dies of it: the user stopping the run, not a failure.
      cleanup(frame);
      stop_all();
      outcome = RunOutcome::interrupted;
      break;
    }
    const std::string log_text = read_text_file(dir + log_name(frame));
    if (const std::optional<PovParseError> parse = find_parse_error(log_text)) {
      // The scene itself is wrong: another attempt would fail the same way.
      if (outcome == RunOutcome::done) {
        std::string file = parse->file.empty() ? frame_name(frame) + ".pov" : parse->file;
        if (file.front() != '/')
          file = (settings.shown_frames_dir.empty() ? frames_dir : settings.shown_frames_dir) + "/" + file;
        const std::string line = parse->line > 0 ? ":" + std::to_string(parse->line) : "";
        progress.finish();
        progress.message(file + line + ": error: povray: " + parse->message);
      }
      fail(frame, shown_frame(frame) + " failed to render: POV-Ray could not parse it");
      continue;
    }
    const std::string reason =
        unreadable.empty() ? failure_reason(success, signal, picture_there, log_text) : unreadable;
    if (outcome == RunOutcome::done && attempt.number < kRenderAttempts) {
      cleanup(frame);
      progress.message("billiards-export: warning: " + shown_frame(frame) + ": povray failed (" + reason +
                       "); retrying (attempt " + std::to_string(attempt.number + 1) + " of " +
                       std::to_string(kRenderAttempts) + ")");
      waiting.push_front({attempt.job, attempt.number + 1});
      continue;
    }
    fail(frame, shown_frame(frame) + " failed to render (" + std::to_string(attempt.number) +
                    (attempt.number == 1 ? " attempt): " : " attempts): ") + reason);
  }
  progress.finish();
  if (outcome == RunOutcome::done && InterruptGuard::interrupted()) outcome = RunOutcome::interrupted;
  return outcome;
}

}  // namespace bsim
