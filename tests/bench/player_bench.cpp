// player_bench: the player (player.h) on racked-and-broken tables. Each table is racked (`rack`, a seed
// each), broken by the player's own break, and then played on by the player for a number of shots under
// simple rules kept here (9-ball: the lowest ball first; 8-ball: an open table, then the group of the
// first ball made, then the 8; a foul gives ball in hand anywhere; a table ends when its last ball is
// down). Every planned shot is played with the player's noise. Prints, per game and in all: the pots
// tried and made, the safeties, the simulations and the CPU seconds of planning per shot.
// `--look-ahead N` instead measures the second ply: N seeded 9-ball end positions (the 1, the 2 and the
// 9 dropped at random, the cue ball too) each run out with the look-ahead and without it, side by side:
// the share cleared with no miss, and the positions where the two players' first shots differ.
//   player_bench [--tables N] [--shots M] [--noise K] [--game 9ball|8ball] [--verbose]
//   player_bench --look-ahead N [--noise K]
//   player_bench --look-ahead N --position S    position S run out N times each way
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

/// A 9-ball end position: the cue ball, the 1, the 2 and the 9 dropped at random on the bed, at least
/// a ball's width from the cushions and from each other.
Scene end_position(std::uint64_t seed) {
  Scene scene = racked(RackGame::nine_ball, 1);
  const double R = scene.physics.ball_radius;
  scene.balls.resize(1);
  SplitMix64 random(seed);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * random.uniform(); };
  for (int number : {1, 2, 9}) {
    Ball b;
    b.number = number;
    scene.balls.push_back(b);
  }
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    for (bool free = false; !free;) {
      scene.balls[i].position = Vec3(uniform(-1.2, 1.2), uniform(-0.55, 0.55), R);
      free = true;
      for (std::size_t j = 0; j < i; ++j)
        free = free && (scene.balls[j].position - scene.balls[i].position).norm() > 4 * R;
    }
  }
  return scene;
}

/// Runs out `position` (9-ball, the lowest first) with noise; true when every ball goes down on a called
/// pot with no miss, safety or foul. `first` gets the first plan.
bool run_out(Scene table, double noise, bool look_ahead, std::uint64_t seed, PlannedShot& first) {
  PlayerSkill skill{"bench", noise, look_ahead};
  ShotRules rules;
  rules.winning_ball = 9;
  for (int k = 0; k < 3; ++k) {
    rules.targets = targets(table, false, 0);
    const PlannedShot plan = plan_shot(table, rules, skill, seed * 1000 + static_cast<std::uint64_t>(k));
    if (k == 0) first = plan;
    if (plan.call.safety || plan.call.ball < 0) return false;
    const Played p = play(table, plan, rules, noise, seed * 7919 + static_cast<std::uint64_t>(k));
    if (p.scratch || !p.legal_first) return false;
    bool called = false;
    for (std::size_t i = 0; i < p.made.size(); ++i)
      called = called || (p.made[i] == plan.call.ball && p.pockets[i] == plan.call.pocket);
    if (!called) return false;
    if (std::find(p.made.begin(), p.made.end(), 9) != p.made.end()) return true;
  }
  return false;
}

void look_ahead_bench(int positions, double noise) {
  std::printf("player_bench: the second ply, 9-ball end positions (1, 2, 9), noise %.2f, %d positions\n", noise,
              positions);
  int cleared[2] = {}, differ = 0;
  double seconds[2] = {};
  for (int s = 1; s <= positions; ++s) {
    const Scene position = end_position(static_cast<std::uint64_t>(s));
    PlannedShot first[2];
    bool out[2];
    for (int a = 0; a < 2; ++a) {
      const std::clock_t c0 = std::clock();
      out[a] = run_out(position, noise, a == 1, static_cast<std::uint64_t>(s), first[a]);
      seconds[a] += static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      cleared[a] += out[a];
    }
    const bool same = first[0].call.ball == first[1].call.ball && first[0].call.pocket == first[1].call.pocket &&
                      first[0].heading_deg == first[1].heading_deg && first[0].stroke.speed == first[1].stroke.speed &&
                      first[0].stroke.height == first[1].stroke.height && first[0].stroke.side == first[1].stroke.side;
    differ += !same;
    if (verbose && !same) {
      std::printf("  position %d:", s);
      for (const Ball& b : position.balls) std::printf(" %d (%.3f, %.3f)", b.number, b.position.x(), b.position.y());
      for (int a = 0; a < 2; ++a)
        std::printf("%s: %d in %d at %.1f m/s height %.2f side %.2f%s", a ? "; with" : "\n    without",
                    first[a].call.ball, first[a].call.pocket, first[a].stroke.speed, first[a].stroke.height,
                    first[a].stroke.side, out[a] ? " cleared" : " not cleared");
      std::printf("\n");
    }
  }
  std::printf("%-16s %8s %10s\n", "", "cleared", "CPU s");
  std::printf("%-16s %7.1f%% %10.1f\n", "one ply", 100.0 * cleared[0] / positions, seconds[0]);
  std::printf("%-16s %7.1f%% %10.1f\n", "with look-ahead", 100.0 * cleared[1] / positions, seconds[1]);
  std::printf("first shots differ in %d of %d positions\n", differ, positions);
}

/// One position run out `runs` times (each with its own noise seeds), with and without the look-ahead.
void look_ahead_position(int position_seed, int runs, double noise) {
  const Scene position = end_position(static_cast<std::uint64_t>(position_seed));
  int cleared[2] = {};
  for (int r = 1; r <= runs; ++r)
    for (int a = 0; a < 2; ++a) {
      PlannedShot first;
      cleared[a] += run_out(position, noise, a == 1, static_cast<std::uint64_t>(r) * 104729u, first);
    }
  std::printf("position %d, %d runs: one ply cleared %d, with look-ahead %d\n", position_seed, runs, cleared[0],
              cleared[1]);
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
  int look_ahead = 0, position = 0;
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
    else if (std::strcmp(argv[i], "--position") == 0)
      position = std::atoi(argv[i + 1]);
    else if (std::strcmp(argv[i], "--look-ahead") == 0)
      look_ahead = std::max(1, std::atoi(argv[i + 1]));
    else if (std::strcmp(argv[i], "--game") == 0)
      game = std::strcmp(argv[i + 1], "8ball") == 0 ? RackGame::eight_ball : RackGame::nine_ball;
  }
  if (look_ahead > 0 && position > 0) {
    look_ahead_position(position, look_ahead, noise);
    return 0;
  }
  if (look_ahead > 0) {
    look_ahead_bench(look_ahead, noise);
    return 0;
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
