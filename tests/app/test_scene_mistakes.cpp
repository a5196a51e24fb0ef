// End to end through both programs: scenes a new user writes that would lose a ball off the table or
// strike the wrong ball. A table with a gap no pocket fills is an error at the scene (exit 1, nothing
// written); a ball that still leaves the bed fails the run naming it; a `cue` line that strikes a
// numbered ball, and a `place` over a pocket, are warned about at their lines.
#include <doctest/doctest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

const std::string kCamera = "camera\nevent 0 0 0 hover 0 -3 2 0 0 0\nendcamera\n";

test::CommandResult run_export(const std::string& scene, const fs::path& out) {
  return test::run_command(quoted(test::bin("billiards-export")) + " " + quoted(scene) + " --events-only -o " +
                           quoted(out.string()));
}

test::CommandResult run_preview(const std::string& scene, const fs::path& picture) {
  return test::run_command(quoted(test::bin("billiards-preview")) + " " + quoted(scene) + " --at 0 --size 64x36 -o " +
                           quoted(picture.string()));
}

/// Both programs fail on `scene` with an error at line:column (and one naming `part`), writing nothing.
void expect_both_fail(const test::TempDir& tmp, const std::string& scene, int line, int column,
                      const std::string& part) {
  const fs::path out = tmp.path / "out";
  const fs::path picture = tmp.path / "shot.png";
  for (const test::CommandResult& r : {run_export(scene, out), run_preview(scene, picture)}) {
    INFO(r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find(scene + ":" + std::to_string(line) + ":" + std::to_string(column) + ": error: ") !=
          std::string::npos);
    CHECK(r.err.find(part) != std::string::npos);
  }
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(fs::exists(picture));
  CHECK(test::leftovers(tmp.path).empty());
}

}  // namespace

TEST_SUITE("scene mistakes end to end") {
  TEST_CASE("a table whose own pocket leaves the standard cushions' other gaps open: an error at the pocket line") {
    // The issue's scene: one corner pocket of the scene's own, so the other five gaps are holes into
    // the room; the cue ball is sent at the top-left corner, whose gap now has no pocket.
    test::TempDir tmp;
    const std::string scene = tmp.file("one_pocket.scn",
                                       "ball 0 -0.9 0.3 0.028575 -1.5 1.2 0 1 0 0 0\n"
                                       "cue 0 141.34\n"
                                       "pocket 1.27 0.635 0 0.08\n" +
                                           kCamera);
    expect_both_fail(tmp, scene, 3, 1, "the gap between rails 5 and 0 of the standard table");
    const test::CommandResult r = run_export(scene, tmp.path / "out");
    // Every open gap is named, each with a pocket that would fill it.
    for (const char* gap : {"rails 0 and 1", "rails 2 and 3", "rails 3 and 4", "rails 4 and 5", "rails 5 and 0"})
      CHECK_MESSAGE(r.err.find(gap) != std::string::npos, r.err);
    CHECK(r.err.find("rails 1 and 2") == std::string::npos);  // the pocket fills that one
    CHECK(r.err.find("add a `pocket` line there, such as `pocket 0 0.635 0 0.0642937`") != std::string::npos);
  }

  TEST_CASE("a ball that still leaves the bed fails the run, naming the ball, the time and the place") {
    // The table lies at x from 0 to 2.54; shot 1 scratches the cue ball into the top-right corner, and
    // shot 2 puts it back on the head spot (-0.635, 0), which on this table is off the bed.
    test::TempDir tmp;
    const std::string scene = tmp.file("off_bed.scn",
                                       "rail 0.08 0.635 0.0363  1.205 0.635 0.0363\n"
                                       "rail 1.335 0.635 0.0363  2.46 0.635 0.0363\n"
                                       "rail 2.54 0.555 0.0363  2.54 -0.555 0.0363\n"
                                       "rail 2.46 -0.635 0.0363  1.335 -0.635 0.0363\n"
                                       "rail 1.205 -0.635 0.0363  0.08 -0.635 0.0363\n"
                                       "rail 0 -0.555 0.0363  0 0.555 0.0363\n"
                                       "pocket 0 0.635 0 0.08\npocket 1.27 0.635 0 0.065\npocket 2.54 0.635 0 0.08\n"
                                       "pocket 2.54 -0.635 0 0.08\npocket 1.27 -0.635 0 0.065\npocket 0 -0.635 0 0.08\n"
                                       "ball 0 2.2 0.3 0.028575 1 1 0 1 0 0 0\n"
                                       "cue 0 45\n"
                                       "cue 0 0\nstroke 1 0 0 0\n" +
                                           kCamera);
    expect_both_fail(tmp, scene, 15, 1, "the cue ball (ball index 0) left the table at ");
    const test::CommandResult r = run_export(scene, tmp.path / "out");
    CHECK_MESSAGE(std::regex_search(r.err, std::regex(R"(left the table at \d+(\.\d+)? s, at \(-0\.635, 0\.000\))")),
                  r.err);
  }

  TEST_CASE("a cue line that strikes a numbered ball while the cue ball is elsewhere: a warning naming its index") {
    // `rack 9ball` before the cue ball's line: index 0 is the rack's 1, and the cue ball is index 9.
    test::TempDir tmp;
    const std::string scene = tmp.file("rack_first.scn",
                                       "rack 9ball\n"
                                       "ball 0 -0.635 0 0.028575 0 0 0 1 0 0 0\n"
                                       "cue 0 0\nstroke 2 0 0 0\n" +
                                           kCamera);
    const test::CommandResult r = run_export(scene, tmp.path / "out");
    CHECK(r.exit_code == 0);
    CHECK_MESSAGE(
        r.err.find(scene + ":3:5: warning: the cue strikes ball index 0, the 1, not the cue ball; the cue ball "
                           "(painted 0) is ball index 9") != std::string::npos,
        r.err);
    // Written the other way round, no warning.
    const std::string right = tmp.file("cue_first.scn",
                                       "ball 0 -0.635 0 0.028575 0 0 0 1 0 0 0\n"
                                       "rack 9ball\n"
                                       "cue 0 0\nstroke 2 0 0 0\n" +
                                           kCamera);
    const test::CommandResult fine = run_export(right, tmp.path / "out2");
    CHECK(fine.exit_code == 0);
    CHECK_MESSAGE(fine.err.find("warning") == std::string::npos, fine.err);
  }

  TEST_CASE("a later shot's place over a pocket: the same warning at the place line as at a ball line") {
    test::TempDir tmp;
    const std::string scene = tmp.file("place_pocket.scn",
                                       "ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\n"
                                       "ball 1 0.3 -0.3 0.028575 0 0 0 1 0 0 0\n"
                                       "cue 0 0\nstroke 1 0 0 0\n"
                                       "cue 0 0\nstroke 1 0 0 0\n"
                                       "place 0 1.265 0.63\n" +
                                           kCamera);
    const test::CommandResult r = run_export(scene, tmp.path / "out");
    CHECK(r.exit_code == 0);
    CHECK_MESSAGE(
        r.err.find(scene + ":7:9: warning: ball 0 starts over the top-right corner (pocket 2)") != std::string::npos,
        r.err);
    // The ball line's own words there.
    const std::string ball =
        tmp.file("ball_pocket.scn", "ball 0 1.265 0.63 0.028575 0 0 0 1 0 0 0\ncue 0 0\n" + kCamera);
    const test::CommandResult b = run_export(ball, tmp.path / "out2");
    CHECK_MESSAGE(
        b.err.find(ball + ":1:8: warning: ball 0 starts over the top-right corner (pocket 2)") != std::string::npos,
        b.err);
  }
}
