// game_bench: whole games played by the program's players, measured as the literature measures players
// (research/pool_ai.md): professionals break and run 28 % of 9-ball racks (2016 WPA World 9-Ball; the
// breaker wins 56 %) and 41 % of 8-ball racks (2024); the best published program (pix2pockets, 2025)
// makes 94.7 % of its shots; the Olympiad's champion (CueCard) searched thousands to tens of thousands
// of simulations a shot. Seeded games at noise 1 and at noise 5 (the 2011 tournament's "high" level).
//   game_bench [--games N] [--rules 9ball|8ball] [--noise K]
//   game_bench --soak N      N games of each rules at noise 1
//   --first-seed S           seeds S, S + 1, ... instead of 1, 2, ... (to split a soak over processes)
// Every game is checked as it is played: no physics fault (overlap, escape, NaN; tests/support/shot_checks.h)
// and no turn the independent judge (tests/support/game_judge.h) disputes; the `fault` column counts both.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include <sstream>

#include "game_judge.h"
#include "game_stats.h"
#include "outputs.h"
#include "shot.h"
#include "shot_checks.h"

namespace {

using namespace bsim;

struct Options {
  int games = 20;
  std::vector<std::string> rules = {"9ball", "8ball"};
  std::vector<double> noise = {1, 5};
  int soak = 0;
  int first_seed = 1;
};

Options options(int argc, char** argv) {
  Options o;
  for (int k = 1; k + 1 < argc; k += 2) {
    const std::string flag = argv[k], value = argv[k + 1];
    if (flag == "--games")
      o.games = std::atoi(value.c_str());
    else if (flag == "--rules")
      o.rules = {value};
    else if (flag == "--noise")
      o.noise = {std::atof(value.c_str())};
    else if (flag == "--first-seed")
      o.first_seed = std::max(1, std::atoi(value.c_str()));
    else if (flag == "--soak")
      o.soak = std::atoi(value.c_str());
  }
  return o;
}

/// Plays one seeded game; false when it could not be parsed or played.
bool play_one(const std::string& rules, unsigned long seed, double noise, games::Tally& tally, double& cpu,
              int& faults) {
  const ParseResult parsed = parse_scene(games::game_text(rules, seed, noise), "game");
  if (!parsed.scene) return false;
  const std::clock_t begun = std::clock();
  const GameResult game = play_game(*parsed.scene);
  cpu += static_cast<double>(std::clock() - begun) / CLOCKS_PER_SEC;
  if (game.failure) {
    std::printf("  seed %lu: %s\n", seed, game.failure->message.c_str());
    return false;
  }
  tally.add(game.record, game.timeline, game.scene);
  const checks::Faults f = checks::find_faults(game.scene, game.timeline);
  faults += static_cast<int>(f.total());
  if (f.total() > 0)
    std::printf(
        "  %s seed %lu noise %g: %ld overlaps, %ld escapes, %ld not finite, %ld missed contacts, %ld energy "
        "gains (deepest %.3g mm)\n",
        rules.c_str(), seed, noise, f.overlaps, f.escapes, f.nans, f.missed, f.energy_gains, f.deepest * 1e3);
  // The independent judge reads the game as events.json has it.
  Shot shot;
  shot.scene = game.scene;
  shot.timeline = game.timeline;
  shot.game = game.record;
  std::ostringstream json;
  write_events_json(shot, json);
  const std::vector<test::Dispute> disputes = test::judge_game(json.str(), test::ball_numbers(json.str()));
  if (!disputes.empty()) {
    std::printf("  %s seed %lu noise %g: %s", rules.c_str(), seed, noise, test::describe(disputes).c_str());
    faults += static_cast<int>(disputes.size());
  }
  return true;
}

void row(const std::string& rules, double noise, int games, int first_seed) {
  games::Tally t;
  double cpu = 0;
  int faults = 0, failed = 0;
  for (int g = 0; g < games; ++g)
    if (!play_one(rules, static_cast<unsigned long>(first_seed + g), noise, t, cpu, faults)) ++failed;
  const auto pct = [](int a, int b) { return b > 0 ? 100.0 * a / b : 0.0; };
  std::printf("%-6s %5.1f %5d %6.1f%% %6.1f%% %8.1f%% %6.2f %6.2f %6.2f %7.1f%% %8.0f %9.3f %7.3f %7.2f %5d %5d\n",
              rules.c_str(), noise, t.games, pct(t.break_and_runs, t.games), pct(t.finished, t.games),
              pct(t.made, t.attempts), t.visits ? double(t.legal_balls) / t.visits : 0.0,
              t.games ? double(t.fouls) / t.games : 0.0, t.games ? double(t.safeties) / t.games : 0.0,
              pct(t.breaker_wins, t.finished), t.shots ? double(t.simulations) / t.shots : 0.0,
              t.shots ? t.planning_seconds / t.shots : 0.0, t.worst_planning, t.games ? cpu / t.games : 0.0, faults,
              failed);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = options(argc, argv);
  if (o.soak > 0) {
    for (const std::string& rules : {std::string("9ball"), std::string("8ball")}) row(rules, 1, o.soak, o.first_seed);
    return 0;
  }
  std::printf(
      "rules  noise games  b&run finished  made/att  balls/ fouls/ safe/ breaker  sims/  plan s/  worst  CPU s/ fault "
      "fail\n");
  std::printf(
      "                                              visit  game   game   wins     shot   shot     plan   game\n");
  for (const std::string& rules : o.rules)
    for (double noise : o.noise) row(rules, noise, o.games, o.first_seed);
  return 0;
}
