// player_bench: the player (player.h) on racked-and-broken tables. Each table is racked (`rack`, a seed
// each), broken by the player's own break, and then played on by the player for a number of shots under
// simple rules kept here (9-ball: the lowest ball first; 8-ball: an open table, then the group of the
// first ball made, then the 8; a foul gives ball in hand anywhere; a table ends when its last ball is
// down). Every planned shot is played with the player's noise. Prints, per game and in all: the pots
// tried and made, the safeties, the simulations and the CPU seconds of planning per shot.
//   player_bench [--tables N] [--shots M] [--noise K] [--game 9ball|8ball] [--verbose]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "player.h"
#include "simulate.h"

namespace {

using namespace bsim;

bool verbose = false;

struct Tally {
  int shots = 0, tried = 0, made = 0, safeties = 0, fouls = 0, push_outs = 0;
  int games = 0, runs = 0;  ///< tables played, and those cleared from the break with no miss, safety or foul
  int band_tried[5] = {}, band_made[5] = {};  ///< by planned chance: < 0.6, < 0.7, < 0.8, < 0.9, >= 0.9
  long simulations = 0;
  double seconds = 0, worst = 0;
  void add(const Tally& o) {
    shots += o.shots, tried += o.tried, made += o.made, safeties += o.safeties, fouls += o.fouls;
    push_outs += o.push_outs, simulations += o.simulations, seconds += o.seconds;
    games += o.games, runs += o.runs;
    for (int b = 0; b < 5; ++b) band_tried[b] += o.band_tried[b], band_made[b] += o.band_made[b];
    worst = std::max(worst, o.worst);
  }
};

Scene racked(RackGame game, std::uint64_t seed) {
  Scene scene;
  scene.rails = standard_rails();
  scene.pockets = standard_pockets();
  const double R = scene.physics.ball_radius;
  Ball cue;
  cue.position = Vec3(-0.635, 0, R);
  scene.balls.push_back(cue);
  RackSpec spec;
  spec.game = game;
  spec.seed = seed;
  for (const RackedBall& r : rack_balls(spec)) {
    Ball b;
    b.number = r.number;
    b.position = Vec3(r.x, r.y, R);
    scene.balls.push_back(b);
  }
  return scene;
}

std::vector<int> on_table(const Scene& s) {
  std::vector<int> on;
  for (const Ball& b : s.balls)
    if (b.number > 0 && b.pocket < 0) on.push_back(b.number);
  std::sort(on.begin(), on.end());
  return on;
}

/// The legal first balls: 9-ball the lowest; 8-ball the group (0 open, 1 solids, 2 stripes) or the 8.
std::vector<int> targets(const Scene& s, bool eight, int group) {
  const std::vector<int> on = on_table(s);
  if (!eight) return on.empty() ? on : std::vector<int>{on.front()};
  std::vector<int> t;
  for (int n : on)
    if (n != 8 && (group == 0 || (group == 1) == (n < 8))) t.push_back(n);
  if (t.empty() && group != 0) t.push_back(8);
  return t;
}

/// Plays `plan` (with noise) on `table` and leaves the balls where they stop; returns the facts needed.
struct Played {
  bool scratch = false, legal_first = false, cushion = false;
  std::vector<int> made, pockets;
};

Played play(Scene& table, const PlannedShot& plan, const ShotRules& rules, double noise, std::uint64_t seed) {
  int cue = 0;
  for (std::size_t i = 0; i < table.balls.size(); ++i)
    if (table.balls[i].number == 0) cue = static_cast<int>(i);
  if (plan.place) {
    table.balls[static_cast<std::size_t>(cue)].position = *plan.place;
    table.balls[static_cast<std::size_t>(cue)].pocket = -1;
  }
  SplitMix64 random(seed);
  Cue c;
  c.target = cue;
  c.heading_deg = plan.heading_deg;
  c.stroke = plan.stroke;
  apply_noise(noise, table.physics.ball_radius, random, c.heading_deg, *c.stroke);
  table.cues = {c};
  const SimulationResult r = simulate_events(table);
  Played p;
  double first = -1;
  for (const Event& e : r.events) {
    for (const Contact& k : e.contacts)
      if (first < 0 && (k.a == cue || k.b == cue)) {
        first = k.time;
        const int other = table.balls[static_cast<std::size_t>(k.a == cue ? k.b : k.a)].number;
        p.legal_first = std::find(rules.targets.begin(), rules.targets.end(), other) != rules.targets.end();
      }
    if (first >= 0 && (e.type == EventType::ball_rail || e.type == EventType::ball_jaw) && e.time >= first)
      p.cushion = true;
  }
  for (const PocketDrop& d : r.drops) {
    const int n = table.balls[static_cast<std::size_t>(d.ball)].number;
    if (n == 0)
      p.scratch = true;
    else
      p.made.push_back(n), p.pockets.push_back(d.pocket);
  }
  for (std::size_t i = 0; i < table.balls.size(); ++i) {
    const MotionSegment& last = r.segments[i].back();
    table.balls[i].position = last.start.position;
    const bool down = last.start.motion == Motion::pocketed || last.start.motion == Motion::falling;
    table.balls[i].pocket = down ? last.pocket : -1;
  }
  return p;
}

Tally play_table(RackGame game, std::uint64_t seed, int shots, double noise) {
  const bool eight = game == RackGame::eight_ball;
  Scene table = racked(game, seed);
  PlayerSkill skill{"bench", noise};
  ShotRules rules;
  rules.winning_ball = eight ? 8 : 9;
  rules.break_shot = true;
  rules.in_hand = InHand::kitchen;
  rules.targets = eight ? std::vector<int>{1, 2, 3, 4, 5, 6, 7, 9, 10, 11, 12, 13, 14, 15} : std::vector<int>{1};
  Tally t;
  int group = 0;
  bool clean = true;  // a ball made on a legal break, then every shot a called pot made
  t.games = 1;
  for (int k = 0; k <= shots && !on_table(table).empty(); ++k) {
    const std::clock_t c0 = std::clock();
    const PlannedShot plan = plan_shot(table, rules, skill, seed * 1000 + static_cast<std::uint64_t>(k));
    const double s = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    const Played p = play(table, plan, rules, noise, seed * 7919 + static_cast<std::uint64_t>(k));
    const bool foul = p.scratch || !p.legal_first || (p.made.empty() && !p.cushion);
    if (!rules.break_shot) {
      ++t.shots;
      t.simulations += plan.simulations;
      t.seconds += s;
      t.worst = std::max(t.worst, s);
      t.fouls += foul;
      t.safeties += plan.call.safety;
      t.push_outs += plan.call.push_out;
      if (verbose)
        std::printf("  shot %2d: call %2d in %d chance %.2f%s%s, made %zu%s%s\n", k, plan.call.ball, plan.call.pocket,
                    plan.chance, plan.call.safety ? " safety" : "", plan.place ? " in hand" : "", p.made.size(),
                    p.scratch ? " scratch" : "", foul ? " FOUL" : "");
      bool called_made = false;
      for (std::size_t i = 0; i < p.made.size(); ++i)
        called_made = called_made || (!foul && p.made[i] == plan.call.ball && p.pockets[i] == plan.call.pocket);
      if (plan.call.ball >= 0) {
        const int band = std::clamp(static_cast<int>((plan.chance - 0.5) * 10), 0, 4);
        ++t.tried, ++t.band_tried[band];
        t.made += called_made, t.band_made[band] += called_made;
      }
      clean = clean && called_made;
    } else {
      clean = !foul && !p.made.empty();
    }
    if (eight && group == 0 && !foul && !rules.break_shot && !p.made.empty() && p.made.front() != 8)
      group = p.made.front() < 8 ? 1 : 2;
    if (std::find(p.made.begin(), p.made.end(), rules.winning_ball) != p.made.end()) {
      t.runs = clean && !foul;
      break;
    }
    rules.break_shot = false;
    rules.may_push_out = false;
    rules.in_hand = foul ? InHand::anywhere : InHand::none;
    rules.targets = targets(table, eight, group);
  }
  return t;
}

void print(const char* what, const Tally& t) {
  const double shots = std::max(1, t.shots);
  std::printf(
      "%-14s %3d shots, pots made %3d of %3d (%5.1f%%), %2d safeties, %2d fouls, %6.0f sims/shot, "
      "%.3f s/shot (worst %.3f)\n",
      what, t.shots, t.made, t.tried, t.tried ? 100.0 * t.made / t.tried : 0.0, t.safeties, t.fouls,
      static_cast<double>(t.simulations) / shots, t.seconds / shots, t.worst);
  if (std::strcmp(what, "all") != 0) return;
  std::printf("cleared from the break with no miss: %d of %d tables (%.0f%%)\nmade by planned chance:", t.runs, t.games,
              100.0 * t.runs / std::max(1, t.games));
  const char* bands[5] = {"<0.6", "0.6-0.7", "0.7-0.8", "0.8-0.9", ">=0.9"};
  for (int b = 0; b < 5; ++b) std::printf("  %s: %d/%d", bands[b], t.band_made[b], t.band_tried[b]);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  int tables = 4, shots = 12;
  double noise = 1.0;
  RackGame game = RackGame::nine_ball;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--verbose") == 0) verbose = true;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--tables") == 0)
      tables = std::max(1, std::atoi(argv[i + 1]));
    else if (std::strcmp(argv[i], "--shots") == 0)
      shots = std::max(1, std::atoi(argv[i + 1]));
    else if (std::strcmp(argv[i], "--noise") == 0)
      noise = std::atof(argv[i + 1]);
    else if (std::strcmp(argv[i], "--game") == 0)
      game = std::strcmp(argv[i + 1], "8ball") == 0 ? RackGame::eight_ball : RackGame::nine_ball;
  }
  std::printf("player_bench: %s, noise %.2f, %d tables of up to %d shots after the break\n",
              game == RackGame::eight_ball ? "8-ball" : "9-ball", noise, tables, shots);
  Tally all;
  for (int s = 1; s <= tables; ++s) {
    const Tally t = play_table(game, static_cast<std::uint64_t>(s), shots, noise);
    print(("table " + std::to_string(s)).c_str(), t);
    all.add(t);
  }
  print("all", all);
  return 0;
}
