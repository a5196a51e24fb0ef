// Every way a scene can be wrong gets an error (or warning) at the token at fault that says what
// was expected and what was found.
#include <doctest/doctest.h>

#include <string>

#include "fixtures.h"
#include "parse_checks.h"
#include "scene_parse.h"

using namespace bsim;

namespace {

const std::string kCam = test::fixtures::kHoverCamera;
const std::string kBall0 = "ball 0 0 0 0.028575 1 0 0 1 0 0 0\n";

using test::all_messages;
using test::expect_error;

/// `text` parses, with exactly one warning at line:column containing `part`.
void expect_warning(const std::string& text, int line, int column, std::string_view part) {
  const ParseResult r = parse_scene(text, "t");
  INFO("scene:\n" << text << "diagnostics:\n" << all_messages(r));
  REQUIRE(r.scene.has_value());
  REQUIRE(r.diagnostics.size() == 1);
  CHECK(r.diagnostics[0].severity == Severity::warning);
  CHECK(r.diagnostics[0].loc.line == line);
  CHECK(r.diagnostics[0].loc.column == column);
  CHECK(r.diagnostics[0].message.find(part) != std::string::npos);
}

void expect_clean(const std::string& text) {
  const ParseResult r = parse_scene(text, "t");
  INFO("scene:\n" << text << "diagnostics:\n" << all_messages(r));
  CHECK(r.scene.has_value());
  CHECK(r.diagnostics.empty());
}

}  // namespace

