// The `rack` extension: the racking model (core/scene/rack.h) and the rack line in a scene, its
// indices, and every way a rack line can be wrong.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "parse_checks.h"
#include "rack.h"
#include "scene_parse.h"

using namespace bsim;

namespace {

constexpr double kR = 0.028575;  // the physics' nominal radius: 2 1/4 in

/// The cue ball on the head spot, struck toward the rack.
const std::string kCue = "cue 0 0\nball 0 -0.635 0 0.028575  10.7 0 0  1 0 0 0\n";

using test::all_messages;
using test::expect_error;

Scene parse_ok(const std::string& text) {
  ParseResult r = parse_scene(text, "t");
  INFO("scene:\n" << text << "diagnostics:\n" << all_messages(r));
  REQUIRE(r.scene.has_value());
  CHECK(r.diagnostics.empty());
  return *r.scene;
}

double gap(const RackedBall& a, const RackedBall& b) { return std::hypot(a.x - b.x, a.y - b.y) - 2 * kR; }

const RackedBall& at(const std::vector<RackedBall>& rack, int row, int column) {
  const auto found =
      std::find_if(rack.begin(), rack.end(), [&](const RackedBall& b) { return b.row == row && b.column == column; });
  REQUIRE(found != rack.end());
  return *found;
}

/// Neighbours in the perfect rack: the same row, next columns, or the rows next to each other with
/// centres under 2.5 radii apart.
bool neighbours(const RackedBall& a, const RackedBall& b) {
  return std::abs(a.row - b.row) <= 1 && std::hypot(a.x - b.x, a.y - b.y) < 2.5 * kR && a.number != b.number;
}

RackSpec spec(RackGame game, std::uint64_t seed, bool tight = false) {
  RackSpec s;
  s.game = game;
  s.seed = seed;
  s.tight = tight;
  return s;
}

constexpr RackGame kGames[] = {RackGame::eight_ball, RackGame::nine_ball, RackGame::ten_ball};

}  // namespace

