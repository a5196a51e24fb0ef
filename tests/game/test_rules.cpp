// The rules of 9-ball and 8-ball (rules.h): a shot's facts read from a hand-made event log, and the
// verdicts of the WPA rules on shots built the same way.
#include <doctest/doctest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rules.h"

using namespace bsim;

namespace {

/// A timeline's events and drops written by hand. The scene's balls are in file order with the object
/// balls in descending painted number and the cue ball last, so a file index is never the ball's
/// painted number (for an odd count of object balls). Every call names balls by painted number; each event comes 0.01 s
/// after the one before unless `at` says when.
class Log {
 public:
  explicit Log(int object_balls = 15) {
    for (int n = object_balls; n >= 0; --n) balls_.push_back(ball(n));
  }
  /// The next event happens at `time` exactly.
  Log& at(double time) {
    at_ = time;
    return *this;
  }
  /// A new shot: its strike (the first is shot 0).
  Log& cue() {
    t_ += 1;
    ++shot_;
    events_.push_back(event(EventType::cue, {index(0)}));
    return *this;
  }
  Log& hit(int a, int b) { return group({{a, b}}, false); }
  /// A ball-ball event: its contacts (painted numbers) in the order they began, 0.001 s apart.
  Log& group(const std::vector<std::pair<int, int>>& contacts, bool grouped = true) {
    Event e = event(EventType::ball_ball, {});
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      const auto& [a, b] = contacts[k];
      const int i = std::min(index(a), index(b)), j = std::max(index(a), index(b));
      e.contacts.push_back(Contact{i, j, e.time + static_cast<double>(k) * 0.001, 1, {0, 0, 0}});
      for (int n : {i, j})
        if (std::find(e.balls.begin(), e.balls.end(), n) == e.balls.end()) e.balls.push_back(n);
    }
    std::sort(e.balls.begin(), e.balls.end());
    e.grouped = grouped;
    events_.push_back(e);
    t_ = e.contacts.back().time;
    return *this;
  }
  Log& rail(int n) {
    events_.push_back(event(EventType::ball_rail, {index(n)}));
    return *this;
  }
  Log& jaw(int n) {
    events_.push_back(event(EventType::ball_jaw, {index(n)}));
    return *this;
  }
  Log& drop(int n, int pocket) {
    t_ += 0.01;
    drops_.push_back(PocketDrop{t_, index(n), pocket});
    return *this;
  }
  ShotFacts facts() const { return facts(shot_); }
  ShotFacts facts(int shot) const { return shot_facts(events_, drops_, balls_, shot); }

 private:
  int index(int number) const {
    for (std::size_t i = 0; i < balls_.size(); ++i)
      if (balls_[i].number == number) return static_cast<int>(i);
    FAIL("no ball " << number);
    return -1;
  }
  static Ball ball(int number) {
    Ball b;
    b.number = number;
    return b;
  }
  Event event(EventType type, std::vector<int> balls) {
    t_ = at_ ? *at_ : t_ + 0.01;
    at_.reset();
    Event e;
    e.index = static_cast<int>(events_.size()) + 1;
    e.time = t_;
    e.type = type;
    e.balls = std::move(balls);
    e.shot = shot_;
    return e;
  }

  std::vector<Ball> balls_;
  std::vector<Event> events_;
  std::vector<PocketDrop> drops_;
  double t_ = 0;
  std::optional<double> at_;
  int shot_ = -1;
};

/// A shot of its own: a fresh log's first strike.
Log shot() { return std::move(Log().cue()); }

ShotCall called(int ball, int pocket) { return ShotCall{ball, pocket, false, false}; }
ShotCall push_out() { return ShotCall{-1, -1, false, true}; }
ShotCall safety() { return ShotCall{-1, -1, true, false}; }

TurnVerdict play(GameRules& rules, const Log& log, const ShotCall& call = {}) { return rules.judge(log.facts(), call); }

std::vector<int> numbers(int from, int to) {
  std::vector<int> out;
  for (int n = from; n <= to; ++n) out.push_back(n);
  return out;
}

GameRules nine() { return GameRules(RackGame::nine_ball, numbers(1, 9)); }
GameRules eight() { return GameRules(RackGame::eight_ball, numbers(1, 15)); }