TEST_SUITE("validation: tokens") {
  TEST_CASE("unknown keyword") {
    expect_error("cue 0 0\nbal 0 0 0 0.028575 1 0 0 1 0 0 0\n" + kCam, 2, 1,
                 {"unknown keyword 'bal'", "expected one of cue, ball, rail, camera, pocket, spin, param"});
  }

  TEST_CASE("a number where a keyword belongs") {
    expect_error("cue 0 0 5\n" + kBall0, 1, 9, {"expected a keyword", "found the number '5'"});
  }

  TEST_CASE("a word where a number belongs") {
    expect_error("cue 0 0\nball 0 0 abc 0.028575 1 0 0 1 0 0 0\n" + kCam, 2, 10,
                 {"expected a number for the ball's y position, found 'abc'"});
    expect_error("cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nrail 1 1 x 1 -1 0\n", 3, 10,
                 {"expected a number for the rail's first end z, found 'x'"});
  }

  TEST_CASE("a fraction or a word where an integer belongs") {
    expect_error("cue 0 0\nball 1.5 0 0 0.028575 1 0 0 1 0 0 0\n", 2, 6,
                 {"expected an integer for the ball number, found '1.5'"});
    expect_error("cue zero 0\n" + kBall0, 1, 5, {"expected an integer for the cue's target ball, found 'zero'"});
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 1e0 0 0 hover 0 -3 2 0 0 0\nendcamera\n", 4, 7,
                 {"expected an integer for the event number, found '1e0'"});
  }

  TEST_CASE("a keyword where a value belongs: the line before is short") {
    // Reported at the short line itself, just past its last token.
    expect_error("cue 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\n", 1, 6,
                 {"expected a number for the cue's heading in degrees, found 'ball', which starts the next statement"});
    // The keyword still starts its own line, so the short line costs one error, not two.
    CHECK(parse_scene("cue 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nball 1 x\n", "t").diagnostics.size() == 2);
    CHECK(parse_scene("param\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\n", "t")
              .diagnostics.size() == 2);
  }

  TEST_CASE("missing tokens at the end of the file point just past the last token") {
    expect_error("cue 0 0\nball 0 0\n", 2, 9, {"expected a number for the ball's y position, found end of file"});
    expect_error("cue 0 0\nball 0 0 0 0.028575\n", 2, 20,
                 {"expected a number for the ball's x velocity, found end of file"});
    expect_error("cue 0 0\n" + kBall0 + "param", 3, 6, {"expected a parameter name", "found end of file"});
    expect_error("cue", 1, 4, {"expected an integer for the cue's target ball, found end of file"});
  }

  TEST_CASE("numbers that are not finite") {
    for (const std::string bad : {"nan", "inf", "-inf", "Infinity", "NaN", "1e400", "-1e999"}) {
      CAPTURE(bad);
      expect_error("cue 0 0\nball 0 0 0 0.028575 " + std::string(bad) + " 0 0 1 0 0 0\n" + kCam, 2, 21,
                   {"expected a finite number for the ball's x velocity", "(not finite)"});
    }
    expect_error("cue 0 nan\n" + kBall0, 1, 7, {"finite number for the cue's heading"});
  }

  TEST_CASE("an empty file is an error at 1:1") {
    expect_error("", 1, 1, {"the scene is empty", "expected a cue description and at least one ball"});
    expect_error("# nothing but a comment\n", 1, 1, {"the scene is empty"});
  }

  TEST_CASE("a scene without a cue or without balls") {
    expect_error(kBall0 + kCam, 4, 10, {"expected a cue description", "found none"});
    expect_error("cue 0 0\n" + kCam, 4, 10, {"expected at least one ball description", "found none"});
  }

  TEST_CASE("a later cue needs its stroke; one camera description per scene") {
    expect_error("cue 0 0\n" + kBall0 + "cue 0 0\n", 3, 1, {"expected a 'stroke' line under this cue"});
    expect_error("cue 0 0\n" + kBall0 + kCam + kCam, 6, 1, {"one camera description", "already one on line 3"});
  }

  TEST_CASE("independent mistakes are all reported, in file order") {
    const ParseResult r = parse_scene("cue 0 x\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nbal 1\nrail 0 0 0 q 0 0\n", "t");
    REQUIRE(r.diagnostics.size() == 3);
    CHECK(r.diagnostics[0].loc.line == 1);
    CHECK(r.diagnostics[1].loc.line == 3);
    CHECK(r.diagnostics[2].loc.line == 4);
    CHECK(r.diagnostics[2].loc.column == 12);
  }

  TEST_CASE("a flood of errors stops after a bounded number") {
    std::string junk;
    for (int i = 0; i < 1000; ++i) junk += "ball x\n";
    const ParseResult r = parse_scene(junk, "t");
    CHECK(r.diagnostics.size() < 40);
    CHECK(r.diagnostics.back().message.find("too many errors") != std::string::npos);
  }
}

