#pragma once
// Figures of played games, as the literature reports players (research/pool_ai.md): the share of
// racks broken and run, pots made over pots attempted, balls made per visit to the table, fouls and
// safeties per game, the breaker's share of wins. Shared by game_bench and the game tests.
#include <string>
#include <vector>

#include "game.h"
#include "scene_parse.h"

namespace bsim::games {

/// A game scene's text: `game RULES seed N`, two players of noise `noise`.
inline std::string game_text(const std::string& rules, unsigned long seed, double noise, int shots = 60) {
  return "game " + rules + " seed " + std::to_string(seed) + " shots " + std::to_string(shots) + "\nplayer Ann noise " +
         std::to_string(noise) + "\nplayer Bo noise " + std::to_string(noise) + "\n";
}

struct Tally {
  int games = 0, finished = 0, break_and_runs = 0, breaker_wins = 0;
  int attempts = 0, made = 0;  ///< planned pots (not the break, not safeties) and those that dropped as called
  int legal_balls = 0, visits = 0;
  int fouls = 0, safeties = 0, shots = 0;
  long simulations = 0;
  double planning_seconds = 0, worst_planning = 0;

  /// Adds one game: its record and the drops of its timeline (to tell a called pot from a lucky one).
  void add(const GameRecord& record, const Timeline& timeline, const Scene& scene) {
    ++games;
    if (record.turns.empty()) return;
    const int breaker = record.turns.front().player;
    finished += record.winner.has_value();
    breaker_wins += record.winner == breaker;
    bool run = record.winner == breaker;
    int previous = -1;
    for (const GameTurn& turn : record.turns) {
      ++shots;
      run = run && turn.player == breaker;
      visits += turn.player != previous;
      previous = turn.player;
      fouls += !turn.verdict.legal;
      safeties += turn.planned.safety;
      simulations += turn.simulations;
      planning_seconds += turn.planning_seconds;
      worst_planning = std::max(worst_planning, turn.planning_seconds);
      if (turn.verdict.legal) legal_balls += static_cast<int>(turn.verdict.pocketed.size());
      if (turn.verdict.break_shot || turn.written || turn.planned.ball < 0) continue;
      ++attempts;
      made += called_drop(timeline, scene, turn);
    }
    break_and_runs += run;
  }

  /// Whether the turn's called ball dropped into the called pocket in its shot.
  static bool called_drop(const Timeline& timeline, const Scene& scene, const GameTurn& turn) {
    const ShotSpan& span = timeline.shots()[static_cast<std::size_t>(turn.shot)];
    const double until = turn.shot + 1 < timeline.shot_count()
                             ? timeline.shots()[static_cast<std::size_t>(turn.shot + 1)].start
                             : timeline.duration() + 1;
    for (const PocketDrop& d : timeline.pocket_drops())
      if (d.time >= span.start && d.time < until && scene.ball(d.ball).number == turn.planned.ball &&
          d.pocket == turn.planned.pocket)
        return true;
    return false;
  }
};

}  // namespace bsim::games
