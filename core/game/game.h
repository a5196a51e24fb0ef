#pragma once
// A game played: the scene's `game` line racked, broken and played to the end by the rules (rules.h)
// and the players (player.h). The game is played through the same shot chain as any scene of several
// shots (play.h): what comes out is an explicit scene (each shot a `cue` line with its heading, its
// stroke and its `place` lines) that plays to the same events, its timeline, and the rules' record.
#include <optional>
#include <string>
#include <vector>

#include "play.h"
#include "rules.h"
#include "scene.h"
#include "timeline.h"

namespace bsim {

/// One turn of the game: a shot and the rules' verdict on it (events.json `game.turns`).
struct GameTurn {
  int shot = 0;               ///< from 0
  int player = 0;             ///< 0 or 1
  bool written = false;       ///< the scene's own `cue` line (judged), not a player's plan
  ShotCall planned;           ///< a player's plan (ball and pocket, or safety / push-out); a written `pot` line's call
  double chance = 0;          ///< a plan's estimated chance of the pot
  TurnVerdict verdict;        ///< legal, foul, pocketed, continues, ball in hand, winner
  std::vector<int> on_table;  ///< object balls (painted numbers) on the table after the shot, as the rules count them
  int simulations = 0;        ///< shots the player simulated to choose it
  double planning_seconds = 0;  ///< CPU time to plan it (the bench's; never written to a file)
};

/// The rules' record of a game.
struct GameRecord {
  RackGame rules = RackGame::nine_ball;
  std::vector<std::string> players;  ///< two names
  std::vector<double> noise;         ///< each player's noise
  std::optional<int> winner;         ///< none: unfinished (the shot limit)
  bool shot_limit = false;           ///< the game stopped at its `shots` limit
  std::vector<GameTurn> turns;       ///< one per shot
};

struct GameResult {
  Scene scene;        ///< explicit: the balls as racked, the cue ball where it broke from, one cue per shot
  Timeline timeline;  ///< every shot played
  GameRecord record;
  std::optional<PlayFailure> failure;  ///< a written shot that cannot be played (its line is to blame)
};

/// Plays the game of `scene` (scene.game set): its written cues first, then the players.
GameResult play_game(const Scene& scene);

/// The two players' names: the `player` lines', the rest "Player 1", "Player 2".
std::vector<std::string> player_names(const GameLine& game);

}  // namespace bsim