TEST_SUITE("validation: balls") {
  TEST_CASE("ball numbers from 0 to 15, each once") {
    expect_error("cue 0 0\nball 16 0 0 0.028575 1 0 0 1 0 0 0\n", 2, 6,
                 {"expected a ball number from 0 to 15, found '16'"});
    expect_error("cue 0 0\nball -1 0 0 0.028575 1 0 0 1 0 0 0\n", 2, 6, {"from 0 to 15, found '-1'"});
    expect_error("cue 0 0\nball 99999999999999999999999 0 0 0.028575 1 0 0 1 0 0 0\n", 2, 6, {"from 0 to 15"});
    expect_error("cue 0 0\n" + kBall0 + "ball 0 0.5 0 0.028575 0 0 0 1 0 0 0\n", 3, 6,
                 {"ball number 0 is already used by the ball on line 2"});
  }

  TEST_CASE("a cue target out of range is located on the target") {
    expect_error("cue 3 0\n" + kBall0 + kCam, 1, 5,
                 {"expected a cue target ball index from 0 to 0", "the scene has 1 ball", "found 3"});
    expect_error("cue -1 0\n" + kBall0, 1, 5, {"ball index of 0 or more", "found '-1'"});
  }

  TEST_CASE("a zero quaternion") {
    expect_error("cue 0 0\nball 0 0 0 0.028575 1 0 0 0 0 0 0\n" + kCam, 2, 27,
                 {"expected a non-zero orientation quaternion", "found 0 0 0 0"});
    expect_error("cue 0 0\nball 0 0 0 0.028575 1 0 0 0 0 nan 0\n", 2, 31,
                 {"finite number for the ball's orientation y"});
  }

  TEST_CASE("a ball whose centre is not on the bed") {
    expect_error("cue 0 0\nball 0 0 0 0.03 1 0 0 1 0 0 0\n", 2, 12,
                 {"expected the ball's centre on the bed at z = 0.028575", "found z = 0.03"});
    expect_error("cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nparam ball_radius 0.03\n", 2, 12,
                 {"at z = 0.03", "found z = 0.028575"});
  }

  TEST_CASE("overlapping balls are reported at the later ball") {
    expect_error("cue 0 0\n" + kBall0 + "ball 1 0.01 0 0.028575 0 0 0 1 0 0 0\n" + kCam, 3, 1,
                 {"ball 1 overlaps ball 0 (line 2)", "at least 0.05715 m apart", "found 0.01 m"});
    // Touching is fine.
    expect_clean("cue 0 0\n" + kBall0 + "ball 1 0.05715 0 0.028575 0 0 0 1 0 0 0\n");
  }

  TEST_CASE("a ball outside the cushions") {
    expect_error("cue 0 0\nball 0 1.3 0 0.028575 1 0 0 1 0 0 0\n", 2, 8,
                 {"expected the ball inside the cushions", "x from -1.24143 to 1.24143", "found x = 1.3, y = 0"});
    expect_error("cue 0 0\nball 0 0 -0.62 0.028575 1 0 0 1 0 0 0\n", 2, 8, {"inside the cushions", "y = -0.62"});
    // A lone cushion encloses nothing, but a ball behind it is still on the wrong side.
    expect_error("cue 0 0\n" + kBall0 + "ball 1 0 1 0.028575 0 0 0 1 0 0 0\nrail -1 0.5 0.0363 1 0.5 0.0363\n", 3, 8,
                 {"expected the ball on the playing side of its nearest cushion, rail 0 (line 4)", "found it behind"});
  }

  TEST_CASE("a ball cutting into a cushion") {
    expect_error("cue 0 0\nball 0 -1.2 0.62 0.028575 1 0 0 1 0 0 0\n", 2, 8, {"inside the cushions"});
    expect_error("cue 0 0\nball 0 0 0.48 0.028575 1 0 0 1 0 0 0\nrail -1 0.5 0.0363 1 0.5 0.0363\n", 2, 8,
                 {"ball 0 cuts into the cushion of rail 0 (line 3)", "found 0.02 m"});
    // A ball frozen to the cushion is fine.
    expect_clean("cue 0 180\nball 0 1.241425 0 0.028575 -1 0 0 1 0 0 0\n");
  }

  TEST_CASE("a ball starting over a pocket is a warning") {
    // On the standard table the pocket is named in words.
    expect_warning("cue 0 180\nball 0 1.265 0.63 0.028575 -1 0 0 1 0 0 0\n", 2, 8,
                   "ball 0 starts over the top-right corner (pocket 2) and will drop into it");
  }

  TEST_CASE("a ball on a cut pocket's shelf is on the table; one cutting into a jaw is not") {
    // Past the top-right corner's mouth (its middle at 1.2288, 0.5938), short of the hole: on the shelf.
    expect_clean("cue 0 180\nball 0 1.245 0.61 0.028575 -1 0 0 1 0 0 0\n");
    // Off the pocket's axis by 4 cm there, it stands in the facing: outside the cushions.
    expect_error("cue 0 180\nball 0 1.273 0.582 0.028575 -1 0 0 1 0 0 0\n", 2, 8,
                 {"expected the ball inside the cushions"});
  }
}