/// 9-ball after a legal break that made nothing (four balls to a cushion): player 1 at the table.
GameRules nine_broken() {
  GameRules rules = nine();
  const TurnVerdict v = play(rules, shot().hit(0, 1).rail(1).rail(2).rail(3).rail(4));
  REQUIRE(v.legal);
  REQUIRE(rules.next().shooter == 1);
  return rules;
}

/// A legal shot that makes nothing: the lowest ball hit, then a cushion.
Log safe_miss(int lowest) { return std::move(shot().hit(0, lowest).rail(0)); }

}  // namespace

TEST_CASE("shot_facts names balls by painted number and reads pockets, the scratch and the cushions") {
  Log log(9);
  log.cue().rail(0).hit(0, 3).hit(3, 7).rail(7).jaw(4).rail(7).rail(0).drop(7, 2).drop(3, 5).drop(0, 1);
  const ShotFacts f = log.facts();
  CHECK(f.first_hit == 3);
  CHECK(f.cushion_after_hit);
  CHECK(f.object_balls_to_cushion == 2);  // the 7 twice and the 4 by a jaw; the cue ball does not count
  CHECK(f.pocketed == std::vector<int>{7, 3});
  CHECK(f.pockets == std::vector<int>{2, 5});
  CHECK(f.scratch);
  CHECK(f.scratch_pocket == 1);
}

TEST_CASE("shot_facts reads only the events and drops of the shot asked for") {
  Log log(9);
  log.cue().hit(0, 1).rail(1).drop(1, 0);
  log.cue().rail(0).hit(0, 2).drop(0, 3);
  log.cue().rail(0);
  const ShotFacts first = log.facts(0), second = log.facts(1), third = log.facts(2);
  CHECK(first.first_hit == 1);
  CHECK(first.pocketed == std::vector<int>{1});
  CHECK_FALSE(first.scratch);
  CHECK(first.object_balls_to_cushion == 1);
  CHECK(second.first_hit == 2);
  CHECK(second.pocketed.empty());
  CHECK(second.scratch);
  CHECK_FALSE(second.cushion_after_hit);  // the cue ball's rail came before the hit
  CHECK(second.object_balls_to_cushion == 0);
  CHECK(third.first_hit == -1);
  CHECK_FALSE(third.scratch);
  CHECK(log.facts(3).first_hit == -1);  // no such shot
}

TEST_CASE("shot_facts reads a group collision's contacts in the order they began") {
  // The cue ball meets the 3 first: neither the lowest number it touches (the 1) nor the first of its
  // partners the event lists (the 5: the event lists balls by ascending file index).
  Log log(9);
  log.cue().group({{5, 6}, {0, 3}, {0, 1}, {0, 5}});
  CHECK(log.facts().first_hit == 3);
  // A pair met before the group counts first.
  Log earlier(9);
  earlier.cue().hit(0, 8).group({{0, 3}, {0, 1}});
  CHECK(earlier.facts().first_hit == 8);
}

TEST_CASE("a cushion counts after the hit only strictly after the cue ball's contact, a group's by its contact time") {
  Log log(9);
  log.cue().at(2.0).group({{2, 3}, {4, 5}, {6, 7}, {0, 4}});  // the cue ball's contact at 2.0 + 3 ms
  log.at(2.0 + 0.002).rail(7);                                // after the event, before the contact
  CHECK_FALSE(log.facts().cushion_after_hit);
  log.at(2.0 + 3 * 0.001).rail(7);  // the very instant of the contact
  CHECK_FALSE(log.facts().cushion_after_hit);
  log.at(2.0 + 0.004).jaw(6);
  CHECK(log.facts().cushion_after_hit);
  CHECK(log.facts().first_hit == 4);
}

