// A game played: the `game` and `player` lines read (and their mistakes located), whole games on
// several seeds checked turn by turn by the independent judge (tests/support/game_judge.h) reading
// events.json alone and by the physics' soak checks, the same game to the byte, written shots judged,
// the shot limit, and the game written as an explicit scene that replays to the same events.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "aim.h"
#include "game.h"
#include "game_judge.h"
#include "number_format.h"
#include "outputs.h"
#include "shot.h"
#include "shot_checks.h"
#include "support.h"

using namespace bsim;

namespace {

/// The first error's message of a scene that must not load, with its line and column.
std::string first_error(const std::string& text, bool strict = false) {
  ParseOptions options;
  options.strict = strict;
  const ShotResult r = load_shot(text, "game", options);
  for (const Diagnostic& d : r.diagnostics)
    if (d.severity == Severity::error)
      return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " + d.message;
  return "";
}

std::unique_ptr<Shot> loaded(const std::string& text) {
  ShotResult r = load_shot(text, "game");
  for (const Diagnostic& d : r.diagnostics) INFO(format_diagnostic(d, "game"));
  REQUIRE(r.shot != nullptr);
  REQUIRE(r.shot->game.has_value());
  return std::move(r.shot);
}

std::string events_json(const Shot& shot) {
  std::ostringstream out;
  write_events_json(shot, out);
  return out.str();
}

}  // namespace

