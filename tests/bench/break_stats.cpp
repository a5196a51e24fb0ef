// break_stats: N seeded breaks of 9-ball and 8-ball racks (tests/support/break_stats.h), and what they
// pocket beside the real figures; with --sweep, what moves the share (rack gaps, speed, pocket size).
//   break_stats [--breaks N] [--sweep]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "break_stats.h"

namespace {

using bsim::breaks::BreakSetup;
using bsim::breaks::BreakStats;

BreakStats report(const char* name, const BreakSetup& setup, int count, bool histogram) {
  const auto t0 = std::chrono::steady_clock::now();
  const BreakStats s = bsim::breaks::play_breaks(setup, count);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The binomial standard error of the share, for reading differences between lines.
  const double error = std::sqrt(s.share() * (1 - s.share()) / s.breaks);
  std::printf("%-34s %5d breaks  %5.1f%% +- %4.1f pocket a ball  %4.2f down on average  %4.1f%% scratch  (%.1f s)\n",
              name, s.breaks, 100 * s.share(), 100 * error, s.mean_down(), 100 * s.scratch_rate(), seconds);
  if (histogram) {
    std::printf("  %-32s", "object balls down:");
    for (std::size_t n = 0; n < s.histogram.size(); ++n)
      std::printf(" %zu: %4.1f%%", n, 100.0 * s.histogram[n] / s.breaks);
    std::printf("\n");
  }
  return s;
}

void sweep(bsim::RackGame game, int count) {
  const std::string g(bsim::rack_game_name(game));
  BreakSetup base;
  base.game = game;
  BreakSetup v = base;
  v.tight = true;
  report((g + " tight rack").c_str(), v, count, false);
  for (double scale : {0.5, 2.0, 4.0}) {
    v = base;
    v.gap_scale = scale;
    report((g + " gaps x" + std::to_string(scale).substr(0, 3)).c_str(), v, count, false);
  }
  for (double speed : {8.0, 9.0, 12.0}) {
    v = base;
    v.speed = speed;
    report((g + " at " + std::to_string(speed).substr(0, 4) + " m/s").c_str(), v, count, false);
  }
  for (double scale : {0.9, 1.1}) {
    v = base;
    v.pocket_scale = scale;
    report((g + " pockets x" + std::to_string(scale).substr(0, 3)).c_str(), v, count, false);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int count = 1000;
  bool do_sweep = false;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--breaks" && k + 1 < argc) {
      count = static_cast<int>(std::strtol(argv[++k], nullptr, 10));
      if (count <= 0) {
        std::fprintf(stderr, "break_stats: --breaks needs a positive count\n");
        return 2;
      }
    } else if (arg == "--sweep") {
      do_sweep = true;
    } else {
      std::fprintf(stderr, "usage: break_stats [--breaks N] [--sweep]\n");
      return 2;
    }
  }
  std::printf(
      "Breaks: cue ball anywhere behind the head string, aimed at the apex +- 0.3 deg, 10.7 +- 0.8 m/s,\n"
      "a rack seed per break (seeds 1 to %d).\n",
      count);
  BreakSetup nine;
  nine.game = bsim::RackGame::nine_ball;
  report("9ball", nine, count, true);
  std::printf("  real: %.0f%% (2016 WPA World 9-Ball, 105 breaks)\n", 100 * bsim::breaks::kRealShare9Ball);
  BreakSetup eight;
  eight.game = bsim::RackGame::eight_ball;
  report("8ball", eight, count, true);
  std::printf("  real: %.0f%% (an 8-ball event, AZBilliards' break statistics)\n", 100 * bsim::breaks::kRealShare8Ball);
  if (do_sweep) {
    std::printf("What moves the share:\n");
    sweep(bsim::RackGame::nine_ball, count);
    sweep(bsim::RackGame::eight_ball, count);
  }
  return 0;
}