TEST_SUITE("rack") {
  TEST_CASE("splitmix64 gives Vigna's reference outputs") {
    // Oracle: splitmix64.c (Vigna, prng.di.unimi.it) seeded with 0: its first outputs.
    SplitMix64 random(0);
    CHECK(random.next() == 0xE220A8397B1DCDAFull);
    CHECK(random.next() == 0x6E789E6AA1B965F4ull);
    CHECK(random.next() == 0x06C45D188009454Full);
  }

  TEST_CASE("no two balls overlap at the nominal radius, and neighbours leave real gaps") {
    // WPA: diameters 2.25 in +- 0.005 in, so a racked set cannot all touch: neighbour gaps of a few
    // tens of micrometres typically (up to the tolerance, 0.254 mm, and a little more where gaps add
    // up toward the back), never an overlap.
    for (RackGame game : kGames) {
      std::vector<double> gaps;
      for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const std::vector<RackedBall> rack = rack_balls(spec(game, seed));
        REQUIRE(static_cast<int>(rack.size()) == rack_ball_count(game));
        for (std::size_t i = 0; i < rack.size(); ++i) {
          CHECK(std::abs(rack[i].diameter - 2 * kR) <= 0.005 * 0.0254 + 1e-15);
          for (std::size_t j = i + 1; j < rack.size(); ++j) {
            CHECK(gap(rack[i], rack[j]) >= -1e-12);
            if (neighbours(rack[i], rack[j])) gaps.push_back(gap(rack[i], rack[j]));
          }
        }
      }
      std::sort(gaps.begin(), gaps.end());
      const double median = gaps[gaps.size() / 2], p90 = gaps[gaps.size() * 9 / 10];
      INFO(rack_game_name(game) << ": median gap " << median << " m, 90th percentile " << p90 << ", largest "
                                << gaps.back());
      CHECK(median > 5e-6);
      CHECK(median < 100e-6);
      CHECK(p90 > 50e-6);
      CHECK(p90 < 300e-6);
      CHECK(gaps.back() < 1e-3);
    }
  }

  TEST_CASE("every ball rests on two others or a ball and the frame: the rack is pushed together") {
    // Each ball but the apex touches at least one ball of its row or the row nearer the apex: its centre
    // within 1 nm of the contact distance, the two drawn radii (never under two nominal radii).
    for (RackGame game : kGames)
      for (std::uint64_t seed = 0; seed < 10; ++seed) {
        const std::vector<RackedBall> rack = rack_balls(spec(game, seed));
        for (const RackedBall& b : rack) {
          if (b.row == 0) continue;
          const bool rests = std::any_of(rack.begin(), rack.end(), [&](const RackedBall& other) {
            const double contact = std::max(2 * kR, (b.diameter + other.diameter) / 2);
            return other.row <= b.row && neighbours(b, other) &&
                   std::hypot(b.x - other.x, b.y - other.y) - contact < 1e-9;
          });
          CHECK(rests);
        }
      }
  }

  TEST_CASE("the same seed gives the same rack to the bit, another seed another rack") {
    for (RackGame game : kGames) {
      const std::vector<RackedBall> a = rack_balls(spec(game, 7)), b = rack_balls(spec(game, 7));
      const std::vector<RackedBall> c = rack_balls(spec(game, 8));
      REQUIRE(a.size() == b.size());
      bool moved = false, reordered = false;
      for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(std::memcmp(&a[i].x, &b[i].x, sizeof(double)) == 0);
        CHECK(std::memcmp(&a[i].y, &b[i].y, sizeof(double)) == 0);
        CHECK(a[i].row == b[i].row);
        CHECK(a[i].column == b[i].column);
        moved = moved || a[i].x != c[i].x || a[i].y != c[i].y;
        reordered = reordered || a[i].row != c[i].row || a[i].column != c[i].column;
      }
      CHECK(moved);
      CHECK(reordered);
    }
  }

  TEST_CASE("a fixed seed keeps its rack (the random stream and the settling do not drift)") {
    // Oracle: the values this model gave when written; the same on every platform (splitmix64 and
    // IEEE +, -, *, /, sqrt only).
    const std::vector<RackedBall> rack = rack_balls(spec(RackGame::nine_ball, 0));
    CHECK(rack[0].x == 0.635);
    CHECK(rack[0].y == 0.0);
    CHECK(rack[8].number == 9);
    CHECK(rack[8].row == 2);
    CHECK(rack[8].column == 1);
    CHECK(rack[3].row == 4);  // the 4 at the back of the diamond
    CHECK(rack[3].x == 0x1.aa9568bc39fe6p-1);
    CHECK(rack[3].y == -0x1.2f2ae62502483p-13);
    CHECK(rack[8].x == 0x1.77dd7361ef011p-1);
    CHECK(rack[8].y == 0x1.0562ea823095cp-17);
  }

  TEST_CASE("tight is the mathematical rack: every neighbour exactly touching") {
    for (RackGame game : kGames) {
      const std::vector<RackedBall> rack = rack_balls(spec(game, 3, true));
      int touching = 0;
      for (std::size_t i = 0; i < rack.size(); ++i) {
        CHECK(rack[i].diameter == 2 * kR);
        CHECK(rack[i].x == doctest::Approx(0.635 + rack[i].row * std::sqrt(3.0) * kR).epsilon(1e-14));
        for (std::size_t j = i + 1; j < rack.size(); ++j) {
          CHECK(gap(rack[i], rack[j]) >= -1e-15);
          if (neighbours(rack[i], rack[j])) {
            CHECK(std::abs(gap(rack[i], rack[j])) < 1e-15);
            ++touching;
          }
        }
      }
      // Contacts in the perfect rack: a triangle of n rows has 3n(n-1)/2; the diamond 16.
      const int expected = game == RackGame::eight_ball ? 30 : game == RackGame::ten_ball ? 18 : 16;
      CHECK(touching == expected);
    }
  }

  TEST_CASE("the games' rules say where balls go, the seed the rest") {
    // WPA racking rules: 8-ball the 8 in the middle of the third row, a stripe and a solid in the
    // back corners; 9-ball a diamond, the 1 at the apex and the 9 in the middle; 10-ball the 1 at the
    // apex and the 10 in the middle of the third row.
    int stripe_left = 0;
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      const std::vector<RackedBall> eight = rack_balls(spec(RackGame::eight_ball, seed));
      CHECK(at(eight, 2, 1).number == 8);
      const int left = at(eight, 4, 0).number, right = at(eight, 4, 4).number;
      CHECK(((left < 8 && right > 8) || (left > 8 && right < 8)));
      stripe_left += left > 8 ? 1 : 0;
      const std::vector<RackedBall> nine = rack_balls(spec(RackGame::nine_ball, seed));
      CHECK(at(nine, 0, 0).number == 1);
      CHECK(at(nine, 2, 1).number == 9);
      CHECK(at(nine, 4, 0).x > at(nine, 2, 1).x);  // a diamond: one ball in the back row
      const std::vector<RackedBall> ten = rack_balls(spec(RackGame::ten_ball, seed));
      CHECK(at(ten, 0, 0).number == 1);
      CHECK(at(ten, 2, 1).number == 10);
    }
    CHECK(stripe_left > 5);  // the seed picks the corner
    CHECK(stripe_left < 35);
  }

  TEST_CASE("the apex ball sits on the foot spot and the rack opens toward the foot rail") {
    for (RackGame game : kGames) {
      const std::vector<RackedBall> rack = rack_balls(spec(game, 11));
      CHECK(at(rack, 0, 0).x == 0.635);
      CHECK(at(rack, 0, 0).y == 0.0);
      for (const RackedBall& b : rack) CHECK(b.x >= 0.635);
    }
  }
}

