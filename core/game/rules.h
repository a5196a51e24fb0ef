#pragma once
// The rules of pool as pure functions of what a shot did: the WPA World Standard Rules of 9-ball and
// 8-ball (World Pool-Billiard Association, "World Standardized Rules", the General Rules and the
// rules of each game). The queries on a shot's events follow pooltool's `ruleset` utilities (Kiefl,
// pooltool `ruleset/utils.py`: first ball hit, balls to a cushion after it, balls pocketed, the cue
// ball's fate); the state kept between shots follows FastFiz's `GameState` (Leckie & Greenspan,
// FastFiz `Rules.cpp`: the fouls in a row, the push-out, the 9 spotted after a foul).
//
// Balls are named by their painted numbers here (the cue ball is 0), never by file order.
// What the rules leave to the players' choice is decided as follows (README, "Games"):
//  - 8-ball, an illegal break (no ball made, fewer than four to a cushion): a foul; the incoming player
//    accepts the table as it lies (no re-rack) without ball in hand.
//  - 8-ball, the 8 made on the break: it is spotted and the breaker goes on if the break was otherwise
//    a legal shot that made a ball; with a scratch the incoming player has ball in hand behind the
//    head string.
//  - 8-ball, a shot that calls nothing (a `cue` line with a heading): it is taken as calling the first
//    ball of the shooter's group it makes, in the pocket it went into (an "obvious" shot).
//  - 9-ball: a foul on the break does not count toward three fouls in a row.
#include <optional>
#include <string>
#include <vector>

#include "event.h"
#include "rack.h"
#include "scene.h"

namespace bsim {

/// Where the next shooter may put the cue ball by hand.
enum class InHand { none, kitchen, anywhere };

/// What one shot did, read from its events and drops alone.
struct ShotFacts {
  int first_hit = -1;               ///< the first object ball the cue ball touched; -1: it touched none
  bool cushion_after_hit = false;   ///< a ball (the cue ball or any other) met a cushion or a jaw after it
  int object_balls_to_cushion = 0;  ///< distinct object balls that met a cushion or a jaw during the shot
  std::vector<int> pocketed;        ///< object balls made, in the order they dropped
  std::vector<int> pockets;         ///< the pocket each of `pocketed` dropped into (Scene::pockets)
  bool scratch = false;             ///< the cue ball went into a pocket
  int scratch_pocket = -1;          ///< and which
};

/// The facts of shot `shot` (from 0) of a timeline: `events` and `drops` as the timeline has them (only
/// those of that shot are read), `balls` the scene's balls in file order (for their painted numbers).
ShotFacts shot_facts(const std::vector<Event>& events, const std::vector<PocketDrop>& drops,
                     const std::vector<Ball>& balls, int shot);

/// What the shooter says before a shot: the ball and pocket meant (8-ball calls them; a player's plan
/// always has them), or a safety, or a 9-ball push-out.
struct ShotCall {
  int ball = -1;    ///< painted number, -1: none called
  int pocket = -1;  ///< Scene::pockets index, -1: none called
  bool safety = false;
  bool push_out = false;
  bool operator==(const ShotCall&) const = default;
};

/// What the rules allow and ask of the next shot.
struct ShotRules {
  int shooter = 0;                ///< 0 or 1
  bool break_shot = false;        ///< the opening break
  InHand in_hand = InHand::none;  ///< where the shooter may put the cue ball first
  std::vector<int> targets;       ///< the balls the cue ball may legally hit first (ascending; a push-out may hit any)
  int winning_ball = 9;           ///< 9-ball: the 9; 8-ball: the 8 (legal to make only once `targets` is {8})
  bool may_push_out = false;      ///< 9-ball: the shot right after the break
  bool call_required = false;     ///< 8-ball after the break: the ball and pocket are called
};

/// The rules' verdict on one shot (one turn of events.json's game).
struct TurnVerdict {
  int shooter = 0;
  bool break_shot = false;
  bool legal = true;
  std::string foul;               ///< the rule broken, in a person's words; empty on a legal shot
  std::vector<int> pocketed;      ///< object balls made (as ShotFacts)
  bool continues = false;         ///< the same player shoots the next shot
  InHand in_hand = InHand::none;  ///< where the next shooter may put the cue ball
  bool push_out = false;          ///< a 9-ball push-out (`continues` is then set by take_push_out)
  std::vector<int> spotted;   ///< balls the rules put back on the foot spot (the 9 made on a foul, the 8 on the break)
  std::optional<int> winner;  ///< the game is over: its winner
  std::string call;           ///< the referee's words, no names: "foul: ...; ball in hand", "push-out", "wins the game"
  int fouls_in_row = 0;       ///< the shooter's fouls in a row after this shot (9-ball; 2 is a warning)
};

/// A game's state between shots: whose turn, who plays which group, the fouls in a row, the balls up.
class GameRules {
 public:
  /// `object_balls` the painted numbers on the table at the start.
  GameRules(RackGame game, std::vector<int> object_balls);

  RackGame game() const { return game_; }
  /// What the next shot may and must do.
  ShotRules next() const;
  /// Judges the shot just played (its facts and what the shooter called) and moves the game on.
  TurnVerdict judge(const ShotFacts& facts, const ShotCall& call);
  /// After a push-out: the incoming player shoots (`take` true) or hands the table back. Returns whether
  /// the pushing player shoots again.
  bool take_push_out(bool take);

  bool over() const { return winner_.has_value(); }
  std::optional<int> winner() const { return winner_; }
  /// The object balls on the table, ascending.
  const std::vector<int>& on_table() const { return on_table_; }
  /// 8-ball: the group of player p: 0 open, 1 solids (1-7), 2 stripes (9-15).
  int group(int player) const { return group_[player]; }
  /// 9-ball: the fouls in a row of player p.
  int fouls_in_row(int player) const { return fouls_[player]; }

 private:
  std::vector<int> targets() const;
  TurnVerdict judge_rotation(const ShotFacts& facts, const ShotCall& call);
  TurnVerdict judge_eight(const ShotFacts& facts, const ShotCall& call);
  TurnVerdict judge_eight_break(const ShotFacts& facts);
  TurnVerdict eight_down(const ShotFacts& facts, const ShotCall& call, const std::string& foul, TurnVerdict verdict);

  RackGame game_;
  std::vector<int> on_table_;
  int shooter_ = 0;
  bool break_next_ = true;
  bool push_out_next_ = false;
  InHand in_hand_ = InHand::kitchen;
  int group_[2] = {0, 0};
  int fouls_[2] = {0, 0};
  std::optional<int> winner_;
  int winning_ = 9;                ///< the ball that wins (next().winning_ball)
  bool push_out_pending_ = false;  ///< a push-out was played: take_push_out decides who shoots
};

}  // namespace bsim
