#include "render_jobs.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>

#include "child_process.h"
#include "develop.h"
#include "frame_captions.h"
#include "frame_lens.h"
#include "pov_frame.h"
#include "process_pool.h"
#include "progress_reporter.h"
#include "scene_file.h"

namespace bsim {

namespace {

/// POV-Ray's linear picture, while the frame is not yet whole (the PNG developed from it is written
/// whole, atomic_file.h).
/// Rectangle `part` of a partial frame has names of its own (-1: the whole frame).
std::string part_tag(int part) { return part < 0 ? "" : ".r" + std::to_string(part); }
std::string temp_hdr(int frame, int part = -1) { return "." + frame_name(frame) + part_tag(part) + ".tmp.hdr"; }
std::string log_name(int frame, int part = -1) { return "." + frame_name(frame) + part_tag(part) + ".log"; }

void remove_quietly(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

/// How long a POV-Ray run idles as it starts (its threads hand messages round in 50 ms waits, about
/// 0.65 s in all even for an empty scene): meanwhile a partial frame's rectangle may start (ProcessPool).
constexpr std::chrono::milliseconds kPovraySettle{700};

/// What POV-Ray 3.7 prints when it cannot start its render thread in time, as happens under load.
constexpr const char* kWorkerTimeout = "Timed out waiting for worker thread startup";

/// A frame (or rectangle `part` of a partial frame; -1: the whole frame) waiting to be rendered, and
/// which attempt at it this is (1 for the first).
struct Attempt {
  FrameJob job;
  int number = 1;
  int part = -1;
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
  return povray_arguments(settings, FrameJob{frame, 0, -1, {}}, -1);
}

std::vector<std::string> povray_arguments(const RenderSettings& settings, const FrameJob& job, int part) {
  // -D: no display (with one asked for and none there, POV-Ray draws ASCII art on stdout).
  // +WT1: one render thread a process; parallelism comes from running several processes.
  // +FH: linear light, unclipped, in a Radiance .hdr (the include sets assumed_gamma 1), which the
  // develop stage turns into the PNG (develop.h).
  std::vector<std::string> args = {settings.povray,
                                   "-D",
                                   "+FH",
                                   "+WT1",
                                   "+I" + frame_name(job.frame) + ".pov",
                                   "+O" + temp_hdr(job.frame, part),
                                   "+W" + std::to_string(settings.width),
                                   "+H" + std::to_string(settings.height)};
  const std::vector<std::string> quality = povray_quality_arguments(settings.quality);
  args.insert(args.end(), quality.begin(), quality.end());
  if (part >= 0) {
    // 1-based and inclusive. A start of 1 is left out: POV-Ray reads a value up to 1 as a share of the
    // picture, not a pixel.
    const PixelRect& r = job.rects[static_cast<std::size_t>(part)];
    if (r.x0 > 0) args.push_back("+SC" + std::to_string(r.x0 + 1));
    args.push_back("+EC" + std::to_string(r.x1));
    if (r.y0 > 0) args.push_back("+SR" + std::to_string(r.y0 + 1));
    args.push_back("+ER" + std::to_string(r.y1));
  }
  return args;
}

namespace {

/// A partial frame's traced rectangles, until they and its reference's picture are all there.
struct PartialFrame {
  FrameJob job;
  int parts_left = 0;
  std::vector<HdrImage> parts;
};

/// Lays rectangle `rect` of `part` over `picture` (the same size).
void lay_over(HdrImage& picture, const HdrImage& part, const PixelRect& rect) {
  for (int y = rect.y0; y < rect.y1; ++y) {
    const std::size_t at =
        (static_cast<std::size_t>(y) * static_cast<std::size_t>(picture.width) + static_cast<std::size_t>(rect.x0)) * 3;
    std::copy_n(part.rgb.begin() + static_cast<std::ptrdiff_t>(at), static_cast<std::size_t>(rect.x1 - rect.x0) * 3,
                picture.rgb.begin() + static_cast<std::ptrdiff_t>(at));
  }
}

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
        pool_(settings.processes, kPovraySettle),
        progress_("billiards-export", "rendering", total, total - static_cast<int>(jobs.size()),
                  progress_style(settings.quiet)),
        captions_(read_caption_lines(frames_dir)),
        lenses_(read_lens_file(frames_dir)) {
    if (!lenses_.frames.empty() && !parse_depth_scene(lenses_.scene, depth_scene_, depth_scene_error_))
      depth_scene_error_ = std::string(kLensName) + " does not describe the scene: " + depth_scene_error_;
    // The time left is reckoned from the pixels still to trace (and each POV-Ray run's start), so a
    // run of cheap partial frames after a whole one does not make it look short or long.
    double work = 0;
    for (const FrameJob& job : jobs) {
      work += work_of(job, -1);
      for (int part = 0; part < static_cast<int>(job.rects.size()); ++part) work += work_of(job, part);
    }
    progress_.count_work(work);
    for (const FrameJob& job : jobs) {
      if (job.reference < 0) {
        waiting_.push_back({job, 1, -1});
        continue;
      }
      ++dependents_[job.reference];
      const int parts = static_cast<int>(job.rects.size());
      partial_[job.frame] = {job, parts, std::vector<HdrImage>(job.rects.size())};
      for (int part = 0; part < parts; ++part) waiting_.push_back({job, 1, part});
    }
  }

  RunOutcome run() {
    compose_ready();  // frames with nothing to trace whose reference is already there (none yet)
    while (!waiting_.empty() || !pool_.empty()) {
      start_waiting();
      if (pool_.empty()) break;
      ProcessPool<Attempt>::Ended ended;
      const auto waited = pool_.wait(std::chrono::seconds(1), ended);
      if (!stop_stalled()) break;
      if (waited == ProcessPool<Attempt>::Wait::still_running) {
        progress_.tick();
        continue;
      }
      if (waited == ProcessPool<Attempt>::Wait::interrupted) {  // Ctrl-C
        stop_all();
        outcome_ = RunOutcome::interrupted;
        break;
      }
      watched_.erase(ended.pid);
      if (!attempt_ended(ended)) break;
    }
    if (outcome_ == RunOutcome::done && !partial_.empty() && !InterruptGuard::interrupted()) {
      const int frame = partial_.begin()->first;
      fail(frame, shown_frame(frame) + " could not be made: the frame it reuses was not rendered");
    }
    progress_.finish();
    if (outcome_ == RunOutcome::done && InterruptGuard::interrupted()) outcome_ = RunOutcome::interrupted;
    return outcome_;
  }

  /// The frame whose failure stopped the run (-1: none).
  int failed_frame() const { return failed_frame_; }

 private:
  /// What tracing the whole frame (part -1) or one rectangle costs, in pixels.
  double work_of(const FrameJob& job, int part) const {
    if (part < 0)
      return job.reference < 0 ? static_cast<double>(settings_.width) * settings_.height + kRegionStartPixels : 0.0;
    return static_cast<double>(job.rects[static_cast<std::size_t>(part)].area() + kRegionStartPixels);
  }

  void cleanup(int frame, int part = -1) {
    remove_quietly(dir_ + temp_hdr(frame, part));
    remove_quietly(dir_ + log_name(frame, part));
  }
  void stop_all() {
    pool_.stop_all([&](const Attempt& attempt) { cleanup(attempt.job.frame, attempt.part); });
  }
  void fail(int frame, const std::string& message, int part = -1) {
    if (outcome_ == RunOutcome::done) {
      error_ = message;
      failed_frame_ = frame;
      outcome_ = RunOutcome::failed;
      stop_all();  // no point finishing the others: the movie cannot be made
    }
    cleanup(frame, part);
  }

  /// After Ctrl-C: drops `attempt`'s files, stops every other run and marks the run interrupted
  /// (true); else false.
  bool stopped_by_user(const Attempt& attempt) {
    if (!InterruptGuard::interrupted()) return false;
    cleanup(attempt.job.frame, attempt.part);
    stop_all();
    outcome_ = RunOutcome::interrupted;
    return true;
  }

  /// Stops every POV-Ray run whose log has not grown for the stall limit (kStallSeconds), and tries
  /// its frame again or fails it. False when the run stops here (Ctrl-C).
  bool stop_stalled() {
    const auto now = std::chrono::steady_clock::now();
    std::vector<pid_t> stalled;
    pool_.for_each([&](pid_t pid, const Attempt& attempt) {
      std::error_code ec;
      const std::uintmax_t size = std::filesystem::file_size(dir_ + log_name(attempt.job.frame, attempt.part), ec);
      const auto [watch, fresh] = watched_.try_emplace(pid, Watch{size, now});
      if (!fresh && size != watch->second.log_size)
        watch->second = {size, now};
      else if (now - watch->second.since > stall_limit_)
        stalled.push_back(pid);
    });
    for (const pid_t pid : stalled) {
      watched_.erase(pid);
      const Attempt attempt = pool_.stop(pid);
      if (stopped_by_user(attempt)) return false;
      retry_or_fail(attempt, "printed nothing for " + std::to_string(stall_limit_.count()) + " s: it hangs");
    }
    return true;
  }

  /// The stall limit: kStallSeconds, or BSIM_POVRAY_STALL_SECONDS when that is a whole number of seconds.
  static std::chrono::seconds stall_limit() {
    const char* text = std::getenv("BSIM_POVRAY_STALL_SECONDS");
    if (text != nullptr) {
      char* end = nullptr;
      const long seconds = std::strtol(text, &end, 10);
      if (end != text && *end == '\0' && seconds > 0) return std::chrono::seconds(seconds);
    }
    return std::chrono::seconds(kStallSeconds);
  }

  /// Starts waiting frames while the pool has room and nothing has failed.
  void start_waiting() {
    // A rectangle of a partial frame is a short job: it may start while other runs still start up.
    while (outcome_ == RunOutcome::done && !waiting_.empty() && pool_.has_room(waiting_.front().part >= 0) &&
           !InterruptGuard::interrupted()) {
      const Attempt attempt = waiting_.front();
      waiting_.pop_front();
      const int frame = attempt.job.frame;
      if (!pool_.start(attempt, povray_arguments(settings_, attempt.job, attempt.part), frames_dir_,
                       dir_ + log_name(frame, attempt.part), error_)) {
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
    const std::string hdr = temp_hdr(frame, attempt.part);
    std::error_code ec;
    const auto size = std::filesystem::file_size(dir_ + hdr, ec);
    const bool picture_there = !ec;
    // POV-Ray's picture, read back whole: one it wrote but that cannot be read is a failed attempt.
    HdrImage image;
    std::string unreadable;
    if (ended.success && picture_there && size > 0 && !read_hdr(dir_ + hdr, image, unreadable)) {
      const std::string named = "cannot read " + dir_ + hdr + ": ";
      if (unreadable.rfind(named, 0) == 0) unreadable.erase(0, named.size());
      unreadable = "wrote a picture that cannot be read: " + unreadable;
    }
    if (ended.success && picture_there && size > 0 && unreadable.empty()) {
      rendered(attempt, std::move(image));
      return true;
    }
    // Ctrl-C reaches POV-Ray too, which dies of it: the user stopping the run, not a failure.
    if (stopped_by_user(attempt)) return false;
    const std::string log_text = read_text_file(dir_ + log_name(frame, attempt.part));
    if (const std::optional<PovParseError> parse = find_parse_error(log_text)) {
      parse_failed(attempt, *parse);
      return true;
    }
    const std::string reason =
        unreadable.empty() ? failure_reason(ended.success, ended.signal, picture_there, log_text) : unreadable;
    retry_or_fail(attempt, reason);
    return true;
  }

  /// A whole frame is developed at once (and kept while a later frame reuses it); a rectangle waits
  /// for the frame's other rectangles and its reference.
  void rendered(const Attempt& attempt, HdrImage image) {
    const int frame = attempt.job.frame;
    cleanup(frame, attempt.part);
    progress_.add_work(work_of(attempt.job, attempt.part));
    if (attempt.part < 0) {
      developed(frame, attempt.job.key, std::move(image));
    } else {
      PartialFrame& partial = partial_[frame];
      partial.parts[static_cast<std::size_t>(attempt.part)] = std::move(image);
      --partial.parts_left;
    }
    compose_ready();
  }

  /// Lays every partial frame whose rectangles and reference are all there over its reference, and
  /// develops it; each may be another's reference, so until none is left.
  void compose_ready() {
    for (bool progress = true; progress && outcome_ == RunOutcome::done;) {
      progress = false;
      for (auto it = partial_.begin(); it != partial_.end(); ++it) {
        PartialFrame& partial = it->second;
        const auto reference = kept_.find(partial.job.reference);
        if (partial.parts_left > 0 || reference == kept_.end()) continue;
        HdrImage picture = reference->second;
        if (--dependents_[partial.job.reference] == 0) kept_.erase(reference);
        for (std::size_t part = 0; part < partial.job.rects.size(); ++part)
          lay_over(picture, partial.parts[part], partial.job.rects[part]);
        const FrameJob job = partial.job;
        partial_.erase(it);
        developed(job.frame, job.key, std::move(picture));
        progress = true;
        break;
      }
    }
  }

  /// Develops a rendered frame into its PNG and records it in the frame store.
  void developed(int frame, std::uint64_t key, HdrImage image) {
    if (dependents_[frame] > 0) kept_[frame] = image;
    const std::string png = frame_name(frame) + ".png";
    std::string develop_error;
    FrameCaption caption;
    const auto line = captions_.find(frame);
    if (line != captions_.end() && !parse_caption(line->second, caption)) {
      fail(frame, shown_frame(frame) + " could not be developed: its line in " + kCaptionsName + " is not a caption");
      return;
    }
    FrameLens lens;
    const auto lens_line = lenses_.frames.find(frame);
    const bool has_lens = lens_line != lenses_.frames.end();
    if (has_lens && (!depth_scene_error_.empty() || !parse_frame_lens(lens_line->second, lens))) {
      fail(frame, shown_frame(frame) + " could not be developed: " +
                      (depth_scene_error_.empty() ? "its line in " + std::string(kLensName) + " is not a frame's lens"
                                                  : depth_scene_error_));
      return;
    }
    const DevelopLens develop_lens = has_lens ? DevelopLens{&lens, &depth_scene_} : DevelopLens{};
    if (!develop_to_png(std::move(image), dir_ + png, develop_error, line != captions_.end() ? &caption : nullptr,
                        develop_lens)) {
      fail(frame, shown_frame(frame) + " could not be developed: " + develop_error);
      return;
    }
    cache_.set(png, key);
    progress_.advance();
  }

  /// The scene itself is wrong: another attempt would fail the same way.
  void parse_failed(const Attempt& attempt, const PovParseError& parse) {
    const int frame = attempt.job.frame;
    if (outcome_ == RunOutcome::done) {
      std::string file = parse.file.empty() ? frame_name(frame) + ".pov" : parse.file;
      if (file.front() != '/')
        file = (settings_.shown_frames_dir.empty() ? frames_dir_ : settings_.shown_frames_dir) + "/" + file;
      const std::string line = parse.line > 0 ? ":" + std::to_string(parse.line) : "";
      progress_.finish();
      progress_.message(file + line + ": error: povray: " + parse.message);
    }
    fail(frame, shown_frame(frame) + " failed to render: POV-Ray could not parse it", attempt.part);
  }

  void retry_or_fail(const Attempt& attempt, const std::string& reason) {
    const int frame = attempt.job.frame;
    if (outcome_ == RunOutcome::done && attempt.number < kRenderAttempts) {
      cleanup(frame, attempt.part);
      progress_.message("billiards-export: warning: " + shown_frame(frame) + ": povray failed (" + reason +
                        "); retrying (attempt " + std::to_string(attempt.number + 1) + " of " +
                        std::to_string(kRenderAttempts) + ")");
      waiting_.push_front({attempt.job, attempt.number + 1, attempt.part});
      return;
    }
    fail(frame,
         shown_frame(frame) + " failed to render (" + std::to_string(attempt.number) +
             (attempt.number == 1 ? " attempt): " : " attempts): ") + reason,
         attempt.part);
  }

  const std::string& frames_dir_;
  const std::string dir_;
  const RenderSettings& settings_;
  FrameCache& cache_;
  std::string& error_;
  ProcessPool<Attempt> pool_;
  ProgressReporter progress_;
  std::deque<Attempt> waiting_;
  std::map<int, PartialFrame> partial_;        ///< partial frames not yet developed
  std::map<int, int> dependents_;              ///< frame -> partial frames still to be laid over it
  std::map<int, HdrImage> kept_;               ///< pictures (before developing) that partial frames still need
  const std::map<int, std::string> captions_;  ///< each captioned frame's line of captions.txt
  const LensFile lenses_;                      ///< lens.txt: the fixed scene and each frame's line
  DepthScene depth_scene_;                     ///< the fixed scene, read
  std::string depth_scene_error_;              ///< why it could not be read
  RunOutcome outcome_ = RunOutcome::done;
  int failed_frame_ = -1;
  /// Each running POV-Ray's log size and since when it has had it.
  struct Watch {
    std::uintmax_t log_size = 0;
    std::chrono::steady_clock::time_point since;
  };
  std::map<pid_t, Watch> watched_;
  const std::chrono::seconds stall_limit_ = stall_limit();
};

}  // namespace

RunOutcome render_frames(const std::string& frames_dir, const std::vector<FrameJob>& jobs, int total,
                         const RenderSettings& settings, FrameCache& cache, std::string& error, int* failed_frame) {
  FrameRendering rendering(frames_dir, jobs, total, settings, cache, error);
  const RunOutcome outcome = rendering.run();
  if (failed_frame) *failed_frame = rendering.failed_frame();
  return outcome;
}

}  // namespace bsim