TEST_CASE("9-ball: a break is legal with the 1 first and a ball made or four object balls to a cushion") {
  GameRules made = nine();
  TurnVerdict v = play(made, shot().hit(0, 1).drop(2, 0));
  CHECK(v.legal);
  CHECK(v.break_shot);
  CHECK(v.continues);
  CHECK(made.next().shooter == 0);
  CHECK(made.next().may_push_out);
  CHECK(made.on_table() == std::vector<int>{1, 3, 4, 5, 6, 7, 8, 9});

  GameRules four = nine();  // the fourth ball meets a jaw
  v = play(four, shot().hit(0, 1).rail(1).rail(2).rail(3).jaw(4));
  CHECK(v.legal);
  CHECK_FALSE(v.continues);
  CHECK(four.next().shooter == 1);
  CHECK(four.next().in_hand == InHand::none);
  CHECK(four.next().may_push_out);

  GameRules three = nine();  // three balls (one twice) and the cue ball: not four
  v = play(three, shot().hit(0, 1).rail(1).rail(1).rail(2).rail(3).rail(0));
  CHECK_FALSE(v.legal);
  CHECK(v.foul == "an illegal break: no ball made and fewer than four balls to a cushion");
  CHECK(v.call == "foul: an illegal break: no ball made and fewer than four balls to a cushion; ball in hand");
  CHECK(v.in_hand == InHand::anywhere);
  CHECK(three.next().shooter == 1);
  CHECK(three.next().in_hand == InHand::anywhere);
  CHECK_FALSE(three.next().may_push_out);  // a push-out only follows a legal break
}

TEST_CASE("9-ball: a break that does not hit the 1 first, or scratches, is a foul") {
  GameRules rules = nine();
  CHECK(rules.next().break_shot);
  CHECK(rules.next().in_hand == InHand::kitchen);
  TurnVerdict v = play(rules, shot().hit(0, 3).drop(2, 0).rail(4).rail(5).rail(6).rail(7));
  CHECK_FALSE(v.legal);
  CHECK(v.foul == "the break did not hit the 1 first");
  CHECK(v.in_hand == InHand::anywhere);
  CHECK_FALSE(v.continues);
  CHECK(rules.on_table() == std::vector<int>{1, 3, 4, 5, 6, 7, 8, 9});  // the 2 stays down
  CHECK(rules.fouls_in_row(0) == 0);                                    // a breaking foul does not count

  GameRules scratch = nine();
  v = play(scratch, shot().hit(0, 1).drop(5, 0).drop(0, 1));
  CHECK(v.foul == "the cue ball went into a pocket");
  CHECK(scratch.next().in_hand == InHand::anywhere);
}

TEST_CASE("9-ball: the 9 made on a legal break wins; with a scratch it is spotted") {
  GameRules rules = nine();
  TurnVerdict v = play(rules, shot().hit(0, 1).hit(1, 9).drop(9, 3));
  CHECK(v.legal);
  REQUIRE(v.winner);
  CHECK(*v.winner == 0);
  CHECK(v.call == "wins the game");
  CHECK(rules.over());

  GameRules scratch = nine();
  v = play(scratch, shot().hit(0, 1).hit(1, 9).drop(9, 3).drop(0, 2));
  CHECK_FALSE(v.winner);
  CHECK(v.spotted == std::vector<int>{9});
  CHECK(scratch.on_table() == numbers(1, 9));
  CHECK(v.call == "foul: the cue ball went into a pocket; the 9 is spotted; ball in hand");
}

TEST_CASE("9-ball: the push-out after the break hits any ball, needs no cushion, and the incoming player chooses") {
  for (bool take : {true, false}) {
    GameRules rules = nine_broken();
    const ShotRules next = rules.next();
    CHECK(next.may_push_out);
    CHECK(next.targets == std::vector<int>{1});  // a shot that is not a push-out hits the lowest
    const TurnVerdict v = play(rules, shot().hit(0, 6), push_out());
    CHECK(v.legal);
    CHECK(v.push_out);
    CHECK(v.call == "push-out");
    CHECK(v.in_hand == InHand::none);
    CHECK(rules.next().shooter == 0);  // the incoming player decides
    CHECK(rules.take_push_out(take) == !take);
    CHECK(rules.next().shooter == (take ? 0 : 1));
    CHECK(rules.next().in_hand == InHand::none);
    CHECK_FALSE(rules.next().may_push_out);
    CHECK(rules.next().targets == std::vector<int>{1});
  }
}

