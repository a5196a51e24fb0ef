#pragma once
// Scenes built in code for the bench and the property tests: the standard table, a racked break,
// a two-ball shot, seeded random breaks and a many-ball stress table. Seeded with a small
// hand-written generator, so a seed means the same scene with every compiler and library.
#include <cmath>
#include <cstdint>

#include "scene.h"

namespace bsim::scenes {

/// splitmix64: tiny, portable, good enough to scatter test scenes.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Each coordinate uniform in [lo, hi), drawn x, y, z in that order (argument order is unspecified in C++).
  Vec3 vector(double lo, double hi, double z_lo = 0, double z_hi = 0) {
    const double x = uniform(lo, hi);
    const double y = uniform(lo, hi);
    const double z = z_lo == z_hi ? z_lo : uniform(z_lo, z_hi);
    return Vec3(x, y, z);
  }

 private:
  std::uint64_t state_;
};

inline Ball ball_at(int number, double x, double y, const PhysicsParams& physics, Vec3 velocity = Vec3(0, 0, 0)) {
  Ball b;
  b.number = number;
  b.position = Vec3(x, y, physics.ball_radius);
  b.velocity = velocity;
  return b;
}

/// The standard 9-foot table with no balls.
inline Scene standard_table() {
  Scene scene;
  scene.rails = standard_rails();
  scene.pockets = standard_pockets();
  return scene;
}

/// Fifteen balls in a triangle, apex at (apex_x, 0), `gap` between neighbours; each ball nudged by
/// up to `jitter` m so the rack is not perfectly regular.
inline void add_rack(Scene& scene, double apex_x, double gap, double jitter, Rng* rng) {
  const double R = scene.physics.ball_radius, pitch = 2 * R + gap;
  int number = 1;
  for (int row = 0; row < 5; ++row)
    for (int k = 0; k <= row; ++k) {
      double x = apex_x + row * pitch * std::sqrt(3.0) / 2, y = (k - row / 2.0) * pitch;
      if (rng && jitter > 0) {
        x += rng->uniform(-jitter, jitter);
        y += rng->uniform(-jitter, jitter);
      }
      scene.balls.push_back(ball_at(number++, x, y, scene.physics));
    }
}

/// The standard break: cue ball on the head spot at 8 m/s, rack on the foot spot with 0.1 mm gaps.
inline Scene standard_break(double speed = 8.0, double vy = 0.0) {
  Scene scene = standard_table();
  scene.name = "break";
  scene.balls.push_back(ball_at(0, -0.635, 0, scene.physics, Vec3(speed, vy, 0)));
  add_rack(scene, 0.635, 1e-4, 0, nullptr);
  return scene;
}

/// A tight break: cue ball on the head spot at `speed`, rack of touching balls on the foot spot.
inline Scene tight_break(double speed = 10.7) {
  Scene scene = standard_table();
  scene.name = "tight_break";
  scene.balls.push_back(ball_at(0, -0.635, 0.03, scene.physics, Vec3(speed, -0.0235 * speed, 0).normalized() * speed));
  add_rack(scene, 0.635, 0, 0, nullptr);
  return scene;
}

/// A cut shot: the cue ball sends the object ball toward a corner pocket.
inline Scene two_ball_shot() {
  Scene scene = standard_table();
  scene.name = "two_ball";
  scene.balls.push_back(ball_at(0, -0.6, -0.2, scene.physics, Vec3(2.5, 0.9, 0)));
  scene.balls.push_back(ball_at(1, 0.3, 0.15, scene.physics));
  return scene;
}

/// A random break on the standard table: cue ball anywhere behind the head string, aimed near the
/// apex at 2-10 m/s with random follow/draw and side spin; the rack tight (touching but for a few
/// micrometres) or with gaps, its placement jittered.
inline Scene random_break(std::uint64_t seed) {
  Rng rng(seed);
  Scene scene = standard_table();
  scene.name = "random_break";
  const double R = scene.physics.ball_radius;
  const double cue_x = rng.uniform(-1.1, -0.7);
  const Vec3 cue(cue_x, rng.uniform(-0.5, 0.5), R);
  const double apex = 0.635;
  const double aim = std::atan2(-cue.y(), apex - cue.x()) + rng.uniform(-0.03, 0.03);
  const double speed = rng.uniform(2.0, 10.0);
  Ball b = ball_at(0, cue.x(), cue.y(), scene.physics, Vec3(speed * std::cos(aim), speed * std::sin(aim), 0));
  const double follow = rng.uniform(-0.6, 0.6) * speed / R;  // +: topspin about the axis left of travel
  const double side = rng.uniform(-60, 60);
  b.spin = Vec3(-std::sin(aim), std::cos(aim), 0) * follow + Vec3(0, 0, side);
  scene.balls.push_back(b);
  // Half the racks are tight: the balls touch but for a jitter of a few micrometres (a real rack);
  // the others have gaps of up to 0.3 mm. 3 x the jitter keeps neighbours from overlapping.
  const bool tight = rng.uniform(0, 1) < 0.5;
  const double jitter = tight ? rng.uniform(0, 4e-6) : rng.uniform(0, 5e-5);
  const double gap = 3 * jitter + (tight ? 0.0 : rng.uniform(0, 3e-4));
  add_rack(scene, apex, gap, jitter, &rng);
  scene.cue().heading_deg = aim * 180 / M_PI;
  return scene;
}

/// `count` balls scattered over a 6 m x 3 m table with four cushions and six pockets, all moving.
inline Scene stress_table(int count, std::uint64_t seed) {
  Rng rng(seed);
  Scene scene;
  scene.name = "stress";
  const double hx = 3.0, hy = 1.5, h = kStandardNoseHeight, c = 0.12, R = scene.physics.ball_radius;
  auto rail = [h](double ax, double ay, double bx, double by) { return Rail{Vec3(ax, ay, h), Vec3(bx, by, h), {}}; };
  scene.rails = {rail(-hx + c, hy, -c, hy), rail(c, hy, hx - c, hy),     rail(hx, hy - c, hx, -hy + c),
                 rail(hx - c, -hy, c, -hy), rail(-c, -hy, -hx + c, -hy), rail(-hx, -hy + c, -hx, hy - c)};
  for (double x : {-hx, 0.0, hx})
    for (double y : {hy, -hy}) scene.pockets.push_back(Pocket{Vec3(x, y, 0), c, {}});
  const int columns = static_cast<int>(std::ceil(std::sqrt(2.0 * count)));
  const int rows = (count + columns - 1) / columns;
  const double dx = 2 * (hx - 0.2) / columns, dy = 2 * (hy - 0.2) / rows;
  for (int k = 0; k < count; ++k) {
    const double x = -hx + 0.2 + (k % columns + 0.5) * dx + rng.uniform(-0.2, 0.2) * (dx - 2 * R);
    const double y = -hy + 0.2 + (k / columns + 0.5) * dy + rng.uniform(-0.2, 0.2) * (dy - 2 * R);
    const double heading = rng.uniform(0, 2 * M_PI);
    const double speed = rng.uniform(0.5, 3.0);
    scene.balls.push_back(ball_at(k % 16, x, y, scene.physics, speed * Vec3(std::cos(heading), std::sin(heading), 0)));
  }
  return scene;
}

}  // namespace bsim::scenes
