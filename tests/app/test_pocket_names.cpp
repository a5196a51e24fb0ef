// Pockets in words, through both programs: the camera key `drop I` (a ball dropping, with `pocket I`
// its older spelling), a `pot` that names its pocket (`cue 0 pot 1 top-right`), and the messages that
// name a pocket ("the top-right corner (pocket 2)"); a failed `pot` names the pockets that would take
// the ball.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

/// The 3 (index 1) cut into the top-right corner (pocket 2) with a stroke; `pocket` is how the cue line
/// names the pocket, `camera` the camera block.
std::string pot_scene(const std::string& pocket, const std::string& camera) {
  return "cue 0 pot 1 " + pocket +
         "\nstroke 1.5 0.4 0 0\n"
         "ball 0  -0.9 -0.3 0.028575   0 0 0     1 0 0 0\n"
         "ball 3  -0.4 -0.1 0.028575   0 0 0     1 0 0 0\n" +
         camera;
}

/// A camera that cuts from a hover at the start to another when the ball keyed by `key` drops.
std::string cut_at(const std::string& key) {
  return "camera\nevent start 0 0 hover -0.2 -1.5 1.7  0.2 0.1 0\nevent " + key +
         " 0 0 hover 1.5 0.2 0.5  1.27 0.635 0\nendcamera\n";
}

test::CommandResult run(const std::string& program, const std::string& args) {
  return test::run_command(quoted(test::bin(program)) + " " + args);
}

