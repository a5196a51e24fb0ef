#include "render_jobs.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <regex>
#include <sstream>

#include "child_process.h"
#include "develop.h"
#include "pov_frame.h"
#include "process_pool.h"
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

namespace {

/// One call of render_frames: the frames waiting, the POV-Ray processes rendering, and what came of it.
class FrameRendering {
 public:
  FrameRendering(const std::string& frames_dir, const std::vector<FrameJob>& jobs, int total,
                 const RenderSettings& settings, FrameCache& cache, std::string& error)
      : frames_dir_(frames_dir),
        dir_(frames_dir + "/"),
        settings_(settings),
        cache_(cache),
        error_(error),
        pool_(settings.processes),
        progress_("billiards-export", "rendering", total, total - static_cast<int>(jobs.size()),
                  progress_style(settings.quiet)) {
    for (const FrameJob& job : jobs) waiting_.push_back({job, 1});
  }

  RunOutcome run() {
    while (!waiting_.empty() || !pool_.empty()) {
      start_waiting();
      if (pool_.empty()) break;
      ProcessPool<Attempt>::Ended ended;
      const auto waited = pool_.wait(std::chrono::seconds(1), ended);
      if (waited == ProcessPool<Attempt>::Wait::still_running) {
        progress_.tick();
        continue;
      }
      if (waited == ProcessPool<Attempt>::Wait::interrupted) {  // Ctrl-C
        stop_all();
        outcome_ = RunOutcome::interrupted;
        break;
      }
      if (!attempt_ended(ended)) break;
    }
    progress_.finish();
    if (outcome_ == RunOutcome::done && InterruptGuard::interrupted()) outcome_ = RunOutcome::interrupted;
    return outcome_;
  }

 private:
  void cleanup(int frame) {
    remove_quietly(dir_ + temp_hdr(frame));
    remove_quietly(dir_ + log_name(frame));
  }
  void stop_all() {
    pool_.stop_all([&](const Attempt& attempt) { cleanup(attempt.job.frame); });
  }
  void fail(int frame, const std::string& message) {
    if (outcome_ == RunOutcome::done) {
      error_ = message;
      outcome_ = RunOutcome::failed;
      stop_all();  // no point finishing the others: the movie cannot be made
    }
    cleanup(frame);
  }

  /// Starts waiting frames while the pool has room and nothing has failed.
  void start_waiting() {
    while (outcome_ == RunOutcome::done && !waiting_.empty() && pool_.has_room() && !InterruptGuard::interrupted()) {
      const Attempt attempt = waiting_.front();
      waiting_.pop_front();
      const int frame = attempt.job.frame;
      if (!pool_.start(attempt, povray_arguments(settings_, frame), frames_dir_, dir_ + log_name(frame), error_)) {
        outcome_ = RunOutcome::failed;
        break;
      }
    }
  }

  /// Handles an attempt whose POV-Ray ended: develops its picture, or retries or fails it. False when
  /// the run stops here (Ctrl-C).
  bool attempt_ended(const ProcessPool<Attempt>::Ended& ended) {
    const Attempt& attempt = ended.job;
    const int frame = attempt.job.frame;
    std::error_code ec;
    const auto size = std::filesystem::file_size(dir_ + temp_hdr(frame), ec);
    const bool picture_there = !ec;
    // POV-Ray's picture, read back whole: one it wrote but that cannot be read is a failed attempt.
    HdrImage image;
    std::string unreadable;
    if (ended.success && picture_there && size > 0 && !read_hdr(dir_ + temp_hdr(frame), image, unreadable)) {
      const std::string named = "cannot read " + dir_ + temp_hdr(frame) + ": ";
      if (unreadable.rfind(named, 0) == 0) unreadable.erase(0, named.size());
      unreadable = "wrote a picture that cannot be read: " + unreadable;
    }
    if (ended.success && picture_there && size > 0 && unreadable.empty()) {
      developed(attempt, std::move(image));
      return true;
    }
    if (InterruptGuard::interrupted()) {
      // Ctrl-C reaches POV-Ray too, which dies of it: the user stopping the run, not a failure.
      cleanup(frame);
      stop_all();
      outcome_ = RunOutcome::interrupted;
      return false;
    }
    const std::string log_text = read_text_file(dir_ + log_name(frame));
    if (const std::optional<PovParseError> parse = find_parse_error(log_text)) {
      parse_failed(frame, *parse);
      return true;
    }
    const std::string reason =
        unreadable.empty() ? failure_reason(ended.success, ended.signal, picture_there, log_text) : unreadable;
    retry_or_fail(attempt, reason);
    return true;
  }

  /// Develops a rendered frame into its PNG and records it in the frame store.
  void developed(const Attempt& attempt, HdrImage image) {
    const int frame = attempt.job.frame;
    const std::string png = frame_name(frame) + ".png";
    std::string develop_error;
    if (!develop_to_png(std::move(image), dir_ + png, develop_error)) {
      fail(frame, shown_frame(frame) + " could not be developed: " + develop_error);
      return;
    }
    cleanup(frame);
    cache_.set(png, attempt.job.key);
    progress_.advance();
  }

  /// The scene itself is wrong: another attempt would fail the same way.
  void parse_failed(int frame, const PovParseError& parse) {
    if (outcome_ == RunOutcome::done) {
      std::string file = parse.file.empty() ? frame_name(frame) + ".pov" : parse.file;
      if (file.front() != '/')
        file = (settings_.shown_frames_dir.empty() ? frames_dir_ : settings_.shown_frames_dir) + "/" + file;
      const std::string line = parse.line > 0 ? ":" + std::to_string(parse.line) : "";
      progress_.finish();
      progress_.message(file + line + ": error: povray: " + parse.message);
    }
    fail(frame, shown_frame(frame) + " failed to render: POV-Ray could not parse it");
  }

  void retry_or_fail(const Attempt& attempt, const std::string& reason) {
    const int frame = attempt.job.frame;
    if (outcome_ == RunOutcome::done && attempt.number < kRenderAttempts) {
      cleanup(frame);
      progress_.message("billiards-export: warning: " + shown_frame(frame) + ": povray failed (" + reason +
                        "); retrying (attempt " + std::to_string(attempt.number + 1) + " of " +
                        std::to_string(kRenderAttempts) + ")");
      waiting_.push_front({attempt.job, attempt.number + 1});
      return;
    }
    fail(frame, shown_frame(frame) + " failed to render (" + std::to_string(attempt.number) +
                    (attempt.number == 1 ? " attempt): " : " attempts): ") + reason);
  }

  const std::string& frames_dir_;
  const std::string dir_;
  const RenderSettings& settings_;
  FrameCache& cache_;
  std::string& error_;
  ProcessPool<Attempt> pool_;
  ProgressReporter progress_;
  std::deque<Attempt> waiting_;
  RunOutcome outcome_ = RunOutcome::done;
};

}  // namespace

RunOutcome render_frames(const std::string& frames_dir, const std::vector<FrameJob>& jobs, int total,
                         const RenderSettings& settings, FrameCache& cache, std::string& error) {
  return FrameRendering(frames_dir, jobs, total, settings, cache, error).run();
}

}  // namespace bsim