TEST_SUITE("game") {
  TEST_CASE("mistakes in game and player lines are located, and nothing loads") {
    CHECK(first_error("game 9bal\n").starts_with("1:6: expected a game (9ball or 8ball), found '9bal'"));
    CHECK(first_error("game 9bal\n").find("did you mean '9ball'") != std::string::npos);
    CHECK(first_error("game 10ball\n").find("a rack this program has, but not a game it plays") != std::string::npos);
    CHECK(first_error("game 9ball\ngame 8ball\n") ==
          "2:1: a scene is one game, and there is already a 'game' line on line 1");
    CHECK(first_error("game 9ball\nplayer A\nplayer B\nplayer C\n") ==
          "4:1: a game has two players, and they are on lines 2 and 3");
    CHECK(first_error("player A noise -1\ngame 9ball\n").starts_with("1:16: expected the player's noise as 0 or more"));
    CHECK(first_error("game 9ball shots 0\n") == "1:18: expected the game's most shots as 1 or more, found '0'");
    CHECK(first_error("game 9ball seed -2\n") == "1:17: expected a seed of 0 or more, found '-2'");
    CHECK(first_error("game 9ball\n", true) == "1:1: 'game' is an extension that --strict rejects");
    CHECK(first_error("player A\nball 0 0 0\ncue 0 0\nstroke 1 0 0 0\n") ==
          "1:1: a 'player' plays a game, and this scene has no 'game' line (game 9ball, say)");
    CHECK(first_error("game 9ball\nrack 8ball\n").starts_with("2:1: the rack is 8ball and the game (line 1) is 9ball"));
    CHECK(first_error("game 9ball\ncue 3 0\nstroke 1 0 0 0\n") ==
          "2:5: in a game the stick strikes the cue ball, and ball index 3 is the 3");
    CHECK(first_error("ball 0 0 0\nball 1 0.5 0\ncue 0 0 call 1 2\nstroke 1 0 0 0\n") ==
          "3:9: a call is judged by a game's rules, and this scene has no 'game' line");
  }

  TEST_CASE("whole games on several seeds: every turn as the rules say, no physics fault, a winner") {
    for (const char* rules : {"9ball", "8ball"}) {
      for (int seed = 1; seed <= (test::kSanitizedBuild ? 1 : 2); ++seed) {
        CAPTURE(rules);
        CAPTURE(seed);
        const auto shot = loaded(std::string("game ") + rules + " seed " + std::to_string(seed) + "\n");
        const GameRecord& game = *shot->game;
        REQUIRE(game.turns.size() == static_cast<std::size_t>(shot->timeline.shot_count()));
        CHECK(game.turns.front().verdict.break_shot);
        CHECK(game.winner.has_value());
        const std::string json = events_json(*shot);
        const std::vector<test::Dispute> disputes = test::judge_game(json, test::ball_numbers(json));
        CHECK_MESSAGE(disputes.empty(), test::describe(disputes));
        const checks::Faults faults = checks::find_faults(shot->scene, shot->timeline);
        CHECK(faults.total() == 0);
      }
    }
  }

  TEST_CASE("the same scene gives the same game, byte for byte; another seed another game") {
    const std::string a = events_json(*loaded("game 9ball seed 4 shots 6\nplayer Ann noise 2\n"));
    CHECK(events_json(*loaded("game 9ball seed 4 shots 6\nplayer Ann noise 2\n")) == a);
    CHECK(events_json(*loaded("game 9ball seed 5 shots 6\nplayer Ann noise 2\n")) != a);
  }

  TEST_CASE("a written shot is judged by the rules, and the players play on from where it leaves the table") {
    // The break written away from the rack: the cue ball meets no ball, a foul, and ball in hand for Bo.
    const auto shot = loaded("game 9ball seed 2 shots 3\nplayer Ann\nplayer Bo\ncue 0 90\nstroke 0.4 0 0 0\n");
    const GameRecord& game = *shot->game;
    REQUIRE(game.turns.size() >= 2);
    const GameTurn& first = game.turns[0];
    CHECK(first.written);
    CHECK_FALSE(first.verdict.legal);
    CHECK(first.verdict.foul == "the cue ball missed every ball");
    CHECK(first.verdict.in_hand == InHand::anywhere);
    CHECK_FALSE(game.turns[1].written);
    CHECK(game.turns[1].player == 1);
    CHECK(game.players == std::vector<std::string>{"Ann", "Bo"});
  }

  TEST_CASE("a game that reaches its shot limit ends with no winner and says so") {
    const ShotResult r = load_shot("game 9ball seed 3 shots 2\n", "game");
    REQUIRE(r.shot);
    REQUIRE(r.shot->game);
    CHECK(r.shot->game->turns.size() == 2);
    CHECK_FALSE(r.shot->game->winner);
    CHECK(r.shot->game->shot_limit);
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].severity == Severity::warning);
    CHECK(r.diagnostics[0].message ==
          "the game stopped at its limit of 2 shots with no winner; give it more ('game ... shots N') to play it out");
    CHECK(events_json(*r.shot).find("\"winner\": null") != std::string::npos);
  }

  TEST_CASE("a written shot that cannot be played is an error at its line: ball in hand placed on a ball") {
    const std::string head = "game 9ball seed 3 shots 1\ncue 0 0\nstroke 8 0 -0.1 0\n";
    const auto broken = loaded(head);
    const Timeline& t = broken->timeline;
    int up = -1;  // an object ball still on the bed after the break
    for (int b = 1; b < t.ball_count() && up < 0; ++b)
      if (t.motion_state(b, t.duration()).motion != Motion::pocketed) up = b;
    REQUIRE(up > 0);
    const Vec3 at = t.motion_state(up, t.duration()).position;
    const std::string error = first_error(head + "cue 0 90\nstroke 1 0 0 0\nplace 0 " + format_number(at.x()) + " " +
                                          format_number(at.y()) + "\n");
    INFO(error);
    CHECK(error.starts_with("6:1: shot 2 places ball index 0 (the cue ball) at"));
    CHECK(error.find("on " + ball_name(broken->scene, up)) != std::string::npos);
  }

  TEST_CASE("a game's camera keys name its shots, known once it is played") {
    // Shot 4 exists once the game is played; shot 40 does not, and says so at its token.
    const std::string game = "game 9ball seed 3 shots 5\n";
    const auto filmed = loaded(game + "camera\nevent shot 4 cue 0 0 hover 0 -2 2 0 0 0\nendcamera\n");
    CHECK(filmed->camera.has_value());
    CHECK(first_error(game + "camera\nevent shot 40 cue 0 0 hover 0 -2 2 0 0 0\nendcamera\n")
              .starts_with("3:12: shot 40 does not exist: the scene has 5 shots"));
  }
}