TEST_SUITE("rack line") {
  TEST_CASE("the rack's balls take file indices at its place, by painted number: index k is ball k") {
    const Scene scene = parse_ok(kCue + "rack 8ball seed 5\n");
    REQUIRE(scene.balls.size() == 16);
    for (int k = 0; k < 16; ++k) {
      CHECK(scene.ball(k).number == k);
      CHECK(scene.ball(k).position.z() == kR);
      if (k > 0) CHECK(scene.ball(k).velocity == Vec3(0, 0, 0));
    }
    const std::vector<RackedBall> rack = rack_balls(spec(RackGame::eight_ball, 5));
    for (int k = 1; k < 16; ++k) {
      CHECK(scene.ball(k).position.x() == rack[static_cast<std::size_t>(k - 1)].x);
      CHECK(scene.ball(k).position.y() == rack[static_cast<std::size_t>(k - 1)].y);
      CHECK(scene.ball(k).loc.line == 3);
    }
  }

  TEST_CASE("balls after the rack line come after its balls; spin counts the rack's indices") {
    const Scene scene = parse_ok(
        "cue 9 0\nrack 9ball tight\nball 0 -0.635 0 0.028575  10.7 0 0  1 0 0 0\nball 12 -0.6 0.5 0.028575 0 0 0 1 0 0 "
        "0\nspin 10 0 0 5\n");
    REQUIRE(scene.balls.size() == 11);
    for (int k = 0; k < 9; ++k) CHECK(scene.ball(k).number == k + 1);
    CHECK(scene.ball(9).number == 0);
    CHECK(scene.ball(10).number == 12);
    CHECK(scene.ball(10).spin == Vec3(0, 0, 5));
  }

  TEST_CASE("the seed defaults to 0 and options come in any order") {
    const Scene a = parse_ok(kCue + "rack 10ball\n");
    const Scene b = parse_ok(kCue + "rack 10ball seed 0\n");
    const Scene c = parse_ok(kCue + "rack 10ball tight seed 4\n");
    const Scene d = parse_ok(kCue + "rack 10ball seed 4 tight\n");
    for (int k = 1; k <= 10; ++k) {
      CHECK(a.ball(k).position == b.ball(k).position);
      CHECK(c.ball(k).position == d.ball(k).position);
    }
  }

  TEST_CASE("the rack follows param ball_radius wherever it appears") {
    const Scene scene =
        parse_ok("cue 15 0\nrack 8ball tight\nball 0 -0.635 0 0.03 10 0 0 1 0 0 0\nparam ball_radius 0.03\n");
    CHECK(scene.ball(0).position.z() == 0.03);
    double closest = 1;
    for (int i = 0; i < 15; ++i)
      for (int j = i + 1; j < 15; ++j)
        closest = std::min(closest, (scene.ball(i).position - scene.ball(j).position).norm());
    CHECK(closest == doctest::Approx(0.06).epsilon(1e-12));
  }
}