/// billiards-export --events-only on `text`; the run's output directory.
fs::path events_only(const test::TempDir& dir, const std::string& name, const std::string& text,
                     test::CommandResult& r) {
  const std::string scene = dir.file(name + ".scn", text);
  const fs::path out = dir.path / name;
  r = run("billiards-export", quoted(scene) + " --events-only --quiet -o " + quoted(out.string()));
  return out;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("pocket names") {
  TEST_CASE("a camera key 'drop I' and its older spelling 'pocket I' cut at the ball's drop; pot takes a name") {
    test::TempDir dir;
    test::CommandResult by_name, by_number, older;
    const fs::path named = events_only(dir, "named", pot_scene("top-right", cut_at("drop 1")), by_name);
    INFO(by_name.err);
    REQUIRE(by_name.exit_code == 0);
    const fs::path numbered = events_only(dir, "numbered", pot_scene("2", cut_at("pocket 1")), by_number);
    INFO(by_number.err);
    REQUIRE(by_number.exit_code == 0);
    // The 3 drops into the top-right corner, pocket 2, as with the number.
    const std::string events = test::require_file(named / "events.json");
    CHECK(has(events, "\"ball\": 1, \"pocket\": 2}"));
    CHECK(events == test::require_file(numbered / "events.json"));
    // Both keys name the same moment: the same camera, frame for frame; and it is the drop's moment,
    // not the start (a camera keyed at a moment after it differs).
    const std::string camera = test::require_file(named / "camera.csv");
    CHECK(camera == test::require_file(numbered / "camera.csv"));
    test::CommandResult later;
    const fs::path at_end = events_only(dir, "later", pot_scene("top-right", cut_at("end")), later);
    REQUIRE(later.exit_code == 0);
    CHECK(camera != test::require_file(at_end / "camera.csv"));

    // A drop that never happens is named by the key's own word, the same for both spellings.
    for (const std::string key : {"drop 0", "pocket 0"}) {
      CAPTURE(key);
      test::CommandResult never;
      events_only(dir, "never", pot_scene("top-right", cut_at(key)), never);
      CHECK(never.exit_code == 1);
      CHECK(has(never.err, "never.scn:7:7: error: drop 0 never happens: ball 0 drops into no pocket"));
    }
  }

  TEST_CASE("the director writes 'drop I'; a scene round trip keeps a pocket's name working") {
    test::TempDir dir;
    const std::string scene = dir.file("named.scn", pot_scene("top-right", ""));
    const std::string written = (dir.path / "camera.txt").string();
    const test::CommandResult camera =
        run("billiards-preview", quoted(scene) + " --camera auto --write-camera " + quoted(written) + " --quiet");
    INFO(camera.err);
    REQUIRE(camera.exit_code == 0);
    const std::string script = test::require_file(written);
    CHECK(has(script, "event drop 1 "));
    CHECK_FALSE(has(script, "event pocket "));

    // --write-scene resolves the named pocket to the heading it plays; the written scene plays the same.
    const std::string resolved = (dir.path / "resolved.scn").string();
    const test::CommandResult write =
        run("billiards-preview", quoted(scene) + " --write-scene " + quoted(resolved) + " --quiet");
    INFO(write.err);
    REQUIRE(write.exit_code == 0);
    const std::string text = test::require_file(resolved);
    CHECK_FALSE(has(text, "top-right"));
    test::CommandResult a, b;
    const fs::path first = events_only(dir, "a", pot_scene("top-right", ""), a);
    const fs::path second = events_only(dir, "b", text, b);
    REQUIRE(a.exit_code == 0);
    REQUIRE(b.exit_code == 0);
    CHECK(test::require_file(first / "events.json") == test::require_file(second / "events.json"));
  }

  TEST_CASE("pocket names: a misspelling gets a suggestion, a scene's own pockets take numbers only") {
    test::TempDir dir;
    test::CommandResult typo;
    const fs::path out = events_only(dir, "typo", pot_scene("top-rigth", ""), typo);
    CHECK(typo.exit_code == 1);
    CHECK(has(typo.err,
              "typo.scn:1:13: error: expected the pocket to pot into, its number or its name (top-left, "
              "top-side, top-right, bottom-right, bottom-side, bottom-left), found 'top-rigth'; did you "
              "mean 'top-right'?"));
    CHECK_FALSE(fs::exists(out));
    // The side pockets by the table numbering's word too.
    test::CommandResult middle, side;
    events_only(dir, "middle", pot_scene("bottom-middle", ""), middle);
    events_only(dir, "side", pot_scene("bottom-side", ""), side);
    const auto message = [](const std::string& err) { return err.substr(std::min(err.find(": error: "), err.size())); };
    CHECK_FALSE(message(side.err).empty());
    CHECK(message(middle.err) == message(side.err));

    // The scene's own six pocket lines (where the standard ones are): names name no pocket of them.
    std::string own;
    for (const char* p : {"-1.27 0.635", "0 0.635", "1.27 0.635", "1.27 -0.635", "0 -0.635", "-1.27 -0.635"})
      own += std::string("pocket ") + p + " 0 0.08\n";
    test::CommandResult mine;
    events_only(dir, "own", pot_scene("top-right", own), mine);
    CHECK(mine.exit_code == 1);
    CHECK(has(mine.err,
              "own.scn:1:13: error: pocket names name the standard table's six pockets, and this scene has "
              "its own 'pocket' lines (the first on line 5): give the pocket's number, 0 to 5 in file "
              "order"));
    test::CommandResult numbered;
    events_only(dir, "own_number", pot_scene("2", own), numbered);
    INFO(numbered.err);
    CHECK(numbered.exit_code == 0);
  }

  TEST_CASE("messages name pockets in words: a ball over a pocket, a pot that cannot be made") {
    test::TempDir dir;
    // The 9 starts over the top-right corner.
    test::CommandResult over;
    events_only(dir, "over", pot_scene("top-right", "ball 9 1.265 0.63 0.028575 0 0 0 1 0 0 0\n"), over);
    CHECK(has(over.err,
              "over.scn:5:8: warning: ball 9 starts over the top-right corner (pocket 2) and will drop into it"));

    // Pocket 5, the bottom-left corner, is behind the 3 as the cue ball sees it: no heading pots it there,
    // and the error names the pockets that do take it.
    test::CommandResult behind;
    events_only(dir, "behind", pot_scene("bottom-left", ""), behind);
    CHECK(behind.exit_code == 1);
    CHECK(has(behind.err,
              "behind.scn:1:1: error: no heading pots ball index 1 (the 3) in the bottom-left corner "
              "(pocket 5): the cut is thinner than 89 degrees"));
    CHECK(has(behind.err, "\n  other pockets take it from here: "));
    CHECK(has(behind.err, "the top-right corner (pocket 2)\n"));
  }
}
