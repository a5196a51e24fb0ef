#include "progress_line.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace bsim {

namespace {

std::string clock_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

}  // namespace

ProgressLine::ProgressLine(std::string label, int total, int already_done)
    : label_(std::move(label)),
      total_(total),
      done_(already_done),
      enabled_(wanted()),
      start_(std::chrono::steady_clock::now()) {
  draw();
}

ProgressLine::~ProgressLine() { finish(); }

bool ProgressLine::wanted() { return isatty(STDERR_FILENO) && std::getenv("CI") == nullptr; }

void ProgressLine::advance() {
  ++done_;
  ++done_here_;
  draw();
}

void ProgressLine::draw() {
  if (!enabled_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string line = "\r" + label_ + " frame " + std::to_string(done_) + "/" + std::to_string(total_);
  if (done_here_ > 0 && elapsed > 0) {
    const double rate = done_here_ / elapsed;
    char text[64];
    std::snprintf(text, sizeof text, "  %.2f frames/s  ETA %s", rate, clock_text((total_ - done_) / rate).c_str());
    line += text;
  }
  line += "\033[K";  // clear what a longer earlier line left
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::finish() {
  if (drawn_) {
    std::fputs("\n", stderr);
    std::fflush(stderr);
  }
  drawn_ = false;
  enabled_ = false;
}

}  // namespace bsim
