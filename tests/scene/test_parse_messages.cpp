// The short `ball N X Y` line, short lines reported where they are, one error for a malformed `cue`
// line (not a second at its stroke), and keywords in the wrong case.
#include <doctest/doctest.h>

#include <string>

#include "parse_checks.h"
#include "scene_parse.h"

using namespace bsim;
using test::all_messages;
using test::expect_error;

namespace {

Scene parse_ok(const std::string& text) {
  const ParseResult r = parse_scene(text, "t");
  INFO(all_messages(r));
  REQUIRE(r.scene);
  CHECK(r.diagnostics.empty());
  return *r.scene;
}

}  // namespace

TEST_SUITE("the short ball line") {
  TEST_CASE("`ball N X Y` then a keyword: at rest on the bed, upright") {
    const Scene s = parse_ok("ball 0 -0.5 0.1\ncue 0 0\nstroke 1 0 0 0\nball 1 0.3 0.2 ball 2 0.4 -0.2\n");
    REQUIRE(s.balls.size() == 3);
    CHECK(s.balls[0].position == Vec3(-0.5, 0.1, 0.028575));
    CHECK(s.balls[1].position == Vec3(0.3, 0.2, 0.028575));
    CHECK(s.balls[2].position == Vec3(0.4, -0.2, 0.028575));  // at the end of the file
    for (const Ball& b : s.balls) {
      CHECK(b.velocity == Vec3(0, 0, 0));
      CHECK(b.orientation.isApprox(Quat::Identity()));
    }
  }

  TEST_CASE("its z follows ball_radius wherever the param is written") {
    const Scene s = parse_ok("ball 0 -0.5 0.1\ncue 0 0\nstroke 1 0 0 0\nparam ball_radius 0.03\n");
    CHECK(s.balls[0].position.z() == 0.03);
  }

  TEST_CASE("the same ball as the long line") {
    const Scene a = parse_ok("ball 0 -0.5 0.1\nball 4 0.2 0\ncue 0 0\nstroke 2 0.1 0 5\n");
    const Scene b = parse_ok(
        "ball 0 -0.5 0.1 0.028575 0 0 0 1 0 0 0\nball 4 0.2 0 0.028575 0 0 0 1 0 0 0\ncue 0 0\nstroke 2 0.1 0 5\n");
    REQUIRE(a.balls.size() == b.balls.size());
    for (std::size_t i = 0; i < a.balls.size(); ++i) {
      CHECK(a.balls[i].position == b.balls[i].position);
      CHECK(a.balls[i].velocity == b.balls[i].velocity);
      CHECK(a.balls[i].orientation.coeffs() == b.balls[i].orientation.coeffs());
    }
  }

  TEST_CASE("a number after X Y means the long line, and checks stay at their tokens") {
    expect_error("cue 0 0\nball 0 0 0 0.028575 1 0\n", 2, 24,
                 {"expected a number for the ball's z velocity, found end of file"});
  }

  TEST_CASE("a short ball line is checked as the long one: inside the cushions, apart") {
    expect_error("cue 0 0\nball 0 1.3 0\n", 2, 8, {"expected the ball inside the cushions"});
    expect_error("cue 0 0\nstroke 1 0 0 0\nball 0 0 0\nball 1 0.01 0\n", 4, 1, {"ball 1 overlaps ball 0 (line 3)"});
  }

  TEST_CASE("a short ball line struck by a cue with no stroke is an error at the ball: it gives no velocity") {
    // The acceptance checks' truncated long line reads as a short one; the shot it would make never moves.
    expect_error("cue 0 0\nball 0 0 0\n", 2, 8,
                 {"whose short line 'ball N X Y' leaves it at rest, and there is no stroke"});
    // With a stroke, or struck long-form, it is a shot.
    ParseResult stroked = parse_scene("cue 0 0\nstroke 1 0 0 0\nball 0 0 0\n", "s");
    CHECK(stroked.scene);
    ParseResult other = parse_scene("cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nball 1 0.3 0\n", "s");
    CHECK(other.scene);
  }

  TEST_CASE("--strict rejects it") {
    ParseOptions strict;
    strict.strict = true;
    expect_error("cue 0 0\nball 0 0 0\n", 2, 1, {"the short ball line", "--strict rejects"}, strict);
  }
}

