// billiards-preview --movie, end to end: Ctrl-C (or SIGTERM) while the animatic is being made stops
// ffmpeg, leaves neither the movie nor its half-written .partial file nor any temporary file, says
// so, and dies of the signal; an odd --size is padded to even sides for H.264, with a warning that
// names the size used.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "support.h"

using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

/// Files left in `dir` (not below).
int count_entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST_SUITE("preview animatic") {
  TEST_CASE("Ctrl-C or SIGTERM during the animatic: nothing written, no .partial, the process dies of it") {
    bsim::test::require_program("ffmpeg");
    struct Case {
      const char* signal;
      const char* target;  ///< "-$pid": the whole process group, as Ctrl-C on a terminal; "$pid": the preview alone
      int status;          ///< 128 + the signal's number
    };
    for (const Case c : {Case{"INT", "-$pid", 130}, Case{"TERM", "$pid", 143}}) {
      CAPTURE(c.signal);
      bsim::test::TempDir dir;
      const fs::path tmp = dir.path / "tmp";
      fs::create_directories(tmp);
      const fs::path movie = dir.path / "break.mp4";
      const std::string partial = movie.string() + ".partial";
      // The built-in break: 300 frames, several seconds of work; the signal comes once ffmpeg has
      // begun writing the movie. setsid: the preview leads its own process group, so a signal to the
      // group reaches it and ffmpeg at once.
      const std::string command = "TMPDIR=" + quoted(tmp.string()) + " setsid " +
                                  quoted(bsim::test::bin("billiards-preview")) + " --movie " + quoted(movie.string()) +
                                  " --size 640x360 & pid=$!; i=0; while [ ! -s " + quoted(partial) +
                                  " ] && [ $i -lt 1200 ]; do sleep 0.05; i=$((i+1)); done; kill -" + c.signal + " " +
                                  c.target + "; wait $pid; echo \"status $?\"";
      const bsim::test::CommandResult r = bsim::test::run_command(command);
      INFO(r.err);
      CHECK(r.out.find("status " + std::to_string(c.status)) != std::string::npos);
      CHECK(r.err.find("billiards-preview: interrupted: nothing was written to " + movie.string()) !=
            std::string::npos);
      CHECK_FALSE(fs::exists(partial));
      CHECK_FALSE(fs::exists(movie));
      CHECK(count_entries(tmp) == 0);  // the sound track and ffmpeg's log are gone too
      CHECK(count_entries(dir.path) == 1);
    }
  }

  TEST_CASE("an odd --size is padded to even sides, and a warning names the size used") {
    bsim::test::require_program("ffmpeg");
    bsim::test::require_program("ffprobe");
    bsim::test::TempDir dir;
    const std::string scene = dir.file("short.scn",
                                       "cue 0 0\n"
                                       "ball 0 -0.3 0 0.028575  0.2 0 0  1 0 0 0\n"
                                       "ball 9  0.2 0.05 0.028575  0 0 0  1 0 0 0\n");
    const std::string movie = (dir.path / "odd.mp4").string();
    const bsim::test::CommandResult r = bsim::test::run_command(quoted(bsim::test::bin("billiards-preview")) + " " +
                                                                quoted(scene) + " --movie " + quoted(movie) +
                                                                " --size 161x91 --fps 4");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("billiards-preview: warning: --size 161x91 has an odd side, which H.264 cannot encode: the "
                     "animatic is 162x92 (a black line added at the right and bottom)") != std::string::npos);
    const bsim::test::CommandResult probe = bsim::test::run_command(
        "ffprobe -v error -select_streams v -show_entries stream=width,height -of csv=p=0 " + quoted(movie));
    CHECK(probe.out == "162,92\n");

    // Even sides: no warning.
    const bsim::test::CommandResult even = bsim::test::run_command(quoted(bsim::test::bin("billiards-preview")) + " " +
                                                                   quoted(scene) + " --movie " + quoted(movie) +
                                                                   " --size 160x90 --fps 4");
    REQUIRE(even.exit_code == 0);
    CHECK(even.err.find("warning") == std::string::npos);
  }
}
