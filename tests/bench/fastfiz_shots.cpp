// fastfiz_shots: FastFiz 0.2's physics timed on its own 8-ball break and on a two-ball cut shot, for
// tests/bench/physics_ab.sh's side-by-side figures. FastFiz (Stanford, LGPL) is no part of this project:
// the script builds this file against a copy of it (github.com/ekiefl/FastFiz, FastFiz-0.2/FastFiz)
// with `g++ -O2 -fpermissive` and GSL (Debian's libgsl-dev). Never built by CMake.
//   fastfiz_shots break|two-ball [runs] [break speed m/s] [rack seed]
// prints "fastfiz NAME events E us U": the events of one shot and the median microseconds per shot.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "FastFiz.h"
#include "Rules.h"

using namespace Pool;

namespace {

/// The stick raised 5 degrees (FastFiz refuses a level one: it would pass through the rail) and struck
/// R sin 5 degrees above the centre, so the cue ball leaves at exactly `speed` along `phi` without spin.
ShotParams stun(double speed, double phi) {
  const double deg = 5.0, m = Ball::BALL_MASS, M = Table::CUE_MASS;
  const double stick = speed * (1 + m / M) / (2 * std::cos(deg * M_PI / 180));
  return ShotParams(0, 1000 * Ball::BALL_RADIUS * std::sin(deg * M_PI / 180), deg, phi, stick);
}

/// bench's two-ball shot (cue ball at (-0.6, -0.2) m from the centre of a 2.54 m table at (2.5, 0.9)
/// m/s, the object ball at (0.3, 0.15)), scaled to FastFiz's 2.236 m table, whose long axis is y.
TableState two_ball(ShotParams& shot) {
  TableState state;
  const Table& t = state.getTable();
  const double s = t.getLength() / 2.54, cx = t.getWidth() / 2, cy = t.getLength() / 2;
  state.setBall(Ball::CUE, Ball::STATIONARY, cx + 0.2 * s, cy - 0.6 * s);
  state.setBall(Ball::ONE, Ball::STATIONARY, cx - 0.15 * s, cy + 0.3 * s);
  for (int k = 2; k <= 15; ++k) state.setBall(static_cast<Ball::Type>(k), Ball::NOTINPLAY, 0, 0);
  shot = stun(std::hypot(2.5, 0.9), std::atan2(-0.9, 2.5) * 180 / M_PI + 360);
  return state;
}

/// FastFiz's own 8-ball rack, dithered by its random generator, the cue ball on the head string aimed
/// at the apex.
TableState rack(double speed, ShotParams& shot) {
  EightBallState game(0, 0);
  TableState state = game.tableState();
  const Point cue = state.getBall(Ball::CUE).getPos(), apex = state.getBall(Ball::ONE).getPos();
  shot = stun(speed, std::fmod(std::atan2(apex.y - cue.y, apex.x - cue.x) * 180 / M_PI + 360, 360));
  return state;
}

}  // namespace

int main(int argc, char** argv) {
  const bool is_break = argc < 2 || std::strcmp(argv[1], "two-ball") != 0;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 200;
  const double speed = argc > 3 ? std::atof(argv[3]) : 8.0;
  // The rack's dither: FastFiz seeds GSL's generator from the clock unless GSL_RNG_SEED is set (and
  // then announces the seed on stderr).
  setenv("GSL_RNG_SEED", argc > 4 ? argv[4] : "8", 1);
  std::fclose(stderr);
  ShotParams shot;
  const TableState start = is_break ? rack(speed, shot) : two_ball(shot);
  TableState probe = start;
  Shot* first = probe.executeShot(shot);
  const std::size_t events = first->getEventList().size();
  delete first;
  std::vector<double> us;
  for (int k = 0; k < runs; ++k) {
    TableState state = start;
    const auto t0 = std::chrono::steady_clock::now();
    delete state.executeShot(shot);
    us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(us.begin(), us.end());
  std::printf("fastfiz %s events %zu us %.3f\n", is_break ? "break" : "two-ball", events, us[us.size() / 2]);
  return 0;
}
