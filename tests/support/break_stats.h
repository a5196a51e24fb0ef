#pragma once
// Seeded breaks as a player breaks, and what they make: the break statistics of the `break_stats` bench
// and of tests/physics/test_break_stats.cpp. Each break racks a game with `rack` (its own seed), puts the
// cue ball anywhere behind the head string and strokes it (a `stroke`, strike.h: the stick's speed, tip
// offsets and elevation, the model the scene files use) at the apex ball at a professional's break speed,
// with the Computational Pool Olympiad's execution noise.
//
// Real figures (research: pockets_rules.md D): a break that is legal, makes a ball and does not foul on
// 71% of breaks at the 2016 WPA World 9-Ball Championship (75 of 105) and on 66% at an 8-ball event (the
// 2024 Ultimate Pool Colorado Shootout, 82 of 124). Break speed: men pros 22-26 mph, on average 24 mph =
// 10.7 m/s (Onoda, Billiards Digest 1989). Noise (FastFiz's GaussianNoise, the Olympiad's, C4): standard
// deviations 0.125 deg of heading, 0.1 deg of elevation, 0.5 mm of each tip offset, 0.075 m/s of the
// stick's speed.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "rack.h"
#include "random_scenes.h"
#include "simulate.h"
#include "strike.h"

namespace bsim::breaks {

inline constexpr double kRealShare9Ball = 0.71;  ///< 2016 WPA World 9-Ball, 75 of 105 breaks
inline constexpr double kRealShare8Ball = 0.66;  ///< 2024 Ultimate Pool Colorado Shootout (8-ball), 82 of 124

struct BreakSetup {
  RackGame game = RackGame::nine_ball;
  double speed = 10.7;  ///< m/s, the cue ball's speed off a centre hit (Onoda: men pros' mean)
  // The Olympiad's noise, standard deviations (FastFiz GaussianNoise, magnitude 1).
  double heading_sd_deg = 0.125;  ///< of the stick's heading, about the line to the apex ball's centre
  double elevation_sd_deg = 0.1;  ///< of the elevation about level (folded: the butt never below the tip)
  double tip_sd = 0.0005;         ///< m, of each tip offset (side and height) about the centre
  double stick_speed_sd = 0.075;  ///< m/s, of the stick's speed
  bool tight = false;             ///< the mathematical rack in place of the real one
  double gap_scale = 1.0;         ///< the real rack's offsets from the tight one, times this
  PhysicsParams physics;          ///< the ball, the stick and the pockets (`param corner_mouth`, ...)
  bool bare_pockets = false;      ///< drop circles at the standard places (bare_standard_pockets), no jaws
};

/// A standard normal deviate from two uniform ones (Box-Muller), drawn from the break's own stream.
inline double normal(scenes::Rng& rng) {
  const double u = 1.0 - rng.uniform(0, 1), v = rng.uniform(0, 1);  // u in (0, 1]
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * std::numbers::pi * v);
}

/// m/s of cue-ball speed a centre hit gives per m/s of the stick's, level (strike.h).
inline double speed_gain(const PhysicsParams& physics) {
  Stroke unit;
  unit.speed = 1;
  return strike(unit, 0, physics).velocity.norm();
}

/// The rack as the setup racks it (tight, real, or with its gaps scaled).
inline std::vector<RackedBall> break_rack(const BreakSetup& setup, std::uint64_t seed) {
  RackSpec spec;
  spec.game = setup.game;
  spec.seed = seed;
  spec.radius = setup.physics.ball_radius;
  spec.tight = setup.tight;
  std::vector<RackedBall> rack = rack_balls(spec);
  if (!setup.tight && setup.gap_scale != 1.0) {
    spec.tight = true;
    const std::vector<RackedBall> perfect = rack_balls(spec);  // the same placement: the seed draws it first
    for (std::size_t i = 0; i < rack.size(); ++i) {
      rack[i].x = perfect[i].x + setup.gap_scale * (rack[i].x - perfect[i].x);
      rack[i].y = perfect[i].y + setup.gap_scale * (rack[i].y - perfect[i].y);
    }
  }
  return rack;
}

