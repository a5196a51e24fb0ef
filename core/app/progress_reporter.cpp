#include "progress_reporter.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace bsim {

namespace {

/// "m:ss" or "h:mm:ss", the terminal line's time left.
std::string clock_text(double seconds) {
  const long s = std::lround(seconds);
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

double seconds_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
  return std::max(0.0, std::chrono::duration<double>(to - from).count());
}

}  // namespace

ProgressStyle progress_style(bool quiet) {
  if (quiet) return ProgressStyle::silent;
  return isatty(STDERR_FILENO) && std::getenv("CI") == nullptr ? ProgressStyle::terminal : ProgressStyle::plain;
}

std::string progress_time_text(double seconds) {
  const long s = std::isfinite(seconds) && seconds > 0 ? std::lround(seconds) : 0;
  char text[48];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ldh%02ldm%02lds", s / 3600, s / 60 % 60, s % 60);
  else if (s >= 60)
    std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%lds", s);
  return text;
}

ProgressReporter::ProgressReporter(std::string program, std::string label, int total, int already_done,
                                   ProgressStyle style, std::ostream& out, Clock clock)
    : program_(std::move(program)),
      label_(std::move(label)),
      total_(std::max(total, 0)),
      done_(std::clamp(already_done, 0, total_)),
      done_at_start_(done_),
      style_(style),
      out_(out),
      clock_(std::move(clock)),
      start_(clock_()),
      last_line_(start_),
      last_step_(step(done_)) {
  if (style_ == ProgressStyle::terminal) draw_terminal(start_);
}

ProgressReporter::~ProgressReporter() {
  if (drawn_) {
    out_ << '\n';
    out_.flush();
  }
}

int ProgressReporter::step(int done) const {
  return total_ > 0 ? static_cast<int>(static_cast<long long>(done) * kSteps / total_) : kSteps;
}

void ProgressReporter::set_done(int done) {
  done_ = std::clamp(done, 0, total_);
  update();
}

void ProgressReporter::tick() { update(); }

void ProgressReporter::update() {
  if (style_ == ProgressStyle::silent) return;
  const auto now = clock_();
  if (style_ == ProgressStyle::terminal) {
    if (now - last_draw_ >= kRedrawEvery || done_ == total_) draw_terminal(now);
    return;
  }
  if (step(done_) > last_step_ || now - last_line_ >= kMaxSilence) print_plain(now);
}

double ProgressReporter::time_left(double elapsed) const {
  if (done_ >= total_) return 0;
  if (elapsed <= 0) return -1;
  if (work_total_ > 0) return work_done_ > 0 ? std::max(work_total_ - work_done_, 0.0) * elapsed / work_done_ : -1;
  const int done_here = done_ - done_at_start_;
  return done_here > 0 ? (total_ - done_) * elapsed / done_here : -1;
}

void ProgressReporter::print_plain(std::chrono::steady_clock::time_point now) {
  const double elapsed = seconds_between(start_, now);
  const long percent = total_ > 0 ? static_cast<long>(static_cast<long long>(done_) * 100 / total_) : 100;
  const double left = time_left(elapsed);
  const std::string eta = left < 0 ? "unknown" : progress_time_text(left);
  out_ << program_ << ": " << label_ << ": " << done_ << "/" << total_ << " frames (" << percent << "%), "
       << progress_time_text(elapsed) << " elapsed, ETA " << eta << "\n";
  out_.flush();
  last_line_ = now;
  last_step_ = step(done_);
  printed_done_ = done_;
}

void ProgressReporter::draw_terminal(std::chrono::steady_clock::time_point now) {
  const double elapsed = seconds_between(start_, now);
  const int done_here = done_ - done_at_start_;
  std::string line = "\r" + label_ + " frame " + std::to_string(done_) + "/" + std::to_string(total_);
  const double left = time_left(elapsed);
  if (done_here > 0 && elapsed > 0 && left >= 0) {
    const double rate = done_here / elapsed;
    char text[64];
    std::snprintf(text, sizeof text, "  %.2f frames/s  ETA %s", rate, clock_text(left).c_str());
    line += text;
  }
  line += "\033[K";  // clear what a longer earlier line left
  out_ << line;
  out_.flush();
  drawn_ = true;
  drawn_done_ = done_;
  last_draw_ = now;
}

void ProgressReporter::message(const std::string& line) {
  if (drawn_) out_ << "\r\033[K";
  out_ << line << '\n';
  out_.flush();
  drawn_ = false;
  drawn_done_ = -1;
}

void ProgressReporter::finish() {
  if (style_ == ProgressStyle::plain && printed_done_ != done_) print_plain(clock_());
  if (drawn_ && drawn_done_ != done_) draw_terminal(clock_());
  if (drawn_) {
    out_ << '\n';
    out_.flush();
  }
  drawn_ = false;
  style_ = ProgressStyle::silent;
}

}  // namespace bsim