TEST_SUITE("rack line: errors") {
  TEST_CASE("an unknown game") {
    expect_error(kCue + "rack 7ball\n", 3, 6, {"expected a game (8ball, 9ball or 10ball)", "'7ball'", "'8ball'"});
    expect_error(kCue + "rack\n", 3, 5, {"expected a game", "end of file"});
  }

  TEST_CASE("a bad seed") {
    expect_error(kCue + "rack 9ball seed -1\n", 3, 17, {"seed of 0 or more", "'-1'"});
    expect_error(kCue + "rack 9ball seed x\n", 3, 17, {"integer", "seed", "'x'"});
    expect_error(kCue + "rack 9ball seed 1 seed 2\n", 3, 24, {"already"});
  }

  TEST_CASE("a ball line painting a number the rack holds, either way round") {
    expect_error(kCue + "rack 9ball\nball 9 0 0.5 0.028575 0 0 0 1 0 0 0\n", 4, 6,
                 {"ball number 9", "9ball rack on line 3"});
    expect_error(kCue + "ball 4 0 0.5 0.028575 0 0 0 1 0 0 0\nrack 8ball\n", 4, 6,
                 {"8ball rack holds ball 4", "ball on line 3"});
    // The 10 is no 9-ball ball: it may stand beside a 9-ball rack.
    parse_ok(kCue + "rack 9ball\nball 10 0 0.5 0.028575 0 0 0 1 0 0 0\n");
  }

  TEST_CASE("two racks") {
    expect_error(kCue + "rack 9ball\nrack 10ball seed 2\n", 4, 1, {"one rack", "already one on line 3"});
  }

  TEST_CASE("a rack that does not fit inside the cushions") {
    // The foot cushion at x = 0.8: the 8-ball rack's back row (0.635 + 4 sqrt(3) R = 0.833) is behind it.
    const std::string table =
        "rail -1 -0.6 0.03 -1 0.6 0.03\nrail -1 0.6 0.03 0.8 0.6 0.03\nrail 0.8 0.6 0.03 0.8 -0.6 0.03\n"
        "rail 0.8 -0.6 0.03 -1 -0.6 0.03\n";
    expect_error(kCue + "rack 8ball\n" + table, 3, 1, {"8ball rack does not fit inside the cushions", "ball "});
    // The 9-ball diamond reaches to 0.635 + 4 sqrt(3) R + R as well; the 10-ball triangle only to
    // 0.635 + 3 sqrt(3) R + R = 0.812.
    expect_error(kCue + "rack 9ball tight\n" + table, 3, 1, {"9ball rack does not fit"});
    expect_error(kCue + "rack 10ball\n" + table, 3, 1, {"10ball rack does not fit"});
    parse_ok(kCue + "rack 10ball\n" + "rail -1 -0.6 0.03 -1 0.6 0.03\nrail -1 0.6 0.03 0.9 0.6 0.03\n" +
             "rail 0.9 0.6 0.03 0.9 -0.6 0.03\nrail 0.9 -0.6 0.03 -1 -0.6 0.03\n");
    expect_error(kCue + "rack 8ball\nparam ball_radius 1e300\n", 3, 1, {"8ball rack does not fit"});
  }

  TEST_CASE("--strict rejects the rack") {
    ParseOptions strict;
    strict.strict = true;
    expect_error(kCue + "rack 8ball\n", 3, 1, {"'rack' is an extension that --strict rejects"}, strict);
  }

  TEST_CASE("a ball line on the rack's place overlaps it, reported at the later line") {
    expect_error(kCue + "rack 9ball\nball 12 0.64 0 0.028575 0 0 0 1 0 0 0\n", 4, 1, {"overlaps ball 1"});
  }
}
