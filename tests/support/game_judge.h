#pragma once
// An independent judge of a played game. It reads events.json's text alone (and the scene's painted
// numbers), works out each shot's facts from its events (the first ball the cue ball hit, the cushions
// met after it, the balls made and where, a scratch), and re-derives every turn of the file's `game`
// by the WPA World Standard Rules of 9-ball and 8-ball, written here from the rules and not from the
// program's own rules (core/game). Where the rules leave a choice it takes the program's documented
// one (README, "Games"): 8-ball, an illegal break is a foul and the incoming player takes the table as
// it lies, without ball in hand (behind the head string after a scratch); the 8 made on the break is
// spotted; a shot that calls nothing calls the first ball of the shooter's group it makes, in the
// pocket it went into; 9-ball, a foul on the break does not count toward three fouls in a row. A
// push-out may be played on the shot right after the break unless the break scratched (WPA 9-ball
// 1.5); who shoots after it is the players' choice (the log's `continues`).
//
// No test framework: the benchmarks use it too.
#include <string>
#include <vector>

namespace bsim::test {

/// A turn where the log and the rules differ.
struct Dispute {
  int turn = 0;      ///< the turn from 1 (its shot); 0: the game as a whole (the winner, the file's layout)
  std::string what;  ///< what the log says and what the rules say
};

/// Judges the game of an events.json text. `numbers[i]` is the painted number of the ball with file
/// index i (0: the cue ball). Empty when every turn agrees with the rules.
std::vector<Dispute> judge_game(const std::string& events_json, const std::vector<int>& numbers);

/// The painted numbers by file index, as the file's `final` list gives them.
std::vector<int> ball_numbers(const std::string& events_json);

/// One line per dispute: "turn K: ..." ("game: ..." for turn 0).
std::string describe(const std::vector<Dispute>& disputes);

}  // namespace bsim::test