TEST_SUITE("validation: rails and pockets") {
  TEST_CASE("a rail listed anticlockwise") {
    expect_error("cue 0 0\n" + kBall0 + "rail 1 0.6 0.0363 -1 0.6 0.0363\n", 3, 1,
                 {"expected the rail's ends in clockwise order", "facing away from every ball", "swap its two ends"});
    expect_clean("cue 0 0\n" + kBall0 +
                 "rail -1 0.6 0.0363 1 0.6 0.0363\nrail 1 0.6 0.0363 1 -0.6 0.0363\n"
                 "rail 1 -0.6 0.0363 -1 -0.6 0.0363\nrail -1 -0.6 0.0363 -1 0.6 0.0363\n");
  }

  TEST_CASE("a rail's two ends at different heights") {
    expect_error("cue 0 0\n" + kBall0 + "rail -1 0.6 0.0363 1 0.6 0.04\n", 3, 26,
                 {"same nose height as its first (z = 0.0363)", "found z = 0.04"});
  }

  TEST_CASE("a rail of zero length") {
    expect_error("cue 0 0\n" + kBall0 + "rail 1 0.6 0.0363 1 0.6 0.0363\n", 3, 1, {"two different end points"});
  }

  TEST_CASE("a pocket off the bed or without a radius") {
    expect_error("cue 0 0\n" + kBall0 + "pocket 1 1 0.1 0.05\n", 3, 12, {"centre on the bed (z = 0)", "'0.1'"});
    expect_error("cue 0 0\n" + kBall0 + "pocket 1 1 0 0\n", 3, 14, {"radius greater than 0, found '0'"});
  }
}

TEST_SUITE("validation: camera") {
  TEST_CASE("window fractions outside [0, 1]") {
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 0 1.5 0 hover 0 -3 2 0 0 0\nendcamera\n", 4, 9,
                 {"expected the pre-event interpolation time as a fraction from 0 to 1, found '1.5'"});
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 0 0 -0.1 hover 0 -3 2 0 0 0\nendcamera\n", 4, 11,
                 {"post-event interpolation time", "found '-0.1'"});
  }

  TEST_CASE("camera without endcamera points at the camera keyword") {
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 0 0 0 hover 0 -3 2 0 0 0\n", 3, 1,
                 {"no 'endcamera'", "found end of file"});
    expect_error("cue 0 0\ncamera\nevent 0 0 0 hover 0 -3 2 0 0 0\n" + kBall0, 4, 1,
                 {"expected 'event' or 'endcamera', found 'ball'", "camera description on line 2 has no 'endcamera'"});
  }

  TEST_CASE("camera lines outside camera ... endcamera") {
    expect_error("cue 0 0\n" + kBall0 + "endcamera\n", 3, 1, {"'endcamera' without a 'camera'"});
    expect_error("cue 0 0\n" + kBall0 + "event 0 0 0 hover 0 -3 2 0 0 0\n", 3, 1,
                 {"'event' outside a camera description"});
    expect_error("cue 0 0\n" + kBall0 + "camera\nhover 0 0 0\nendcamera\n", 4, 1,
                 {"expected 'event' or 'endcamera' in the camera description, found 'hover'"});
  }

  TEST_CASE("event numbers and camera modes") {
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent -1 0 0 hover 0 -3 2 0 0 0\nendcamera\n", 4, 7,
                 {"expected an event number from 0 to 65535", "found '-1'"});
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 65536 0 0 hover 0 -3 2 0 0 0\nendcamera\n", 4, 7, {"'65536'"});
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 0 0 0 orbit 0 -3 2 0 0 0\nendcamera\n", 4, 13,
                 {"expected a camera mode (hover, look or follow), found 'orbit'"});
  }

  TEST_CASE("look and follow name a ball that exists") {
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 0 0 0 look 0 -3 2 4\nendcamera\n", 4, 25,
                 {"expected the index of the ball the camera looks at from 0 to 0", "found 4"});
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 0 0 0 follow 2 -1 0 0.3\nendcamera\n", 4, 20,
                 {"the ball the camera follows", "found 2"});
  }

  TEST_CASE("a camera looking at itself") {
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 0 0 0 hover 1 1 1 1 1 1\nendcamera\n", 4, 13,
                 {"location and look-at point equal"});
    expect_error("cue 0 0\n" + kBall0 + "camera\nevent 0 0 0 follow 0 0 0 0\nendcamera\n", 4, 13,
                 {"follow camera offset away from the ball"});
  }
}

