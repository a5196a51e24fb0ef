// fastfiz_side_by_side: this project's physics and FastFiz 0.2's in one process, shot for shot: blocks
// of shots of ours, FastFiz's, FastFiz's, ours (and so on), so both see the same machine at the same
// moments, as FastFiz was measured before (research note break_physics.md). Built by
// tests/bench/physics_ab.sh --fastfiz DIR against a build's libraries and tests/bench/fastfiz_shots.cpp
// (FastFiz is no part of this project); never built by CMake.
//   fastfiz_side_by_side [blocks] [shots a block]
// prints, for each pairing, "NAME us U fastfiz_us F ratio R": the median microseconds of a shot of each.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include "random_scenes.h"
#include "simulate.h"

namespace fastfiz_side {
struct Setup;
Setup* prepare(bool two_ball, double speed, const char* seed);
std::size_t shoot(const Setup* setup);
}  // namespace fastfiz_side

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// `shots` shots of f, each timed, into `us`.
void time_block(const std::function<std::size_t()>& f, int shots, std::vector<double>& us) {
  volatile std::size_t sink = 0;
  for (int k = 0; k < shots; ++k) {
    const auto t0 = Clock::now();
    sink = sink + f();
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }
}

/// `blocks` blocks of each, alternating: `shots` of FastFiz's a block and `ours_each` times as many of ours
/// (about as long).
void side_by_side(const char* name, const bsim::Scene& scene, const fastfiz_side::Setup* ff, int blocks, int shots,
                  int ours_each) {
  const std::function<std::size_t()> ours = [&] { return bsim::simulate_events(scene).events.size(); };
  const std::function<std::size_t()> theirs = [&] { return fastfiz_side::shoot(ff); };
  std::vector<double> a, b;
  for (int k = 0; k < 3; ++k) ours(), theirs();   // warm the caches
  for (int block = 0; block < blocks; ++block) {  // ours, FastFiz's; FastFiz's, ours; ...
    const bool first = block % 2 == 0;
    time_block(first ? ours : theirs, first ? shots * ours_each : shots, first ? a : b);
    time_block(first ? theirs : ours, first ? shots : shots * ours_each, first ? b : a);
  }
  const double us = median(a), ff_us = median(b);
  std::printf("%s us %.3f fastfiz_us %.3f ratio %.4f (ours %zu events, FastFiz's %zu)\n", name, us, ff_us, us / ff_us,
              ours(), theirs());
}

}  // namespace

int main(int argc, char** argv) {
  const int blocks = argc > 1 ? std::atoi(argv[1]) : 20;
  const int shots = argc > 2 ? std::atoi(argv[2]) : 20;
  const fastfiz_side::Setup* rack = fastfiz_side::prepare(false, 8.0, "8");
  const fastfiz_side::Setup* two_ball = fastfiz_side::prepare(true, 0, "8");
  side_by_side("break", bsim::scenes::standard_break(), rack, blocks, shots, 10);
  side_by_side("tight-break", bsim::scenes::tight_break(), rack, blocks, shots, 10);
  side_by_side("two-ball", bsim::scenes::two_ball_shot(), two_ball, blocks, 10 * shots, 6);
  return 0;
}