TEST_CASE("9-ball: a push-out's balls stay down but the 9, which is spotted; its scratch is a foul") {
  GameRules rules = nine_broken();
  TurnVerdict v = play(rules, shot().hit(0, 3).hit(3, 9).drop(9, 1).drop(4, 2), push_out());
  CHECK(v.legal);
  CHECK_FALSE(v.winner);
  CHECK(v.spotted == std::vector<int>{9});
  CHECK(v.call == "push-out; the 9 is spotted");
  CHECK(rules.on_table() == std::vector<int>{1, 2, 3, 5, 6, 7, 8, 9});

  GameRules scratch = nine_broken();
  v = play(scratch, shot().rail(0).drop(0, 4), push_out());
  CHECK_FALSE(v.legal);
  CHECK_FALSE(v.push_out);
  CHECK(v.foul == "the cue ball went into a pocket");
  CHECK(v.in_hand == InHand::anywhere);
  CHECK_FALSE(scratch.take_push_out(false));  // nothing to choose after a foul
  CHECK(scratch.next().shooter == 0);
}

TEST_CASE(
    "9-ball: the shot after the break not called a push-out, and a later push-out call, must hit the lowest first") {
  GameRules rules = nine_broken();
  TurnVerdict v = play(rules, shot().hit(0, 5).rail(5));
  CHECK(v.foul == "the cue ball hit the 5 first, not the 1");
  GameRules later = nine();
  play(later, shot().hit(0, 1).drop(2, 0));  // the breaker goes on and may push out
  play(later, shot().hit(0, 1).drop(1, 0));  // does not: a legal shot that goes on
  CHECK_FALSE(later.next().may_push_out);
  v = play(later, shot().hit(0, 5), push_out());
  CHECK_FALSE(v.push_out);
  CHECK(v.foul == "the cue ball hit the 5 first, not the 3");
}

TEST_CASE("9-ball: the lowest ball first, then a ball made or a cushion; a ball made goes on") {
  GameRules rules(RackGame::nine_ball, {3, 5, 7, 9});
  CHECK(play(rules, shot().hit(0, 3).drop(7, 0)).legal);  // the break: the lowest ball is the 3
  CHECK(rules.next().targets == std::vector<int>{3});     // the push-out shot: the lowest unless pushed out
  TurnVerdict v = play(rules, shot().rail(0).hit(0, 3));
  CHECK(v.foul == "no ball reached a cushion after the cue ball hit the 3");
  CHECK(rules.next().shooter == 1);
  v = play(rules, shot().hit(0, 5).rail(5));
  CHECK(v.foul == "the cue ball hit the 5 first, not the 3");
  v = play(rules, shot().rail(0));
  CHECK(v.foul == "the cue ball missed every ball");
  v = play(rules, shot().hit(0, 3).drop(5, 1));  // legal: a ball made
  CHECK(v.legal);
  CHECK(v.continues);
  CHECK(rules.next().targets == std::vector<int>{3});
  v = play(rules, shot().hit(0, 3).hit(3, 9).rail(9));  // legal: a cushion, nothing made
  CHECK(v.legal);
  CHECK_FALSE(v.continues);
  CHECK(rules.next().shooter == 0);
  CHECK(rules.next().in_hand == InHand::none);
}

TEST_CASE("9-ball: the 9 on a combination wins; on a foul it is spotted") {
  GameRules rules = nine_broken();
  TurnVerdict v = play(rules, shot().hit(0, 5).hit(5, 9).drop(9, 4));
  CHECK_FALSE(v.legal);
  CHECK_FALSE(v.winner);
  CHECK(v.spotted == std::vector<int>{9});
  CHECK(rules.on_table() == numbers(1, 9));
  CHECK(v.call == "foul: the cue ball hit the 5 first, not the 1; the 9 is spotted; ball in hand");
  CHECK(rules.next().shooter == 0);
  v = play(rules, shot().hit(0, 1).hit(1, 9).drop(9, 4));
  CHECK(v.legal);
  REQUIRE(v.winner);
  CHECK(*v.winner == 0);
  CHECK(*rules.winner() == 0);
}

