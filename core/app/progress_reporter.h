#pragma once
// Progress of a long run over frames (rendering, encoding, the animatic) on standard error. On a
// terminal one line rewrites itself; elsewhere (CI, a log file) a plain line of its own appears every
// tenth of the frames and at least every 30 s, and once at the end; --quiet silences both.
#include <chrono>
#include <functional>
#include <iostream>
#include <string>

namespace bsim {

enum class ProgressStyle {
  silent,    ///< nothing (--quiet)
  terminal,  ///< one line rewritten in place ("\r")
  plain,     ///< whole lines, few of them, for CI logs
};

/// silent when `quiet`; terminal when standard error is a terminal and the CI variable is unset;
/// plain otherwise.
ProgressStyle progress_style(bool quiet);

/// "0s", "59s", "1m12s", "1h02m03s": whole seconds, rounded.
std::string progress_time_text(double seconds);

class ProgressReporter {
 public:
  using Clock = std::function<std::chrono::steady_clock::time_point()>;

  static constexpr int kSteps = 10;  ///< a plain line each time another tenth of the frames is done
  static constexpr std::chrono::seconds kMaxSilence{30};         ///< and at least this often
  static constexpr std::chrono::milliseconds kRedrawEvery{100};  ///< a terminal line at most this often

  /// `program` and `label` start a plain line ("billiards-export: rendering: 3/10 frames ...");
  /// `already_done` frames of `total` need no work (they count as done but not towards the rate).
  ProgressReporter(std::string program, std::string label, int total, int already_done, ProgressStyle style,
                   std::ostream& out = std::cerr, Clock clock = std::chrono::steady_clock::now);
  /// Ends a terminal line; prints no plain line (finish() does).
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  /// One more frame done.
  void advance() { set_done(done_ + 1); }
  /// `done` frames of the total are done now.
  void set_done(int done);
  /// The time left is reckoned from work, not frames: `total` units of it (pixels, say) are to be
  /// done in this run, for the frames not already done. Frames still count what is shown.
  void count_work(double total) { work_total_ = total; }
  /// `work` more units done (with or without a frame finishing).
  void add_work(double work) { work_done_ += work; }
  /// Time passed with no news: a plain line if none came for kMaxSilence.
  void tick();
  /// The run is over: the last plain line (unless the one before said the same), or the end of the
  /// terminal line. Reports nothing more afterwards.
  void finish();
  /// A warning or error while the step runs: printed on a line of its own, in place of a terminal
  /// line (which the next update draws again below it).
  void message(const std::string& line);

  int done() const { return done_; }

 private:
  void update();
  void print_plain(std::chrono::steady_clock::time_point now);
  void draw_terminal(std::chrono::steady_clock::time_point now);
  int step(int done) const;
  /// s left, from the work (or the frames) done since the start in `elapsed` s; negative: unknown.
  double time_left(double elapsed) const;

  std::string program_;
  std::string label_;
  int total_ = 0;
  int done_ = 0;
  int done_at_start_ = 0;
  double work_total_ = 0;  ///< 0: the time left is reckoned from frames
  double work_done_ = 0;
  ProgressStyle style_ = ProgressStyle::silent;
  std::ostream& out_;
  Clock clock_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_line_;  ///< when the last plain line was printed (or the start)
  int last_step_ = 0;                                ///< step() of the frames done at the last plain line
  int printed_done_ = -1;                            ///< frames done at the last plain line, -1 before one
  bool drawn_ = false;                               ///< a terminal line is on the screen
  int drawn_done_ = -1;                              ///< frames done on the terminal line
  std::chrono::steady_clock::time_point last_draw_;  ///< when the terminal line was drawn
};

}  // namespace bsim