/// One break: the cue ball is ball 0, the rack's balls follow by painted number; the cue's stroke set.
inline Scene break_scene(const BreakSetup& setup, std::uint64_t seed) {
  Scene scene;
  scene.name = "break";
  scene.physics = setup.physics;
  scene.rails = standard_rails(setup.physics);
  scene.pockets = setup.bare_pockets ? bare_standard_pockets() : standard_pockets(setup.physics);
  const double R = scene.physics.ball_radius;
  const std::vector<RackedBall> rack = break_rack(setup, seed);
  // The cue ball anywhere in the kitchen: behind the head string (x = -0.635), inside the cushions.
  const TableSpec& t = kStandardTable;
  scenes::Rng rng(seed ^ 0x5eed0b4eac000000ull);
  const double margin = R + 1e-3;
  const double x = rng.uniform(-t.half_length + margin, -0.635),
               y = rng.uniform(-t.half_width + margin, t.half_width - margin);
  const RackedBall& apex = *std::find_if(rack.begin(), rack.end(), [](const RackedBall& b) { return b.row == 0; });
  const double deg = 180.0 / std::numbers::pi;
  Stroke stroke;
  stroke.speed = setup.speed / speed_gain(setup.physics) + setup.stick_speed_sd * normal(rng);
  stroke.elevation_deg = std::abs(setup.elevation_sd_deg * normal(rng));
  stroke.side = setup.tip_sd * normal(rng) / R;
  stroke.height = setup.tip_sd * normal(rng) / R;
  scene.balls.push_back(scenes::ball_at(0, x, y, scene.physics));
  for (const RackedBall& b : rack) scene.balls.push_back(scenes::ball_at(b.number, b.x, b.y, scene.physics));
  scene.cue().target = 0;
  scene.cue().heading_deg = std::atan2(apex.y - y, apex.x - x) * deg + setup.heading_sd_deg * normal(rng);
  scene.cue().stroke = stroke;
  strike_cue_ball(scene);  // the ball line's velocity and spin as the stroke gives them (for readers of the scene)
  return scene;
}

struct BreakOutcome {
  int object_balls_down = 0;
  bool scratch = false;   ///< the cue ball pocketed
  int first_hit = -1;     ///< the painted number of the first ball the cue ball touches (-1: none)
  int balls_to_rail = 0;  ///< distinct object balls that met a cushion (a rail or a jaw)
  int lowest = 1;         ///< the rack's lowest number (9-ball: the 1 must be hit first)
  bool nine_ball = false;

  /// WPA: a legal break pockets a ball or drives at least four object balls to a rail; 9-ball also
  /// hits the lowest ball first.
  bool legal() const {
    const bool first_ok = !nine_ball || first_hit == lowest;
    return first_ok && (object_balls_down > 0 || balls_to_rail >= 4);
  }
  /// What the real figures count: legal, at least one ball made, no foul (no scratch).
  bool success() const { return legal() && object_balls_down > 0 && !scratch; }
};

inline BreakOutcome play_break(const Scene& scene, RackGame game) {
  const SimulationResult result = simulate_events(scene);
  BreakOutcome out;
  out.nine_ball = game == RackGame::nine_ball;
  for (const PocketDrop& d : result.drops) {
    if (scene.ball(d.ball).number == 0)
      out.scratch = true;
    else
      ++out.object_balls_down;
  }
  std::vector<char> railed(scene.balls.size(), 0);
  double first_time = 1e300;
  for (const Event& e : result.events) {
    if ((e.type == EventType::ball_rail || e.type == EventType::ball_jaw) && scene.ball(e.balls[0]).number != 0)
      railed[static_cast<std::size_t>(e.balls[0])] = 1;
    for (const Contact& c : e.contacts)
      if ((c.a == 0 || c.b == 0) && c.time < first_time) {
        first_time = c.time;
        out.first_hit = scene.ball(c.a == 0 ? c.b : c.a).number;
      }
  }
  out.balls_to_rail = static_cast<int>(std::count(railed.begin(), railed.end(), 1));
  return out;
}

struct BreakStats {
  int breaks = 0;
  int pocketing = 0;   ///< breaks with at least one object ball down (fouled or not)
  int successful = 0;  ///< legal, a ball made, no foul: what the real figures count
  int legal = 0;       ///< legal breaks (WPA), made or not
  int balls_down = 0;
  int scratches = 0;
  int wrong_first = 0;         ///< 9-ball: the 1 not hit first
  std::vector<int> histogram;  ///< breaks by object balls down: [0], [1], ...
  double share() const { return breaks ? static_cast<double>(pocketing) / breaks : 0; }
  double success_share() const { return breaks ? static_cast<double>(successful) / breaks : 0; }
  double legal_share() const { return breaks ? static_cast<double>(legal) / breaks : 0; }
  double mean_down() const { return breaks ? static_cast<double>(balls_down) / breaks : 0; }
  double scratch_rate() const { return breaks ? static_cast<double>(scratches) / breaks : 0; }
};

/// Breaks with seeds first, first + 1, ..., first + count - 1.
inline BreakStats play_breaks(const BreakSetup& setup, int count, std::uint64_t first = 1) {
  BreakStats stats;
  for (int k = 0; k < count; ++k) {
    const BreakOutcome o = play_break(break_scene(setup, first + static_cast<std::uint64_t>(k)), setup.game);
    ++stats.breaks;
    stats.pocketing += o.object_balls_down > 0 ? 1 : 0;
    stats.successful += o.success() ? 1 : 0;
    stats.legal += o.legal() ? 1 : 0;
    stats.balls_down += o.object_balls_down;
    stats.scratches += o.scratch ? 1 : 0;
    stats.wrong_first += o.nine_ball && o.first_hit != o.lowest ? 1 : 0;
    const auto n = static_cast<std::size_t>(o.object_balls_down);
    if (stats.histogram.size() <= n) stats.histogram.resize(n + 1, 0);
    ++stats.histogram[n];
  }
  return stats;
}

}  // namespace bsim::breaks