TEST_CASE("9-ball: three fouls in a row lose the game; a legal shot in between starts the count again") {
  GameRules rules = nine_broken();  // player 1 at the table
  const Log foul = shot().hit(0, 4).rail(4);
  TurnVerdict v = play(rules, foul);
  CHECK(v.fouls_in_row == 1);
  play(rules, safe_miss(1));  // player 0
  v = play(rules, foul);
  CHECK(v.fouls_in_row == 2);
  CHECK(v.call == "foul: the cue ball hit the 4 first, not the 1; ball in hand; second foul in a row");
  CHECK(rules.fouls_in_row(0) == 0);
  play(rules, safe_miss(1));
  v = play(rules, foul);
  CHECK(v.fouls_in_row == 3);
  REQUIRE(v.winner);
  CHECK(*v.winner == 0);
  CHECK(v.call == "foul: the cue ball hit the 4 first, not the 1; third foul in a row: loses the game");

  GameRules reset = nine_broken();
  play(reset, foul);
  play(reset, safe_miss(1));
  play(reset, foul);
  play(reset, safe_miss(1));
  CHECK(play(reset, safe_miss(1)).legal);  // player 1 shoots legally
  CHECK(reset.fouls_in_row(1) == 0);
  play(reset, foul);  // player 0
  v = play(reset, foul);
  CHECK(v.shooter == 1);
  CHECK(v.fouls_in_row == 1);
  CHECK_FALSE(v.winner);
}

TEST_CASE("9-ball: a foul on the break does not count toward three in a row") {
  GameRules rules = nine();
  play(rules, shot().hit(0, 2).rail(2));  // player 0 fouls the break
  const Log foul = shot().hit(0, 4).rail(4);
  for (int i = 0; i < 2; ++i) {
    CHECK(play(rules, safe_miss(1)).shooter == 1);
    const TurnVerdict v = play(rules, foul);
    CHECK(v.shooter == 0);
    CHECK(v.fouls_in_row == i + 1);
    CHECK_FALSE(v.winner);
  }
}

namespace {

/// 8-ball after a break that made the 9 (the table open, the breaker at the table) with the 1, the 8,
/// the 9 and the 10 racked; then the breaker makes the called 1 and is on the 8 with solids.
GameRules eight_on_the_8() {
  GameRules rules(RackGame::eight_ball, {1, 8, 9, 10});
  REQUIRE(play(rules, shot().hit(0, 1).drop(9, 0)).continues);
  const TurnVerdict v = play(rules, shot().hit(0, 1).drop(1, 2), called(1, 2));
  REQUIRE(v.continues);
  REQUIRE(v.call == "solids");
  REQUIRE(rules.next().targets == std::vector<int>{8});
  return rules;
}

/// 8-ball after a legal break that made the 2 and the 11: the table open, the breaker (0) at the table.
GameRules eight_open() {
  GameRules rules = eight();
  REQUIRE(play(rules, shot().hit(0, 1).drop(2, 0).drop(11, 5)).continues);
  return rules;
}

}  // namespace

TEST_CASE("8-ball: a legal break leaves the table open; an illegal one is a foul without ball in hand") {
  GameRules rules = eight();
  CHECK(rules.next().in_hand == InHand::kitchen);
  CHECK(rules.next().targets == numbers(1, 15));
  CHECK_FALSE(rules.next().call_required);
  TurnVerdict v = play(rules, shot().hit(0, 1).drop(2, 0).drop(11, 5));
  CHECK(v.legal);
  CHECK(v.continues);
  CHECK(rules.group(0) == 0);
  CHECK(rules.group(1) == 0);
  const ShotRules next = rules.next();
  CHECK(next.call_required);
  CHECK(next.winning_ball == 8);
  CHECK(next.targets == std::vector<int>{1, 3, 4, 5, 6, 7, 9, 10, 12, 13, 14, 15});  // not the 8

  GameRules four = eight();  // no ball made, four to a cushion (one by a jaw): legal, the turn passes
  v = play(four, shot().hit(0, 1).rail(1).rail(6).jaw(13).rail(15));
  CHECK(v.legal);
  CHECK_FALSE(v.continues);
  CHECK(four.next().shooter == 1);

  GameRules illegal = eight();
  v = play(illegal, shot().hit(0, 1).rail(1).rail(6).rail(13).rail(0));
  CHECK_FALSE(v.legal);
  CHECK(v.foul == "an illegal break: no ball made and fewer than four balls to a cushion");
  CHECK(v.in_hand == InHand::none);
  CHECK(v.call == "foul: an illegal break: no ball made and fewer than four balls to a cushion; the table as it lies");
  CHECK(illegal.next().shooter == 1);
  CHECK(illegal.next().in_hand == InHand::none);
  CHECK_FALSE(illegal.next().break_shot);
}