TEST_SUITE("validation: extensions and params") {
  TEST_CASE("unknown param names") {
    expect_error("cue 0 0\n" + kBall0 + "param friction 0.2\n", 3, 7,
                 {"unknown parameter 'friction'", "expected one of ball_radius, ball_mass, g, mu_slide"});
    expect_error("cue 0 0\n" + kBall0 + "param 3 0.2\n", 3, 7, {"unknown parameter '3'"});
  }

  TEST_CASE("non-physical param values") {
    const std::pair<const char*, const char*> bad[] = {
        {"ball_radius 0", "greater than 0"}, {"ball_mass -1", "greater than 0"}, {"g 0", "greater than 0"},
        {"mu_slide -0.1", "greater than 0"}, {"mu_roll 0", "greater than 0"},    {"mu_spin -1", "greater than 0"},
        {"e_ball 1.5", "from 0 to 1"},       {"e_ball -0.5", "from 0 to 1"},     {"mu_ball -0.01", "at least 0"},
        {"e_rail 2", "from 0 to 1"},         {"mu_rail -1", "at least 0"},       {"table_speed 0", "greater than 0"},
    };
    for (const auto& [param, range] : bad) {
      const std::string shown = param;
      CAPTURE(shown);
      const std::string line = std::string("param ") + param + "\n";
      const int column = static_cast<int>(line.find(' ', 6)) + 2;
      expect_error("cue 0 0\n" + kBall0 + line, 3, column, {range, "for parameter '"});
    }
    expect_error("cue 0 0\n" + kBall0 + "param g inf\n", 3, 9, {"finite number for parameter 'g'"});
  }

  TEST_CASE("spin names a ball that exists, once") {
    expect_error("cue 0 0\n" + kBall0 + "spin 1 0 0 10\n", 3, 6, {"ball index for 'spin' from 0 to 0", "found 1"});
    expect_error("cue 0 0\n" + kBall0 + "spin 0 0 0 10\nspin 0 0 0 20\n", 4, 1, {"already has a spin on line 3"});
  }

  TEST_CASE("--strict rejects every extension where it appears") {
    const ParseOptions strict{.strict = true};
    expect_error("cue 0 0 # aim\n" + kBall0 + kCam, 1, 9, {"'#' comments are an extension that --strict rejects"},
                 strict);
    expect_error("cue 0 0\n" + kBall0 + "spin 0 0 0 1\n" + kCam, 3, 1, {"'spin' is an extension"}, strict);
    expect_error("cue 0 0\n" + kBall0 + "pocket 0 0 0 0.1\n" + kCam, 3, 1, {"'pocket' is an extension"}, strict);
    expect_error("cue 0 0\n" + kBall0 + kCam + "param g 9.8\n", 6, 1, {"'param' is an extension"}, strict);
    expect_error("cue 0 0\n" + kBall0, 2, 34, {"expected a camera description", "found none"}, strict);
    expect_error("cue 0 0\n" + kBall0 + "bal 0\n" + kCam, 3, 1, {"expected one of cue, ball, rail, camera", "'bal'"},
                 strict);
  }
}

