// The checks at the seams (check.h): a broken promise stops the program with its file, line and
// message; a kept one passes. The seams: a scene's and a timeline's ball index, a segment's time.
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

#include "check.h"
#include "shot.h"
#include "shots.h"

using namespace bsim;

namespace {

struct Stopped {
  bool aborted = false;
  std::string message;  ///< what it wrote to standard error
};

/// Runs `body` in a child process and returns whether it aborted and what it wrote on standard error.
Stopped run_child(const std::function<void()>& body) {
  int fds[2];
  REQUIRE(pipe(fds) == 0);
  std::fflush(nullptr);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    close(fds[0]);
    dup2(fds[1], STDERR_FILENO);
    body();
    _exit(0);
  }
  close(fds[1]);
  Stopped r;
  char buffer[512];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) r.message.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  r.aborted = WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT;
  return r;
}

const char* const kTwoBalls =
    "cue 0 0\n"
    "ball 0  -0.6 0.1 0.028575   1.2 0 0   1 0 0 0\n"
    "ball 3   0.3 0.1 0.028575   0 0 0     1 0 0 0\n";

}  // namespace

TEST_SUITE("check") {
  TEST_CASE("a broken expectation stops the program with its file, line and message; a kept one passes") {
    const Stopped kept = run_child([] { BSIM_EXPECT(1 + 1 == 2, "arithmetic"); });
    CHECK_FALSE(kept.aborted);
    CHECK(kept.message.empty());
    const Stopped broken = run_child([] { BSIM_EXPECT(1 + 1 == 3, "arithmetic"); });
    CHECK(broken.aborted);
    CHECK(broken.message.find("tests/base/test_check.cpp:") != std::string::npos);
    CHECK(broken.message.front() != '/');  // the path in the tree, not where it was built
    CHECK(broken.message.find(": internal error: arithmetic (expected: 1 + 1 == 3)") != std::string::npos);
  }

  TEST_CASE("a ball that is not in the scene or the timeline, or a time that is no number, stops the program") {
    const auto shot = test::load_scene(kTwoBalls, "two");
    REQUIRE(shot);
    const int count = shot->timeline.ball_count();
    CHECK_FALSE(run_child([&] { (void)shot->scene.ball(count - 1); }).aborted);
    CHECK(run_child([&] { (void)shot->scene.ball(count); }).message.find("no such ball in the scene") !=
          std::string::npos);
    CHECK(run_child([&] { (void)shot->timeline.state(-1, 0.0); }).message.find("no such ball in the timeline") !=
          std::string::npos);
    CHECK(run_child([&] { (void)shot->timeline.segments(count); }).aborted);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(run_child([&] { (void)shot->timeline.state(0, nan); }).message.find("not a number") != std::string::npos);
  }
}