TEST_CASE("8-ball: a scratch on a legal break gives ball in hand behind the head string") {
  GameRules rules = eight();
  const TurnVerdict v = play(rules, shot().hit(0, 1).drop(5, 0).drop(0, 1));
  CHECK_FALSE(v.legal);
  CHECK(v.foul == "the cue ball went into a pocket");
  CHECK(v.in_hand == InHand::kitchen);
  CHECK(v.call == "foul: the cue ball went into a pocket; ball in hand behind the head string");
  CHECK(rules.next().shooter == 1);
  CHECK(rules.next().in_hand == InHand::kitchen);
  CHECK(rules.group(1) == 0);
}

TEST_CASE("8-ball: the 8 made on the break is spotted") {
  GameRules rules = eight();
  TurnVerdict v = play(rules, shot().hit(0, 1).hit(1, 8).drop(8, 3));
  CHECK(v.legal);
  CHECK_FALSE(v.winner);
  CHECK(v.spotted == std::vector<int>{8});
  CHECK(v.continues);
  CHECK(v.call == "the 8 is spotted");
  CHECK(rules.on_table() == numbers(1, 15));
  CHECK(rules.next().shooter == 0);

  GameRules scratch = eight();
  v = play(scratch, shot().hit(0, 1).hit(1, 8).drop(8, 3).drop(0, 2));
  CHECK_FALSE(v.winner);
  CHECK(v.spotted == std::vector<int>{8});
  CHECK(v.in_hand == InHand::kitchen);
  CHECK(scratch.on_table() == numbers(1, 15));
}

TEST_CASE("8-ball: the groups are set by a called ball made in its called pocket on an open table") {
  GameRules rules = eight_open();
  TurnVerdict v = play(rules, shot().hit(0, 12).hit(12, 3).drop(3, 4), called(3, 2));  // the wrong pocket
  CHECK(v.legal);
  CHECK_FALSE(v.continues);
  CHECK(rules.group(0) == 0);
  v = play(rules, shot().hit(0, 12).drop(4, 1).drop(12, 2), called(12, 2));  // player 1, a stripe first
  CHECK(v.legal);
  CHECK(v.continues);
  CHECK(v.call == "stripes");
  CHECK(rules.group(1) == 2);
  CHECK(rules.group(0) == 1);
  CHECK(rules.next().targets == std::vector<int>{9, 10, 13, 14, 15});
  CHECK(rules.on_table() == std::vector<int>{1, 5, 6, 7, 8, 9, 10, 13, 14, 15});
  v = play(rules, shot().hit(0, 9).drop(9, 3), called(9, 3));  // the groups stay as they are
  CHECK(v.continues);
  CHECK(v.call.empty());
  CHECK(rules.group(1) == 2);
}

TEST_CASE("8-ball: a shot that calls nothing takes the first ball made; a safety ends the turn") {
  GameRules uncalled = eight_open();
  TurnVerdict v = play(uncalled, shot().hit(0, 7).hit(7, 13).drop(13, 0).drop(7, 4));
  CHECK(v.continues);
  CHECK(uncalled.group(0) == 2);
  CHECK(v.call == "stripes");
  v = play(uncalled, shot().hit(0, 9).hit(9, 1).drop(1, 0).rail(9));  // only a solid made: no more
  CHECK(v.legal);
  CHECK_FALSE(v.continues);

  GameRules safe = eight_open();
  v = play(safe, shot().hit(0, 3).drop(3, 2), safety());
  CHECK(v.legal);
  CHECK_FALSE(v.continues);
  CHECK(safe.group(0) == 0);
  CHECK(safe.next().shooter == 1);
  CHECK(safe.on_table() == std::vector<int>{1, 4, 5, 6, 7, 8, 9, 10, 12, 13, 14, 15});
}

