// Several shots in the scene text: `cue` lines in file order, each `stroke` and `place` line belonging
// to the nearest `cue` line above it (spec.md, "Several shots").
#include <doctest/doctest.h>

#include <string>

#include "parse_checks.h"
#include "scene_parse.h"

using namespace bsim;
using bsim::test::expect_error;

namespace {

const std::string kBalls =
    "ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\n"
    "ball 1 0.3 0.1 0.028575 0 0 0 1 0 0 0\n";

}  // namespace

TEST_SUITE("scene text: several shots") {
  TEST_CASE("each cue line is a shot, with the stroke and place lines under it") {
    const ParseResult r = parse_scene(kBalls +
                                          "cue 0 10\nstroke 2 0 0 0\n"
                                          "cue 0 pot 1 2\nstroke 1.5 0.2 -0.1 3\nplace 1 0.5 -0.2\nplace 0\n"
                                          "cue 1 -90\nstroke 1 0 0 0\n",
                                      "t");
    REQUIRE(r.scene.has_value());
    const Scene& s = *r.scene;
    REQUIRE(s.shot_count() == 3);
    CHECK(s.cues[0].heading_deg == 10);
    CHECK(s.cues[0].stroke->speed == 2);
    CHECK(s.cues[0].places.empty());
    CHECK(s.cues[1].aims());
    CHECK(s.cues[1].stroke->side == 0.2);
    CHECK(s.cues[1].stroke->elevation_deg == 3);
    REQUIRE(s.cues[1].places.size() == 2);
    CHECK(s.cues[1].places[0].ball == 1);
    CHECK(s.cues[1].places[0].at->x() == 0.5);
    CHECK(s.cues[1].places[0].at->y() == -0.2);
    CHECK(s.cues[1].places[0].loc.line == 7);
    CHECK(s.cues[1].places[1].ball == 0);
    CHECK_FALSE(s.cues[1].places[1].at.has_value());
    CHECK(s.cues[2].target == 1);
    CHECK(s.cues[2].stroke->speed == 1);
    CHECK(&s.cue() == &s.cues[0]);
  }

  TEST_CASE("a later cue without a stroke, a second stroke for one cue") {
    expect_error(kBalls + "cue 0 0\nstroke 2 0 0 0\ncue 0 90\n", 5, 1,
                 {"expected a 'stroke' line under this cue", "first shot's"});
    expect_error(kBalls + "cue 0 0\nstroke 2 0 0 0\ncue 0 90\nstroke 1 0 0 0\nstroke 1 0 0 0\n", 7, 1,
                 {"the cue on line 5 already has a stroke on line 6"});
  }

  TEST_CASE("--strict rejects a second cue line") {
    ParseOptions strict;
    strict.strict = true;
    expect_error(kBalls + "cue 0 0\ncue 0 90\ncamera\nevent 0 0 0 hover 0 0 3 0 0 0\nendcamera\n", 4, 1,
                 {"several shots", "--strict", "line 3"}, strict);
  }

  TEST_CASE("place: under a later cue, a ball that exists, once per shot, inside the cushions") {
    const std::string two = kBalls + "cue 0 0\nstroke 2 0 0 0\ncue 0 90\nstroke 1 0 0 0\n";
    expect_error(kBalls + "place 0\ncue 0 0\n", 3, 1, {"expected the 'cue' line", "above it"});
    expect_error(kBalls + "cue 0 0\nstroke 2 0 0 0\nplace 1 0 0\n", 5, 1, {"'place' belongs under a later 'cue' line"});
    expect_error(two + "place 7 0 0\n", 7, 7, {"expected the index of the ball to place from 0 to 1"});
    expect_error(two + "place 1 0 0\nplace 1 0.2 0\n", 8, 7, {"already placed for this shot on line 7"});
    expect_error(two + "place 1 1.5 0\n", 7, 9, {"expected the ball inside the cushions"});
    expect_error(two + "place 1 0.2\n", 7, 12, {"expected a number for the place's y", "found end of file"});
    expect_error(two + "place x\n", 7, 7, {"ball to place"});
  }
}
