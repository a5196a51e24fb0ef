#pragma once
// What a game movie's caption says at a moment of the movie, as television captions a match: the two
// players with the one at the table marked, the balls of the rack still on the table, and the
// referee's calls as they happen. A function of the simulation time a frame shows and of whether the
// frame is part of the replay, so the movie's frames may show the game's times in any order.
//
// When a call shows, and for how long (README, "Games"):
//  - a foul (its reason, a spotted ball, ball in hand, a second foul in a row) once the shot has
//    settled (its balls stopped but for spin in place: Timeline::settled), until the next shot's stroke;
//  - a push-out from the shot's start (it is announced), and once it has settled the incoming
//    player's answer, until the next shot's stroke;
//  - the winner (or the game stopped at its shot limit) once the last shot has settled, to the end,
//    and on every replay frame.
// The marker moves to the next shooter as the next shot starts. A ball leaves the rack's row as it
// drops; after the shot has settled the row is the rules' count (a spotted ball is back on it).
#include <string>
#include <vector>

#include "game.h"

namespace bsim {

/// One of the referee's calls.
struct CaptionCall {
  enum class Kind { foul, push_out, winner, stopped };
  Kind kind = Kind::foul;
  std::string title;  ///< a word or two, e.g. "FOUL", "PUSH-OUT", "WINNER"
  std::string text;   ///< what it is about, in a person's words, e.g. "the cue ball went into a pocket"
  bool operator==(const CaptionCall&) const = default;
};

struct Caption {
  RackGame rules = RackGame::nine_ball;
  std::vector<std::string> players;  ///< the two names
  int at_table = 0;                  ///< the player at the table, 0 or 1
  int shot = 0;                      ///< the game's shot shown, from 0
  std::vector<int> rack;             ///< the game's object balls (painted numbers), ascending
  std::vector<int> on_table;         ///< those still on the table, ascending
  std::vector<CaptionCall> calls;    ///< none, one or two (a foul that loses the game, and its winner)
  bool replay = false;               ///< the frame is part of the replay
  bool operator==(const Caption&) const = default;
};

/// The caption of the moment at simulation time `t` of the game `record` played as `timeline` (the
/// game's explicit `scene`, GameResult::scene); `replay` for a frame of the replay.
Caption caption_at(const GameRecord& record, const Timeline& timeline, const Scene& scene, double t, bool replay);

/// The caption in one line, for messages and tests: "Ann* | Bo | 1 2 3 9 | FOUL: the cue ball ... |
/// REPLAY" (the player at the table starred; only the parts present).
std::string caption_text(const Caption& caption);

/// The game's name as a caption shows it: "9-BALL", "8-BALL", "10-BALL".
const char* caption_game_name(RackGame rules);

}  // namespace bsim