TEST_CASE("8-ball: the shooter's group first, then a ball made or a cushion; the 8 not first on an open table") {
  GameRules open = eight_open();
  TurnVerdict v = play(open, shot().hit(0, 8).rail(8));
  CHECK(v.foul == "the cue ball hit the 8 first on an open table");
  CHECK(v.in_hand == InHand::anywhere);

  GameRules rules = eight_open();
  play(rules, shot().hit(0, 3).drop(3, 2), called(3, 2));  // player 0: solids
  REQUIRE(rules.group(0) == 1);
  v = play(rules, shot().hit(0, 10).rail(10), called(4, 1));
  CHECK(v.foul == "the cue ball hit the 10 first, not a solid");
  CHECK(v.call == "foul: the cue ball hit the 10 first, not a solid; ball in hand");
  CHECK(rules.next().in_hand == InHand::anywhere);
  CHECK(rules.next().shooter == 1);
  v = play(rules, shot().rail(0).hit(0, 10), called(10, 1));  // player 1: the cushion came before the hit
  CHECK(v.foul == "no ball reached a cushion after the cue ball hit the 10");
  v = play(rules, shot().hit(0, 4).rail(0), called(4, 1));  // player 0: a cushion after the hit
  CHECK(v.legal);
  CHECK(rules.next().in_hand == InHand::none);
}

TEST_CASE("8-ball: the 8 made early, on an open table, in another pocket, with a scratch or on a foul loses") {
  GameRules early = eight_open();
  play(early, shot().hit(0, 3).drop(3, 2), called(3, 2));  // solids, the 1, 4-7 still up
  TurnVerdict v = play(early, shot().hit(0, 4).hit(4, 8).drop(8, 1).drop(4, 0), called(4, 0));
  CHECK_FALSE(v.legal);
  CHECK(v.foul == "the 8 went down before the solids were cleared");
  CHECK(v.call == "the 8 went down before the solids were cleared: loses the game");
  REQUIRE(v.winner);
  CHECK(*v.winner == 1);

  GameRules open = eight_open();
  v = play(open, shot().hit(0, 3).hit(3, 8).drop(8, 1), called(8, 1));
  CHECK(v.foul == "the 8 went down on an open table");
  CHECK(*v.winner == 1);

  struct Case {
    Log log;
    ShotCall call;
    std::string foul;
  };
  const std::vector<Case> cases = {
      {shot().hit(0, 8).drop(8, 4), called(8, 5), "the 8 went into another pocket than the one called"},
      {shot().hit(0, 8).drop(8, 5).drop(0, 1), called(8, 5), "the cue ball went into a pocket with the 8"},
      {shot().hit(0, 10).hit(10, 8).drop(8, 5), called(8, 5),
       "the 8 went down on a foul: the cue ball hit the 10 first, not the 8"},
      {shot().hit(0, 8).drop(8, 5), safety(), "the 8 went down without being called"},
  };
  for (const Case& c : cases) {
    GameRules rules = eight_on_the_8();
    v = play(rules, c.log, c.call);
    CHECK(v.foul == c.foul);
    REQUIRE(v.winner);
    CHECK(*v.winner == 1);
    CHECK(rules.over());
  }
}

TEST_CASE("8-ball: the 8 made legally after the group, in the called pocket or uncalled, wins") {
  for (const ShotCall& call : {called(8, 5), ShotCall{}}) {
    GameRules rules = eight_on_the_8();
    const TurnVerdict v = play(rules, shot().hit(0, 8).drop(8, 5), call);
    CHECK(v.legal);
    REQUIRE(v.winner);
    CHECK(*v.winner == 0);
    CHECK(v.call == "wins the game");
  }
  GameRules miss = eight_on_the_8();  // the 8 first, a cushion, nothing made: the turn passes
  const TurnVerdict v = play(miss, shot().hit(0, 8).rail(8), called(8, 5));
  CHECK(v.legal);
  CHECK_FALSE(v.winner);
  CHECK(miss.next().shooter == 1);
  CHECK(miss.next().targets == std::vector<int>{10});  // stripes: the 9 went down on the break
}

TEST_CASE("8-ball has no three-foul rule") {
  GameRules rules = eight_open();
  const Log foul = shot().hit(0, 8).rail(8);
  for (int i = 0; i < 4; ++i) {
    const TurnVerdict v = play(rules, foul);
    CHECK_FALSE(v.legal);
    CHECK(v.fouls_in_row == 0);
    CHECK_FALSE(v.winner);
    play(rules, shot().hit(0, 3).rail(3));
  }
  CHECK_FALSE(rules.over());
}
