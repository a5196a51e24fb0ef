// The table's edge: cushion gaps that no pocket fills are errors at the scene (cushion_gaps.h), and
// the warnings about the ball a `cue` line strikes and a `place` over a pocket.
#include <doctest/doctest.h>

#include <string>

#include "cushion_gaps.h"
#include "parse_checks.h"
#include "scene_parse.h"

using namespace bsim;
using test::all_messages;
using test::expect_error;

namespace {

const std::string kBall0 = "ball 0 0 0 0.028575 1 0 0 1 0 0 0\n";
constexpr double kR = 0.028575;

/// A closed 2 x 1.2 m box of cushions with no gap at all.
const std::string kBox =
    "rail -1 0.6 0.0363 1 0.6 0.0363\nrail 1 0.6 0.0363 1 -0.6 0.0363\n"
    "rail 1 -0.6 0.0363 -1 -0.6 0.0363\nrail -1 -0.6 0.0363 -1 0.6 0.0363\n";

std::vector<CushionGap> gaps(const std::vector<Rail>& rails, const std::vector<Pocket>& pockets, bool& enclosed) {
  return open_cushion_gaps(rails, pockets, kR, enclosed);
}

int error_count(const ParseResult& r) {
  int n = 0;
  for (const Diagnostic& d : r.diagnostics) n += d.severity == Severity::error;
  return n;
}

}  // namespace

