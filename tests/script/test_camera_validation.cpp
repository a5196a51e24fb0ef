// Camera scripts that do not fit the simulated shot: located errors, no shot, and no output files.
#include <doctest/doctest.h>
#include <filesystem>
#include <string>

#include "shot.h"
#include "support.h"

using namespace bsim;

namespace {

const std::string kBalls =
    "cue 0 0\n"
    "ball 0 -0.5 0 0.028575 0.5 0 0 1 0 0 0\n"
    "ball 1 0.5 0.3 0.028575 0 0 0 1 0 0 0\n";

/// The number of events of the shot above (no camera line depends on it).
int event_count() {
  ShotResult result = load_shot(kBalls + "camera\nendcamera\n", "count");
  REQUIRE(result.shot);
  return static_cast<int>(result.shot->timeline.events().size());
}

/// The one error load_shot reports for the camera lines `camera` (starting on line 5).
Diagnostic only_error(const std::string& camera) {
  ShotResult result = load_shot(kBalls + "camera\n" + camera + "endcamera\n", "bad");
  CHECK_FALSE(result.scripted());
  REQUIRE(result.diagnostics.size() == 1);
  CHECK(result.diagnostics[0].severity == Severity::error);
  return result.diagnostics[0];
}

}  // namespace

TEST_SUITE("camera_validation") {
  TEST_CASE("an event the shot does not have") {
    const int n = event_count();
    REQUIRE(n >= 3);
    const Diagnostic d =
        only_error("event 0 0 0 hover 0 -3 2 0 0 0\nevent " + std::to_string(n + 6) + " 0.5 0 hover 1 -3 2 0 0 0\n");
    CHECK(d.message == "event " + std::to_string(n + 6) + " does not exist: the shot has " + std::to_string(n) +
                           " events (0 to " + std::to_string(n - 1) + ")");
    CHECK(d.loc.line == 6);
    CHECK(d.loc.column == 7);
    CHECK(format_diagnostic(d, "bad.scn").rfind("bad.scn:6:7: error: event ", 0) == 0);
  }

  TEST_CASE("the last event by number is fine, one past it is not") {
    const int n = event_count();
    ShotResult fine = load_shot(kBalls + "camera\nevent 0 0 0 hover 0 -3 2 0 0 0\nevent " + std::to_string(n - 1) +
                                    " 0.5 0 hover 1 -3 2 0 0 0\nendcamera\n",
                                "fine");
    CHECK(fine.scripted());
    const Diagnostic d =
        only_error("event 0 0 0 hover 0 -3 2 0 0 0\n  event  " + std::to_string(n) + " 0.5 0 hover 1 -3 2 0 0 0\n");
    CHECK(d.loc.line == 6);
    CHECK(d.loc.column == 10);
  }

  TEST_CASE("events listed out of order") {
    const Diagnostic d = only_error("event 1 0 0 hover 0 -3 2 0 0 0\nevent 0 0.5 0 hover 1 -3 2 0 0 0\n");
    CHECK(d.message == "event 0 is listed after event 1: list the camera's events in increasing order");
    CHECK(d.loc.line == 6);
    CHECK(d.loc.column == 7);
  }

  TEST_CASE("event 65535 after the last event by number repeats it") {
    const int n = event_count();
    const Diagnostic d = only_error("event " + std::to_string(n - 1) +
                                    " 0 0 hover 0 -3 2 0 0 0\nevent 65535 0.5 0 hover 1 -3 2 0 0 0\n");
    CHECK(d.message == "event 65535 (the last event, " + std::to_string(n - 1) + ") is listed after event " +
                           std::to_string(n - 1) + ": list the camera's events in increasing order");
    CHECK(d.loc.line == 6);
    CHECK(d.loc.column == 7);
  }

  TEST_CASE("look and follow name balls the scene has") {
    // The parser already knows the ball count, so these are caught before simulating; either way
    // the error points at the index.
    Diagnostic d = only_error("event 0 0 0 look 0 -3 2 2\n");
    CHECK(d.loc.line == 5);
    CHECK(d.loc.column == 25);
    d = only_error("event 0 0 0 hover 0 -3 2 0 0 0\nevent 1 0 0 follow 7 -1 0 1\n");
    CHECK(d.loc.line == 6);
    CHECK(d.loc.column == 20);
  }

  TEST_CASE("the exporter reports the error with the path, exits 1 and writes nothing") {
    test::TempDir dir;
    const std::string scene = dir.file("late.scn", kBalls +
                                                       "camera\nevent 0 0 0 hover 0 -3 2 0 0 0\n"
                                                       "event 900 0 0 hover 1 -3 2 0 0 0\nendcamera\n");
    const auto out = dir.path / "out";
    const test::CommandResult r =
        test::run_command(test::bin("billiards-export") + " '" + scene + "' --events-only -o '" + out.string() + "'");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find(scene + ":6:7: error: event 900 does not exist") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out / "events.json"));
    CHECK_FALSE(std::filesystem::exists(out / "camera.csv"));
  }
}
