// FastFiz 0.2's side of tests/bench/fastfiz_side_by_side.cpp: its own 8-ball break and a two-ball cut
// shot, set up once and shot again and again. FastFiz (Stanford, LGPL) is no part of this project:
// tests/bench/physics_ab.sh --fastfiz DIR builds this file against a copy of it (github.com/ekiefl/
// FastFiz, FastFiz-0.2/FastFiz) with `g++ -O2 -fpermissive` and GSL (Debian's libgsl-dev), as FastFiz
// was measured before (research note break_physics.md). Never built by CMake.
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "FastFiz.h"
#include "Rules.h"

using namespace Pool;

namespace fastfiz_side {

struct Setup {
  TableState start;
  ShotParams shot;
};

namespace {

/// The stick raised 5 degrees (FastFiz refuses a level one: it would pass through the rail) and struck
/// R sin 5 degrees above the centre, so the cue ball leaves at exactly `speed` along `phi` without spin.
ShotParams stun(double speed, double phi) {
  const double deg = 5.0, m = Ball::BALL_MASS, M = Table::CUE_MASS;
  const double stick = speed * (1 + m / M) / (2 * std::cos(deg * M_PI / 180));
  return ShotParams(0, 1000 * Ball::BALL_RADIUS * std::sin(deg * M_PI / 180), deg, phi, stick);
}

}  // namespace

/// The two-ball shot: bench's (cue ball at (-0.6, -0.2) m from the centre of a 2.54 m table at (2.5, 0.9)
/// m/s, the object ball at (0.3, 0.15)) scaled to FastFiz's 2.236 m table, whose long axis is y. The
/// break: FastFiz's own 8-ball rack, dithered by its random generator from `seed`, the cue ball on the
/// head string aimed at the apex at `speed`.
Setup* prepare(bool two_ball, double speed, const char* seed) {
  Setup* setup = new Setup;
  if (two_ball) {
    const Table& t = setup->start.getTable();
    const double s = t.getLength() / 2.54, cx = t.getWidth() / 2, cy = t.getLength() / 2;
    setup->start.setBall(Ball::CUE, Ball::STATIONARY, cx + 0.2 * s, cy - 0.6 * s);
    setup->start.setBall(Ball::ONE, Ball::STATIONARY, cx - 0.15 * s, cy + 0.3 * s);
    for (int k = 2; k <= 15; ++k) setup->start.setBall(static_cast<Ball::Type>(k), Ball::NOTINPLAY, 0, 0);
    setup->shot = stun(std::hypot(2.5, 0.9), std::atan2(-0.9, 2.5) * 180 / M_PI + 360);
    return setup;
  }
  // FastFiz seeds GSL's generator from the clock unless GSL_RNG_SEED is set.
  setenv("GSL_RNG_SEED", seed, 1);
  EightBallState game(0, 0);
  setup->start = game.tableState();
  const Point cue = setup->start.getBall(Ball::CUE).getPos(), apex = setup->start.getBall(Ball::ONE).getPos();
  setup->shot = stun(speed, std::fmod(std::atan2(apex.y - cue.y, apex.x - cue.x) * 180 / M_PI + 360, 360));
  return setup;
}

/// One shot from the set-up table: its events.
std::size_t shoot(const Setup* setup) {
  TableState state = setup->start;
  Shot* shot = state.executeShot(setup->shot);
  const std::size_t events = shot->getEventList().size();
  delete shot;
  return events;
}

}  // namespace fastfiz_side