TEST_SUITE("validation: warnings") {
  TEST_CASE("a cue heading that disagrees with its ball's velocity") {
    expect_warning("cue 0 30\n" + kBall0, 1, 7, "heading 30 degrees disagrees");
    expect_warning("cue 0 -90\nball 0 0 0 0.028575 0 1 0 1 0 0 0\n", 1, 7, "points at 90 degrees");
  }

  TEST_CASE("headings within a degree, or a full turn apart, agree") {
    expect_clean("cue 0 0.9\n" + kBall0);
    expect_clean("cue 0 359.5\n" + kBall0);
    expect_clean("cue 0 -270\nball 0 0 0 0.028575 0 2 0 1 0 0 0\n");
  }

  TEST_CASE("a cue striking a ball given no velocity") {
    expect_warning("cue 0 0\nball 0 0 0 0.028575 0 0 0 1 0 0 0\n", 1, 5, "the stick will not move it");
  }
}

TEST_SUITE("validation: aim") {
  // `cue I pot B P` (spec.md "Aim"): the ball and the pocket must exist, the potted ball is not the
  // struck one, and the struck ball's `ball` line must give the speed that the found heading turns.
  const std::string kTwoBalls = "ball 0 -0.5 0 0.028575 1 0 0 1 0 0 0\nball 1 0.5 0 0.028575 0 0 0 1 0 0 0\n";

  TEST_CASE("a pot cue parses, its ball and pocket kept") {
    const ParseResult r = parse_scene("cue 0 pot 1 2\n" + kTwoBalls, "t");
    INFO(all_messages(r));
    REQUIRE(r.scene.has_value());
    CHECK(r.diagnostics.empty());
    CHECK(r.scene->cue().aims());
    CHECK(r.scene->cue().pot_ball == 1);
    CHECK(r.scene->cue().pot_pocket == 2);
    CHECK(r.scene->cue().pot_pocket_loc.column == 13);
  }

  TEST_CASE("a pocket that does not exist is an error at the pocket number") {
    expect_error("cue 0 pot 1 6\n" + kTwoBalls, 1, 13,
                 {"expected a pocket number from 0 to 5", "or a pocket's name such as top-right", "found 6"});
    expect_error("cue 0 pot 1 -1\n" + kTwoBalls, 1, 13, {"expected a pocket number of 0 or more", "found '-1'"});
    // A scene's own pockets replace the standard six.
    expect_error("cue 0 pot 1 1\n" + kTwoBalls + "pocket 1.27 0.635 0 0.08\n", 1, 13,
                 {"expected a pocket number from 0 to 0", "numbered by their order in the file", "found 1"});
    // A standard pocket's name; a misspelled one gets a suggestion; a name on a scene with its own pockets.
    expect_error("cue 0 pot 1 top-rigt\n" + kTwoBalls, 1, 13, {"found 'top-rigt'", "did you mean 'top-right'?"});
    expect_error("cue 0 pot 1 bottom-midle\n" + kTwoBalls, 1, 13, {"did you mean 'bottom-middle'?"});
    expect_error("cue 0 pot 1 top-side\n" + kTwoBalls + "pocket 0 0.635 0 0.08\n", 1, 13,
                 {"this scene has its own 'pocket' lines (the first on line 4)", "give the pocket's number, 0 to 0"});
  }

  TEST_CASE("a ball to pot that does not exist, or the struck ball itself") {
    expect_error("cue 0 pot 2 2\n" + kTwoBalls, 1, 11,
                 {"expected the index of the ball to pot from 0 to 1", "found 2"});
    expect_error("cue 0 pot 0 2\n" + kTwoBalls, 1, 11, {"other than the struck one", "ball index 0"});
    expect_error("cue 0 pot x 2\n" + kTwoBalls, 1, 11, {"expected an integer for the ball to pot, found 'x'"});
  }

  TEST_CASE("a struck ball without a speed cannot be aimed") {
    expect_error("cue 1 pot 0 2\n" + kTwoBalls, 1, 1, {"expected a speed to aim with"});
  }

  TEST_CASE("--strict rejects pot at the word") {
    expect_error("cue 0 pot 1 2\n" + kTwoBalls + kCam, 1, 7, {"'pot' is an extension that --strict rejects"},
                 {.strict = true});
  }
}
