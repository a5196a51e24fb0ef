// The `stroke` line (spec.md "Stroke"): its values, its checks located at the token at fault, and the
// stick's params.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "fixtures.h"
#include "parse_checks.h"
#include "scene_parse.h"

using namespace bsim;

namespace {

const std::string kStill0 = "ball 0 0 0 0.028575 0 0 0 1 0 0 0\n";

using test::expect_error;
std::string messages(const ParseResult& r) { return test::all_messages(r); }

}  // namespace

TEST_SUITE("stroke: parsing") {
  TEST_CASE("a stroke attaches to the cue line above it, with its four values") {
    const ParseResult r = parse_scene("cue 0 90\nstroke 2.5 -0.1 0.3 12\n" + kStill0, "t");
    INFO(messages(r));
    REQUIRE(r.scene.has_value());
    CHECK(r.diagnostics.empty());  // no "stick will not move it" warning: the stroke moves it
    REQUIRE(r.scene->cue().stroke.has_value());
    const Stroke& s = *r.scene->cue().stroke;
    CHECK(s.speed == 2.5);
    CHECK(s.side == -0.1);
    CHECK(s.height == 0.3);
    CHECK(s.elevation_deg == 12);
    CHECK(s.loc.line == 2);
    CHECK(s.loc.column == 1);
  }

  TEST_CASE("the seed's velocity form has no stroke") {
    const ParseResult r = parse_scene("cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\n", "t");
    REQUIRE(r.scene.has_value());
    CHECK_FALSE(r.scene->cue().stroke.has_value());
  }

  TEST_CASE("the stick's params, with their defaults") {
    const ParseResult plain = parse_scene("cue 0 0\nstroke 1 0 0 0\n" + kStill0, "t");
    REQUIRE(plain.scene.has_value());
    CHECK(plain.scene->physics.cue_mass == 0.54);
    CHECK(plain.scene->physics.e_tip == 0.75);
    CHECK(plain.scene->physics.cue_end_mass == 0.0057);
    const ParseResult set = parse_scene(
        "cue 0 0\nstroke 1 0 0 0\n" + kStill0 + "param cue_mass 0.6\nparam e_tip 0.85\nparam cue_end_mass 0\n", "t");
    REQUIRE(set.scene.has_value());
    CHECK(set.scene->physics.cue_mass == 0.6);
    CHECK(set.scene->physics.e_tip == 0.85);
    CHECK(set.scene->physics.cue_end_mass == 0);
  }
}

TEST_SUITE("stroke: errors") {
  TEST_CASE("speed above 0 and at most 15 m/s") {
    expect_error("cue 0 0\nstroke 0 0 0 0\n" + kStill0, 2, 8, "expected a stroke speed greater than 0");
    expect_error("cue 0 0\nstroke -1 0 0 0\n" + kStill0, 2, 8, "found '-1'");
    expect_error("cue 0 0\nstroke 15.5 0 0 0\n" + kStill0, 2, 8, "at most 15 m/s, found '15.5'");
    CHECK(parse_scene("cue 0 0\nstroke 15 0 0 0\n" + kStill0, "t").scene.has_value());
  }

  TEST_CASE("elevation from 0 up to, not including, 90 degrees") {
    expect_error("cue 0 0\nstroke 1 0 0 90\n" + kStill0, 2, 14, "below 90 degrees, found '90'");
    expect_error("cue 0 0\nstroke 1 0 0 -5\n" + kStill0, 2, 14, "at least 0");
    CHECK(parse_scene("cue 0 0\nstroke 1 0 0 89.9\n" + kStill0, "t").scene.has_value());
  }

  TEST_CASE("a tip further than 0.5 R from centre miscues") {
    // Alciatore, "How High or Low Should You Hit the Cue Ball?": 0.5 R is the accepted limit.
    expect_error("cue 0 0\nstroke 1 0.4 0.4 0\n" + kStill0, 2, 10, "miscue");
    expect_error("cue 0 0\nstroke 1 0 -0.6 0\n" + kStill0, 2, 10, "expected at most 0.5");
    CHECK(parse_scene("cue 0 0\nstroke 1 0.3 -0.4 0\n" + kStill0, "t").scene.has_value());
  }

  TEST_CASE("non-numbers") {
    expect_error("cue 0 0\nstroke fast 0 0 0\n" + kStill0, 2, 8, "expected a number for the stroke's speed");
    expect_error("cue 0 0\nstroke 1 left 0 0\n" + kStill0, 2, 10, "expected a number for the stroke's side");
    expect_error("cue 0 0\nstroke 1 0 nan 0\n" + kStill0, 2, 12, "finite number for the stroke's height");
    expect_error("cue 0 0\nstroke 1 0 0\n" + kStill0, 2, 13, "expected a number for the stroke's elevation");
  }

  TEST_CASE("the struck ball's lines give it no velocity and no spin") {
    expect_error("cue 0 0\nstroke 1 0 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\n", 2, 1,
                 "expected velocity 0 0 0 on its ball line (line 3), found 1 0 0");
    expect_error("cue 0 0\nstroke 1 0 0 0\n" + kStill0 + "spin 0 0 0 5\n", 2, 1,
                 "expected no 'spin' line for it, found one (line 4)");
    // Other balls may still move and spin.
    CHECK(
        parse_scene("cue 0 0\nstroke 1 0 0 0\n" + kStill0 + "ball 1 0.5 0 0.028575 0 1 0 1 0 0 0\nspin 1 0 0 3\n", "t")
            .scene.has_value());
  }

  TEST_CASE("a stroke needs a cue line above it, once") {
    expect_error("stroke 1 0 0 0\ncue 0 0\n" + kStill0, 1, 1, "expected the 'cue' line this stroke strikes with");
    expect_error("cue 0 0\nstroke 1 0 0 0\nstroke 2 0 0 0\n" + kStill0, 3, 1, "already has a stroke on line 2");
  }

  TEST_CASE("the stick's params out of range") {
    expect_error("cue 0 0\nstroke 1 0 0 0\n" + kStill0 + "param cue_mass 0\n", 4, 16, "greater than 0");
    expect_error("cue 0 0\nstroke 1 0 0 0\n" + kStill0 + "param e_tip 1.2\n", 4, 13, "from 0 to 1");
    expect_error("cue 0 0\nstroke 1 0 0 0\n" + kStill0 + "param cue_end_mass -0.01\n", 4, 20, "at least 0");
  }

  TEST_CASE("--strict rejects the extension") {
    const ParseOptions strict{.strict = true};
    expect_error("cue 0 0\nstroke 1 0 0 0\n" + kStill0 + test::fixtures::kHoverCamera, 2, 1,
                 "'stroke' is an extension that --strict rejects", strict);
  }
}
