#pragma once
// Seeded breaks as a player breaks, and what they pocket: the break statistics of the `break_stats`
// bench and of tests/physics/test_break_stats.cpp. Each break racks a game with `rack` (its own seed),
// puts the cue ball anywhere behind the head string and strikes it at the apex ball with a little aiming
// noise at a professional's break speed, in the seed's velocity form.
//
// Real figures (research: break_physics.md): a ball is pocketed on 71% of breaks at the 2016 WPA World
// 9-Ball Championship (105 breaks) and on 66% in an 8-ball event (AZBilliards' break statistics). Break
// speed: pros 22-26 mph, on average 24 mph = 10.7 m/s (Onoda, Billiards Digest 1989).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "rack.h"
#include "random_scenes.h"
#include "simulate.h"

namespace bsim::breaks {

inline constexpr double kRealShare9Ball = 0.71;  ///< 2016 WPA World 9-Ball, 105 breaks
inline constexpr double kRealShare8Ball = 0.66;  ///< an 8-ball event, AZBilliards' break statistics

struct BreakSetup {
  RackGame game = RackGame::nine_ball;
  double speed = 10.7;         ///< m/s, mean cue-ball speed (Onoda: pros' average)
  double speed_spread = 0.8;   ///< m/s, uniform +- about the mean
  double aim_noise_deg = 0.3;  ///< uniform +- about the line to the apex ball's centre
  bool tight = false;          ///< the mathematical rack in place of the real one
  double gap_scale = 1.0;      ///< the real rack's offsets from the tight one, times this
  double pocket_scale = 1.0;   ///< every pocket's radius, times this
};

/// One break: the cue ball is ball 0, the rack's balls follow by painted number.
inline Scene break_scene(const BreakSetup& setup, std::uint64_t seed) {
  Scene scene = scenes::standard_table();
  scene.name = "break";
  for (Pocket& p : scene.pockets) p.radius *= setup.pocket_scale;
  const double R = scene.physics.ball_radius;
  RackSpec spec;
  spec.game = setup.game;
  spec.seed = seed;
  spec.radius = R;
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
  // The cue ball anywhere in the kitchen: behind the head string (x = -0.635), inside the cushions.
  double min_x = 0, min_y = 0, max_y = 0;
  for (const Rail& r : scene.rails) {
    min_x = std::min({min_x, r.a.x(), r.b.x()});
    min_y = std::min({min_y, r.a.y(), r.b.y()});
    max_y = std::max({max_y, r.a.y(), r.b.y()});
  }
  scenes::Rng rng(seed ^ 0x5eed0b4eac000000ull);
  const double margin = R + 1e-3;
  const double x = rng.uniform(min_x + margin, -0.635), y = rng.uniform(min_y + margin, max_y - margin);
  const RackedBall& apex = *std::find_if(rack.begin(), rack.end(), [](const RackedBall& b) { return b.row == 0; });
  const double heading = std::atan2(apex.y - y, apex.x - x) +
                         rng.uniform(-setup.aim_noise_deg, setup.aim_noise_deg) * std::numbers::pi / 180.0;
  const double speed = rng.uniform(setup.speed - setup.speed_spread, setup.speed + setup.speed_spread);
  scene.balls.push_back(scenes::ball_at(0, x, y, scene.physics, speed * Vec3(std::cos(heading), std::sin(heading), 0)));
  for (const RackedBall& b : rack) scene.balls.push_back(scenes::ball_at(b.number, b.x, b.y, scene.physics));
  scene.cue().target = 0;
  scene.cue().heading_deg = heading * 180.0 / std::numbers::pi;
  return scene;
}

struct BreakOutcome {
  int object_balls_down = 0;
  bool scratch = false;  ///< the cue ball pocketed
};

inline BreakOutcome play_break(const Scene& scene) {
  const SimulationResult result = simulate_events(scene);
  BreakOutcome out;
  for (const PocketDrop& d : result.drops) {
    if (d.ball == 0)
      out.scratch = true;
    else
      ++out.object_balls_down;
  }
  return out;
}

struct BreakStats {
  int breaks = 0;
  int pocketing = 0;  ///< breaks with at least one object ball down
  int balls_down = 0;
  int scratches = 0;
  std::vector<int> histogram;  ///< breaks by object balls down: [0], [1], ...
  double share() const { return breaks ? static_cast<double>(pocketing) / breaks : 0; }
  double mean_down() const { return breaks ? static_cast<double>(balls_down) / breaks : 0; }
  double scratch_rate() const { return breaks ? static_cast<double>(scratches) / breaks : 0; }
};

/// Breaks with seeds first, first + 1, ..., first + count - 1.
inline BreakStats play_breaks(const BreakSetup& setup, int count, std::uint64_t first = 1) {
  BreakStats stats;
  for (int k = 0; k < count; ++k) {
    const BreakOutcome o = play_break(break_scene(setup, first + static_cast<std::uint64_t>(k)));
    ++stats.breaks;
    stats.pocketing += o.object_balls_down > 0 ? 1 : 0;
    stats.balls_down += o.object_balls_down;
    stats.scratches += o.scratch ? 1 : 0;
    const auto n = static_cast<std::size_t>(o.object_balls_down);
    if (stats.histogram.size() <= n) stats.histogram.resize(n + 1, 0);
    ++stats.histogram[n];
  }
  return stats;
}

}  // namespace bsim::breaks