TEST_SUITE("the table's edge") {
  TEST_CASE("the standard table is closed: every gap has its pocket") {
    bool enclosed = false;
    CHECK(gaps(standard_rails(), standard_pockets(), enclosed).empty());
    CHECK(enclosed);
  }

  TEST_CASE("without pockets the standard table has six open gaps, each between two neighbouring rails") {
    bool enclosed = false;
    const std::vector<CushionGap> open = gaps(standard_rails(), {}, enclosed);
    CHECK(enclosed);
    REQUIRE(open.size() == 6);
    for (int i = 0; i < 6; ++i) {
      CHECK(open[static_cast<std::size_t>(i)].from_rail == i);
      CHECK(open[static_cast<std::size_t>(i)].to_rail == (i + 1) % 6);
    }
    // The top side gap runs between the jaw points, a side mouth apart.
    const double half = PhysicsParams{}.side_mouth / 2;
    CHECK(open[0].a.isApprox(Vec3(-half, 0.635, 0)));
    CHECK(open[0].b.isApprox(Vec3(half, 0.635, 0)));
  }

  TEST_CASE("a cut pocket's jaws close its gap; moved off the rails' ends they no longer do") {
    bool enclosed = false;
    std::vector<Pocket> pockets = standard_pockets();
    CHECK(gaps(standard_rails(), pockets, enclosed).empty());
    pockets[1].jaw[0].x() += 0.01;
    const std::vector<CushionGap> open = gaps(standard_rails(), pockets, enclosed);
    REQUIRE(open.size() == 1);
    CHECK(open[0].from_rail == 0);
  }

  TEST_CASE("a bare pocket fills a gap only when its circle covers all of the ball's passage") {
    bool enclosed = false;
    std::vector<Pocket> pockets = bare_standard_pockets();
    CHECK(gaps(standard_rails(), pockets, enclosed).empty());
    // The side pocket's circle shrunk below the passage's half width (0.0643 less a reach, 0.0368 m):
    // a ball rolls past its edge.
    pockets[1].radius = 0.03;
    std::vector<CushionGap> open = gaps(standard_rails(), pockets, enclosed);
    REQUIRE(open.size() == 1);
    CHECK(open[0].from_rail == 0);
    // Just wide enough again.
    pockets[1].radius = 0.038;
    CHECK(gaps(standard_rails(), pockets, enclosed).empty());
    // Two small circles side by side cover it together.
    pockets[1].radius = 0.02;
    pockets.push_back({Vec3(-0.02, 0.635, 0), 0.021, {}});
    pockets.push_back({Vec3(0.02, 0.635, 0), 0.021, {}});
    CHECK(gaps(standard_rails(), pockets, enclosed).empty());
  }

  TEST_CASE("a gap narrower than a ball needs no pocket") {
    bool enclosed = false;
    std::vector<Rail> rails = standard_rails();
    // Rails 0 and 1 brought to 5 cm apart: a ball 5.7 cm across cannot pass (its reach is 2.75 cm).
    rails[0].b.x() = -0.025;
    rails[1].a.x() = 0.025;
    std::vector<Pocket> pockets = standard_pockets();
    pockets.erase(pockets.begin() + 1);
    CHECK(gaps(rails, pockets, enclosed).empty());
    rails[1].a.x() = 0.04;
    CHECK(gaps(rails, pockets, enclosed).size() == 1);
  }

  TEST_CASE("a free-standing cushion on the bed is an obstacle, not the table's edge") {
    bool enclosed = false;
    std::vector<Rail> rails = standard_rails();
    rails.push_back({Vec3(-0.7, -0.5, 0.0363), Vec3(-0.7, 0.5, 0.0363), {}});
    CHECK(gaps(rails, standard_pockets(), enclosed).empty());
    CHECK(enclosed);
    // Alone, it encloses nothing.
    CHECK(gaps({rails.back()}, {}, enclosed).empty());
    CHECK_FALSE(enclosed);
  }

  TEST_CASE("a cushion whose nose stands at a ball's diameter lets balls under it") {
    CHECK(nose_reach(kR, 2 * kR) == 0);
    CHECK(nose_reach(kR, 0) == 0);
    CHECK(nose_reach(kR, kR) == doctest::Approx(kR));
    bool enclosed = false;
    std::vector<Rail> rails = standard_rails();
    rails[2].a.z() = rails[2].b.z() = 0.06;
    const std::vector<CushionGap> open = gaps(rails, standard_pockets(), enclosed);
    REQUIRE(open.size() == 1);
    CHECK(open[0].under);
    CHECK(open[0].from_rail == 2);
  }

  TEST_CASE("the issue's scene: its own corner pocket keeps the standard cushions' other five gaps open") {
    const ParseResult r = parse_scene("cue 0 0\n" + kBall0 + "pocket 1.27 0.635 0 0.08\n", "t");
    INFO(all_messages(r));
    CHECK_FALSE(r.scene);
    CHECK(error_count(r) == 5);
    for (const Diagnostic& d : r.diagnostics) {
      CHECK(d.loc.line == 3);
      CHECK(d.message.find("of the standard table") != std::string::npos);
      CHECK(d.message.find("replace all six of the standard table's") != std::string::npos);
    }
    expect_error(
        "cue 0 0\n" + kBall0 + "pocket 1.27 0.635 0 0.08\n", 3, 1,
        {"the gap between rails 0 and 1 of the standard table, from (-0.0642937, 0.635) to (0.0642937, 0.635), "
         "has no pocket: a ball (radius 0.028575) passes through it off the table",
         "add a `pocket` line there, such as `pocket 0 0.635 0 0.0642937`"});
  }

  TEST_CASE("a scene's own rails: the error is at the rail whose end opens the gap") {
    // Two long cushions with nothing across the ends.
    const std::string two = "rail -1 0.6 0.0363 1 0.6 0.0363\nrail 1 -0.6 0.0363 -1 -0.6 0.0363\n";
    expect_error(
        "cue 0 0\n" + kBall0 + two, 3, 1,
        {"the gap between rails 0 and 1, from (1, 0.6) to (1, -0.6), has no pocket", "such as `pocket 1 0 0 0.6`"});
    // A closed box, and the box with a pocket in a gap cut into it.
    const ParseResult closed = parse_scene("cue 0 0\n" + kBall0 + kBox, "t");
    CHECK_MESSAGE(closed.diagnostics.empty(), all_messages(closed));
    const std::string cut =
        "rail -1 0.6 0.0363 -0.1 0.6 0.0363\nrail 0.1 0.6 0.0363 1 0.6 0.0363\nrail 1 0.6 0.0363 1 -0.6 0.0363\n"
        "rail 1 -0.6 0.0363 -1 -0.6 0.0363\nrail -1 -0.6 0.0363 -1 0.6 0.0363\n";
    expect_error("cue 0 0\n" + kBall0 + cut, 3, 1, {"the gap between rails 0 and 1", "`pocket 0 0.6 0 0.1`"});
    const ParseResult filled = parse_scene("cue 0 0\n" + kBall0 + cut + "pocket 0 0.6 0 0.1\n", "t");
    CHECK_MESSAGE(filled.diagnostics.empty(), all_messages(filled));
  }

  TEST_CASE("a lone cushion does not close round the bed") {
    expect_error("cue 0 0\n" + kBall0 + "rail -1 0.6 0.0363 1 0.6 0.0363\n", 3, 1,
                 {"the cushions do not close round the bed"});
  }

  TEST_CASE("a cushion too high to stop a ball") {
    // param ball_radius applies wherever it is written: small balls roll under the standard noses.
    expect_error("cue 0 0\nball 0 0 0 0.015 1 0 0 1 0 0 0\nparam ball_radius 0.015\n", 2, 1,
                 {"rail 0 of the standard table has its nose at z = 0.0363", "rolls under it off the table"});
  }
}

