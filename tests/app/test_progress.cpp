// The progress reporter with a clock the test moves by hand: off a terminal a plain line every tenth
// of the frames and at least every 30 s, and one at the end; on a terminal one line rewritten in place;
// nothing when quiet. Also how ffmpeg's progress is read, and the wait that lets a run report while
// its children work.
#include <doctest/doctest.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.h"
#include "ffmpeg_assemble.h"
#include "frames.h"
#include "progress_reporter.h"

using namespace bsim;
using std::chrono::seconds;

namespace {

/// A clock that stands still until the test moves it.
struct FakeClock {
  std::chrono::steady_clock::time_point now{};
  void pass(std::chrono::steady_clock::duration d) { now += d; }
  ProgressReporter::Clock clock() {
    return [this] { return now; };
  }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

namespace {

/// Written to by the SIGTERM handler below: a child that ran it instead of dying writes here.
int handler_marks = -1;
void mark_and_return(int) {
  if (handler_marks >= 0) (void)!write(handler_marks, "x", 1);
}

}  // namespace

TEST_SUITE("progress") {
  TEST_CASE("a plain line says frames done of the total, the time so far and the time left") {
    FakeClock clock;
    std::ostringstream out;
    ProgressReporter progress("billiards-export", "rendering", 270, 0, ProgressStyle::plain, out, clock.clock());
    for (int k = 0; k < 134; ++k) progress.advance();
    out.str("");
    clock.pass(seconds(72));
    progress.advance();  // 135 of 270: the fifth tenth
    CHECK(out.str() == "billiards-export: rendering: 135/270 frames (50%), 1m12s elapsed, ETA 1m12s\n");
  }

  TEST_CASE("with work counted, the time left is reckoned from the work, not the frames") {
    // A whole frame (100 units) first, then nine partial frames of 10 units each: after the whole one
    // took 10 s, the frames alone would say 90 s are left, the work says 9 s.
    FakeClock clock;
    std::ostringstream out;
    ProgressReporter progress("billiards-export", "rendering", 10, 0, ProgressStyle::plain, out, clock.clock());
    progress.count_work(190);
    clock.pass(seconds(10));
    progress.add_work(100);
    progress.advance();
    CHECK(out.str() == "billiards-export: rendering: 1/10 frames (10%), 10s elapsed, ETA 9s\n");
    out.str("");
    clock.pass(seconds(1));
    progress.add_work(10);
    progress.advance();  // work is counted as it is done: 110 of 190 in 11 s, 80 left
    CHECK(out.str() == "billiards-export: rendering: 2/10 frames (20%), 11s elapsed, ETA 8s\n");
  }

  TEST_CASE("off a terminal, a line for every tenth of the frames, and one at the end") {
    FakeClock clock;
    std::ostringstream out;
    {
      ProgressReporter progress("billiards-preview", "animatic", 45, 0, ProgressStyle::plain, out, clock.clock());
      CHECK(out.str().empty());  // nothing before the first tenth
      std::vector<int> printed_at;
      for (int k = 1; k <= 45; ++k) {
        clock.pass(seconds(1));
        const auto before = out.str().size();
        progress.advance();
        if (out.str().size() != before) printed_at.push_back(k);
      }
      // 45 frames: the tenths are reached at 5, 9, 14, 18, 23, 27, 32, 36, 41 and 45.
      CHECK(printed_at == std::vector<int>{5, 9, 14, 18, 23, 27, 32, 36, 41, 45});
      progress.finish();  // the last line said 45/45 already
      progress.advance();
      progress.tick();
    }
    const auto lines = lines_of(out.str());
    REQUIRE(lines.size() == 10);
    CHECK(lines.front() == "billiards-preview: animatic: 5/45 frames (11%), 5s elapsed, ETA 40s");
    CHECK(lines.back() == "billiards-preview: animatic: 45/45 frames (100%), 45s elapsed, ETA 0s");
    CHECK(out.str().find('\r') == std::string::npos);
  }

  TEST_CASE("off a terminal, a line at least every 30 s even when a tenth takes longer") {
    FakeClock clock;
    std::ostringstream out;
    ProgressReporter progress("billiards-export", "rendering", 1000, 0, ProgressStyle::plain, out, clock.clock());
    std::vector<int> printed_at;
    for (int k = 1; k <= 30; ++k) {  // a frame every 4 s: a tenth would take 400 s
      clock.pass(seconds(4));
      const auto before = out.str().size();
      progress.advance();
      if (out.str().size() != before) printed_at.push_back(k);
    }
    CHECK(printed_at == std::vector<int>{8, 16, 24});  // at 32 s, 64 s and 96 s
    CHECK(lines_of(out.str()).front() == "billiards-export: rendering: 8/1000 frames (0%), 32s elapsed, ETA 1h06m08s");
  }

  TEST_CASE("off a terminal, a line every 30 s while no frame finishes") {
    FakeClock clock;
    std::ostringstream out;
    ProgressReporter progress("billiards-export", "encoding", 10, 0, ProgressStyle::plain, out, clock.clock());
    clock.pass(seconds(29));
    progress.tick();
    CHECK(out.str().empty());
    clock.pass(seconds(1));
    progress.tick();
    CHECK(out.str() == "billiards-export: encoding: 0/10 frames (0%), 30s elapsed, ETA unknown\n");
    out.str("");
    clock.pass(seconds(29));
    progress.tick();
    CHECK(out.str().empty());
    clock.pass(seconds(1));
    progress.tick();
    CHECK(out.str() == "billiards-export: encoding: 0/10 frames (0%), 1m00s elapsed, ETA unknown\n");
  }

  TEST_CASE("frames already done count towards the total, not towards the rate") {
    FakeClock clock;
    std::ostringstream out;
    ProgressReporter progress("billiards-export", "rendering", 10, 5, ProgressStyle::plain, out, clock.clock());
    clock.pass(seconds(10));
    progress.advance();
    CHECK(out.str() == "billiards-export: rendering: 6/10 frames (60%), 10s elapsed, ETA 40s\n");
  }

  TEST_CASE("the end is reported once, also when nothing was left to do") {
    FakeClock clock;
    std::ostringstream out;
    {
      ProgressReporter progress("billiards-export", "rendering", 4, 4, ProgressStyle::plain, out, clock.clock());
      progress.finish();
      progress.finish();
    }
    CHECK(out.str() == "billiards-export: rendering: 4/4 frames (100%), 0s elapsed, ETA 0s\n");
  }

  TEST_CASE("quiet: nothing at all") {
    FakeClock clock;
    std::ostringstream out;
    {
      ProgressReporter progress("billiards-export", "rendering", 10, 0, ProgressStyle::silent, out, clock.clock());
      for (int k = 0; k < 10; ++k) {
        clock.pass(seconds(40));
        progress.advance();
        progress.tick();
      }
      progress.finish();
    }
    CHECK(out.str().empty());
    CHECK(progress_style(true) == ProgressStyle::silent);
  }

  TEST_CASE("on a terminal, one line rewritten for every frame and ended at the end") {
    FakeClock clock;
    std::ostringstream out;
    {
      ProgressReporter progress("billiards-export", "rendering", 10, 0, ProgressStyle::terminal, out, clock.clock());
      for (int k = 0; k < 4; ++k) {
        clock.pass(seconds(2));
        progress.advance();
      }
      progress.finish();
    }
    const std::string text = out.str();
    CHECK(text.find("\rrendering frame 0/10") == 0);
    CHECK(text.find("\rrendering frame 4/10  0.50 frames/s  ETA 0:12") != std::string::npos);
    CHECK(std::count(text.begin(), text.end(), '\r') == 5);
    CHECK(std::count(text.begin(), text.end(), '\n') == 1);
    CHECK(text.back() == '\n');
  }

  TEST_CASE("a warning clears the terminal line, stands on its own line, and the line comes back below it") {
    FakeClock clock;
    std::ostringstream out;
    ProgressReporter progress("billiards-export", "rendering", 10, 0, ProgressStyle::terminal, out, clock.clock());
    progress.message("warning: frame 1 retried");
    clock.pass(seconds(1));
    progress.advance();
    const std::string text = out.str();
    CHECK(text.find("\rrendering frame 0/10\033[K\r\033[Kwarning: frame 1 retried\n\rrendering frame 1/10") == 0);
    std::ostringstream plain;
    ProgressReporter off("billiards-export", "rendering", 10, 0, ProgressStyle::plain, plain, clock.clock());
    off.message("warning: frame 1 retried");
    CHECK(plain.str() == "warning: frame 1 retried\n");
  }

  TEST_CASE("on a terminal, at most ten redraws a second, and the last frame always shown") {
    FakeClock clock;
    std::ostringstream out;
    {
      ProgressReporter progress("billiards-preview", "animatic", 50, 0, ProgressStyle::terminal, out, clock.clock());
      for (int k = 0; k < 50; ++k) {
        clock.pass(std::chrono::milliseconds(10));
        progress.advance();
      }
      progress.finish();
    }
    const std::string text = out.str();
    CHECK(std::count(text.begin(), text.end(), '\r') == 6);  // at 0, 100, 200, 300, 400 and 500 ms
    CHECK(text.find("\ranimatic frame 10/50") != std::string::npos);
    CHECK(text.find("\ranimatic frame 11/50") == std::string::npos);
    CHECK(text.find("\ranimatic frame 50/50") != std::string::npos);
  }

  TEST_CASE("times in whole seconds, minutes and hours") {
    CHECK(progress_time_text(0) == "0s");
    CHECK(progress_time_text(0.4) == "0s");
    CHECK(progress_time_text(59.4) == "59s");
    CHECK(progress_time_text(72) == "1m12s");
    CHECK(progress_time_text(605) == "10m05s");
    CHECK(progress_time_text(3723) == "1h02m03s");
    CHECK(progress_time_text(-3) == "0s");
  }

  TEST_CASE("ffmpeg's progress: the last frame count it wrote, and the frames the movie holds") {
    CHECK(encoded_frames("") == 0);
    CHECK(encoded_frames("frame=12\nfps=0.00\nprogress=continue\n") == 12);
    CHECK(encoded_frames("frame=12\ndup_frames=0\ndrop_frames=3\nprogress=continue\nframe=24\nfps=0.00\n") == 24);
    CHECK(encoded_frames("frame=7\nkeyframe=9\n") == 7);
    // frame k shows t = k / fps; the movie is cut at the end of the shot
    CHECK(frame_count(10.0, 30) == 300);
    CHECK(frame_count(2.41, 10) == 25);
    CHECK(frame_count(0.1, 4) == 1);
    const std::vector<std::string> args =
        ffmpeg_arguments({.ffmpeg = "ffmpeg", .fps = 30, .duration = 1, .quiet = false}, "o.mp4", "p");
    const auto at = std::find(args.begin(), args.end(), "-progress");
    REQUIRE(at != args.end());
    CHECK(*(at + 1) == "p");
  }

  TEST_CASE("a child stopped at once dies of it and never runs this program's SIGTERM handler") {
    // Stopping a child right after starting it hits it between fork and exec, where it still holds this
    // program's handlers: a handler that returns would leave it running (and, here, mark the pipe).
    int marks[2];
    REQUIRE(pipe(marks) == 0);
    handler_marks = marks[1];
    struct sigaction mine {
    }, before{};
    mine.sa_handler = mark_and_return;
    sigemptyset(&mine.sa_mask);
    REQUIRE(sigaction(SIGTERM, &mine, &before) == 0);
    std::string error;
    for (int k = 0; k < 20; ++k) {
      const pid_t pid = start_process({find_program("sleep"), "30"}, ".", "/dev/null", error);
      REQUIRE_MESSAGE(pid > 0, error);
      stop_process(pid);
    }
    sigaction(SIGTERM, &before, nullptr);
    handler_marks = -1;
    close(marks[1]);
    char buffer[32];
    CHECK(read(marks[0], buffer, sizeof buffer) == 0);  // no child ran the handler
    close(marks[0]);
  }

  TEST_CASE("a wait for children that gives up, so a run can report while they work") {
    std::string error;
    const pid_t pid = start_process({find_program("sleep"), "30"}, ".", "/dev/null", error);
    REQUIRE_MESSAGE(pid > 0, error);
    bool success = true;
    CHECK(wait_any(success, std::chrono::milliseconds(1)) == 0);
    stop_process(pid);
    const pid_t quick = start_process({find_program("true")}, ".", "/dev/null", error);
    REQUIRE_MESSAGE(quick > 0, error);
    pid_t done = 0;
    while (done == 0) done = wait_any(success, std::chrono::milliseconds(100));
    CHECK(done == quick);
    CHECK(success);
  }
}