TEST_SUITE("short lines are reported where they are") {
  TEST_CASE("a ball line cut short before the next statement: at the end of the ball line") {
    expect_error("ball 0 0 0 0.028575 1 0 0\ncue 0 0\n", 1, 26,
                 {"expected a number for the ball's orientation w, found 'cue', which starts the next statement "
                  "(line 2): the statement ends early"});
    // One error: the next statement is still read.
    CHECK(parse_scene("ball 0 0 0 0.028575 1 0 0\ncue x 0\n", "t").diagnostics.size() == 2);
  }

  TEST_CASE("a short cue line before a ball line") {
    expect_error("cue 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\n", 1, 6,
                 {"expected a number for the cue's heading in degrees, found 'ball', which starts the next "
                  "statement (line 2)"});
  }
}

TEST_SUITE("a malformed cue line") {
  TEST_CASE("gets one error, not a second at its stroke") {
    for (const std::string cue : {"cue x 0", "cue 0 y", "cue 0 pot 1 x", "cue -1 0"}) {
      CAPTURE(cue);
      const ParseResult r = parse_scene(
          "ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\nball 1 0 0 0.028575 0 0 0 1 0 0 0\n" + cue + "\nstroke 1 0 0 0\n",
          "t");
      INFO(all_messages(r));
      REQUIRE(r.diagnostics.size() == 1);
      CHECK(r.diagnostics[0].loc.line == 3);
      CHECK(all_messages(r).find("no cue line") == std::string::npos);
      CHECK(all_messages(r).find("found none") == std::string::npos);
    }
  }

  TEST_CASE("a later malformed cue line: its stroke and places are not blamed on the cue before") {
    const ParseResult r = parse_scene(
        "ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\ncue 0 0\nstroke 1 0 0 0\ncue 0 q\nstroke 1 0 0 0\nplace 0\n", "t");
    INFO(all_messages(r));
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].loc.line == 4);
  }

  TEST_CASE("the stroke's own mistakes are still reported") {
    const ParseResult r = parse_scene("ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\ncue x 0\nstroke 99 0 0 0\n", "t");
    INFO(all_messages(r));
    REQUIRE(r.diagnostics.size() == 2);
    CHECK(r.diagnostics[1].loc.line == 3);
    CHECK(r.diagnostics[1].message.find("stroke speed") != std::string::npos);
  }

  TEST_CASE("a stroke with no cue line at all is still an error") {
    expect_error("ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\nstroke 1 0 0 0\ncue 0 0\n", 2, 1,
                 {"expected the 'cue' line this stroke strikes with above it, found none"});
  }
}

TEST_SUITE("keywords in the wrong case") {
  TEST_CASE("BALL: keywords are lower case") {
    expect_error("cue 0 0\nBALL 0 0 0 0.028575 1 0 0 1 0 0 0\n", 2, 1,
                 {"unknown keyword 'BALL'", "; did you mean 'ball'? (keywords are lower case)"});
    expect_error("Cue 0 0\nball 0 0 0\n", 1, 1, {"did you mean 'cue'? (keywords are lower case)"});
  }

  TEST_CASE("other words too: params, camera modes, racks") {
    expect_error("cue 0 0\nball 0 0 0\nparam MU_ROLL 0.01\n", 3, 7, {"did you mean 'mu_roll'? (words are lower case)"});
    expect_error("cue 0 0\nball 0 0 0\nrack 9BALL\n", 3, 6, {"did you mean '9ball'?"});
  }
}
