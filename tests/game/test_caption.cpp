// What a game movie's caption says at each moment: the player at the table, the balls left, the
// referee's calls shown from the moment the shot settles (its balls stopped but for spin in place)
// until the next stroke, the winner to the end, the replay's tag.
#include <doctest/doctest.h>

#include <algorithm>

#include "caption.h"
#include "shot.h"
#include "support.h"

using namespace bsim;

namespace {

std::unique_ptr<Shot> game(const std::string& text) {
  ShotResult r = load_shot(text, "game");
  REQUIRE(r.shot != nullptr);
  REQUIRE(r.shot->game.has_value());
  return std::move(r.shot);
}

Caption at(const Shot& shot, double t, bool replay = false) {
  return caption_at(*shot.game, shot.timeline, shot.scene, t, replay);
}

bool has_call(const Caption& c, CaptionCall::Kind kind) {
  return std::any_of(c.calls.begin(), c.calls.end(), [kind](const CaptionCall& call) { return call.kind == kind; });
}

}  // namespace

TEST_SUITE("caption") {
  TEST_CASE("a written break that misses: the foul and its reason show from its rest to the next stroke") {
    // Ann's break is written away from the rack: the cue ball meets nothing, a foul, ball in hand for Bo.
    const auto shot = game("game 9ball seed 2 shots 3\nplayer Ann\nplayer Bo\ncue 0 90\nstroke 0.4 0 0 0\n");
    const std::vector<ShotSpan>& spans = shot->timeline.shots();
    REQUIRE(spans.size() >= 2);
    REQUIRE(shot->game->turns[0].verdict.foul == "the cue ball missed every ball");

    // Before and during the break: Ann at the table, the whole rack up, no call.
    for (const double t : {0.0, spans[0].cue + 0.1, spans[0].rest - 0.01}) {
      const Caption c = at(*shot, t);
      CAPTURE(t);
      CHECK(c.players == std::vector<std::string>{"Ann", "Bo"});
      CHECK(c.at_table == 0);
      CHECK(c.shot == 0);
      CHECK(c.rack == std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9});
      CHECK(c.on_table == c.rack);
      CHECK(c.calls.empty());
      CHECK_FALSE(c.replay);
    }
    // Once the balls rest the referee calls it, with its reason and ball in hand.
    const Caption called = at(*shot, spans[0].rest);
    REQUIRE(called.calls.size() == 1);
    CHECK(called.calls[0].kind == CaptionCall::Kind::foul);
    CHECK(called.calls[0].title == "FOUL");
    CHECK(called.calls[0].text == "the cue ball missed every ball \xC2\xB7 ball in hand");
    CHECK(called.at_table == 1);  // Bo's shot starts as the balls rest: the table is his
    CHECK(caption_text(called) ==
          "Ann | Bo* | 1 2 3 4 5 6 7 8 9 | FOUL: the cue ball missed every ball \xC2\xB7 "
          "ball in hand");
    // Bo comes to the table: the call stays until his stroke, then goes.
    const Caption next = at(*shot, 0.5 * (spans[1].start + spans[1].cue));
    CHECK(next.at_table == 1);
    CHECK(next.shot == 1);
    CHECK(next.calls == called.calls);
    CHECK(at(*shot, spans[1].cue + 0.01).calls.empty());
  }

  TEST_CASE("balls leave the row as they drop; the winner or the end of the game stays to the end") {
    const auto shot = game("game 9ball seed 3 shots 2\nplayer Ann\nplayer Bo\n");
    const Timeline& t = shot->timeline;
    const GameRecord& record = *shot->game;
    REQUIRE(record.shot_limit);
    // A ball dropping during a shot is off the row from then on.
    for (const PocketDrop& drop : t.pocket_drops()) {
      const int number = shot->scene.balls[static_cast<std::size_t>(drop.ball)].number;
      if (number == 0) continue;
      const auto up = [&](double when) {
        const std::vector<int> on = at(*shot, when).on_table;
        return std::find(on.begin(), on.end(), number) != on.end();
      };
      CAPTURE(number);
      CHECK(up(drop.time - 1e-3));
      CHECK_FALSE(up(drop.time + 1e-3));
    }
    // After the last shot rests the row is the rules' count and the game's end shows, to the end.
    const Caption last = at(*shot, t.duration());
    CHECK(last.on_table == record.turns.back().on_table);
    CHECK(has_call(last, CaptionCall::Kind::stopped));
    CHECK(has_call(at(*shot, t.shots().back().rest), CaptionCall::Kind::stopped));
    CHECK_FALSE(has_call(at(*shot, t.shots().back().rest - 0.01), CaptionCall::Kind::stopped));
  }

  TEST_CASE("the winner is called as the winning shot settles, not after its balls stop spinning") {
    const auto shot = game("game 9ball seed 11\nplayer Ann noise 0\nplayer Bo noise 0\n");
    REQUIRE(shot->game->winner);
    const Timeline& t = shot->timeline;
    const int last = t.shot_count() - 1;
    const double settled = t.settled(last);
    REQUIRE(t.shots().back().rest - settled > 1.0);  // a ball spins on in place for a while
    CHECK_FALSE(has_call(at(*shot, settled - 0.01), CaptionCall::Kind::winner));
    CHECK(has_call(at(*shot, settled), CaptionCall::Kind::winner));
    CHECK(at(*shot, settled).on_table == shot->game->turns.back().on_table);
  }

  TEST_CASE("the replay's ball row is the table at the replayed moment: the 9 is up until it drops again") {
    const auto shot = game("game 9ball seed 11\nplayer Ann noise 0\nplayer Bo noise 0\n");
    REQUIRE(shot->game->winner);
    double drop = -1;
    for (const PocketDrop& d : shot->timeline.pocket_drops())
      if (shot->scene.ball(d.ball).number == 9) drop = d.time;
    REQUIRE(drop > shot->timeline.shots().back().cue);
    const auto nine_up = [](const Caption& c) {
      return std::find(c.on_table.begin(), c.on_table.end(), 9) != c.on_table.end();
    };
    CHECK(nine_up(at(*shot, drop - 0.05, true)));
    CHECK_FALSE(nine_up(at(*shot, drop + 0.05, true)));
    CHECK(has_call(at(*shot, drop - 0.05, true), CaptionCall::Kind::winner));  // the replay names the winner
  }

  TEST_CASE("the replay's frames carry its tag and the winner") {
    const auto shot = game("game 9ball seed 2 shots 3\nplayer Ann\nplayer Bo\ncue 0 90\nstroke 0.4 0 0 0\n");
    GameRecord record = *shot->game;
    record.winner = 1;  // as if Bo had won: the replay of the winning shot names him
    const Caption c = caption_at(record, shot->timeline, shot->scene, shot->timeline.shots()[0].cue + 0.2, true);
    CHECK(c.replay);
    REQUIRE(has_call(c, CaptionCall::Kind::winner));
    CHECK(c.calls.back().text == "Bo wins the game");
    CHECK(caption_text(c).ends_with("WINNER: Bo wins the game | REPLAY"));
  }
}