TEST_SUITE("the ball a cue strikes") {
  TEST_CASE("a cue line striking a numbered ball while the cue ball is elsewhere: a warning naming its index") {
    const ParseResult r = parse_scene("rack 9ball\nball 0 -0.635 0 0.028575 1 0 0 1 0 0 0\ncue 0 0\n", "t");
    INFO(all_messages(r));
    REQUIRE(r.scene);
    REQUIRE(r.diagnostics.size() == 2);  // and the struck ball has no velocity
    const Diagnostic& d = r.diagnostics[0];
    CHECK(d.severity == Severity::warning);
    CHECK(d.loc.line == 3);
    CHECK(d.loc.column == 5);
    CHECK(d.message ==
          "the cue strikes ball index 0, the 1, not the cue ball; the cue ball (painted 0) is ball index 9 (indices "
          "count the `ball` lines and a `rack` line's balls in file order)");
  }

  TEST_CASE("the cue ball struck, or no cue ball in the scene: no warning") {
    CHECK(parse_scene("ball 0 -0.635 0 0.028575 1 0 0 1 0 0 0\nrack 9ball\ncue 0 0\n", "t").diagnostics.empty());
    CHECK(parse_scene("ball 3 -0.635 0 0.028575 1 0 0 1 0 0 0\ncue 0 0\n", "t").diagnostics.empty());
  }

  TEST_CASE("every shot's cue line is checked") {
    const ParseResult r = parse_scene(
        "ball 0 -0.635 0 0.028575 0 0 0 1 0 0 0\nball 1 0.3 0 0.028575 0 0 0 1 0 0 0\ncue 0 0\nstroke 1 0 0 0\n"
        "cue 1 0\nstroke 1 0 0 0\n",
        "t");
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].loc.line == 5);
    CHECK(r.diagnostics[0].message.find("the cue ball (painted 0) is ball index 0") != std::string::npos);
  }
}

TEST_SUITE("a place over a pocket") {
  TEST_CASE("the same warning at the place line as at a ball line") {
    const std::string shots =
        "ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\ncue 0 0\nstroke 1 0 0 0\ncue 0 0\nstroke 1 0 0 0\n";
    const ParseResult placed = parse_scene(shots + "place 0 1.265 0.63\n", "t");
    const ParseResult ball = parse_scene("ball 0 1.265 0.63 0.028575 0 0 0 1 0 0 0\ncue 0 0\nstroke 1 0 0 0\n", "t");
    REQUIRE(placed.diagnostics.size() == 1);
    REQUIRE(ball.diagnostics.size() == 1);
    CHECK(placed.diagnostics[0].severity == Severity::warning);
    CHECK(placed.diagnostics[0].loc.line == 6);
    CHECK(placed.diagnostics[0].loc.column == 9);
    CHECK(placed.diagnostics[0].message == ball.diagnostics[0].message);
    CHECK(ball.diagnostics[0].message.find("starts over the top-right corner (pocket 2)") != std::string::npos);
  }
}
