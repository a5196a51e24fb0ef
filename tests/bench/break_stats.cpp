// break_stats: N seeded player's breaks of 9-ball and 8-ball racks (tests/support/break_stats.h), and the
// share that is legal, makes a ball and does not foul beside the real figures, the share that makes a ball,
// the scratch rate; with --sweep, what moves the share (rack gaps, speed, noise, corner mouths, jaws).
// With --picture FILE it draws the three racks from above instead, their gaps exaggerated (README's picture).
//   break_stats [--breaks N] [--sweep] [--picture FILE]
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "ball_look.h"
#include "break_stats.h"
#include "png_file.h"

namespace {

using bsim::breaks::BreakSetup;
using bsim::breaks::BreakStats;

BreakStats report(const char* name, const BreakSetup& setup, int count, bool detail) {
  const auto t0 = std::chrono::steady_clock::now();
  const BreakStats s = bsim::breaks::play_breaks(setup, count);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The binomial standard error of a share, for reading differences between lines.
  auto error = [&](double p) { return 100 * std::sqrt(p * (1 - p) / s.breaks); };
  std::printf(
      "%-30s %5d breaks  %5.1f%% +- %3.1f made a ball, legal, no foul  %5.1f%% made a ball  %4.1f%% scratch  "
      "%4.2f down  (%.1f s)\n",
      name, s.breaks, 100 * s.success_share(), error(s.success_share()), 100 * s.share(), 100 * s.scratch_rate(),
      s.mean_down(), seconds);
  if (detail) {
    std::printf("  %-28s %5.1f%% legal (a ball made or four to a rail%s)", "", 100 * s.legal_share(),
                setup.game == bsim::RackGame::nine_ball ? ", the 1 first" : "");
    if (setup.game == bsim::RackGame::nine_ball) std::printf(", the 1 not hit first %d times", s.wrong_first);
    std::printf("\n  %-28s", "object balls down:");
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
  for (double noise : {0.0, 2.0}) {
    v = base;
    v.heading_sd_deg *= noise;
    v.elevation_sd_deg *= noise;
    v.tip_sd *= noise;
    v.stick_speed_sd *= noise;
    report((g + " noise x" + std::to_string(noise).substr(0, 3)).c_str(), v, count, false);
  }
  // Tighter and wider corners than the standard table's 4.5875 in (Dr. Dave's TP 3.6 mouth).
  for (double inches : {4.0, 4.25, 4.625}) {
    v = base;
    v.physics.corner_mouth = inches * 0.0254;
    report((g + " corners " + std::to_string(inches).substr(0, 5) + " in").c_str(), v, count, false);
  }
  v = base;
  v.bare_pockets = true;
  report((g + " bare drop circles").c_str(), v, count, false);
}

// ---- the picture: each rack from above, apex on the left, racked as rack.h racks it but with the balls'
// diameters spread kExaggerate times wider than the WPA tolerance, so the gaps show; every ball drawn at
// the nominal size the physics uses, with its colour, stripe and number.

constexpr double kExaggerate = 30.0;
constexpr double kPixelsPerMetre = 1500.0;
constexpr int kPanelWidth = 480, kHeight = 500, kSamples = 4;

/// 3x5 pixel digits, a row per byte's low 3 bits, top row first.
constexpr std::array<std::array<std::uint8_t, 5>, 10> kDigits = {{{7, 5, 5, 5, 7},
                                                                  {2, 6, 2, 2, 7},
                                                                  {7, 1, 7, 4, 7},
                                                                  {7, 1, 7, 1, 7},
                                                                  {5, 5, 7, 1, 1},
                                                                  {7, 4, 7, 1, 7},
                                                                  {7, 4, 7, 5, 7},
                                                                  {7, 1, 1, 1, 1},
                                                                  {7, 5, 7, 5, 7},
                                                                  {7, 5, 7, 1, 7}}};

struct DrawnBall {
  double x = 0, y = 0;  ///< pixels, the centre
  int number = 0;
};

/// Whether the number's digits (each cell `cell` pixels, centred at the ball's centre) cover (px, py).
bool on_digits(const DrawnBall& b, double px, double py, double cell) {
  const std::string text = std::to_string(b.number);
  const double width = (4.0 * static_cast<double>(text.size()) - 1) * cell, height = 5 * cell;
  const double u = (px - (b.x - width / 2)) / cell, v = (py - (b.y - height / 2)) / cell;
  if (u < 0 || v < 0 || v >= 5) return false;
  const auto column = static_cast<int>(u), row = static_cast<int>(v);
  const auto digit = static_cast<std::size_t>(column / 4);
  if (digit >= text.size() || column % 4 == 3) return false;
  const auto bits = kDigits[static_cast<std::size_t>(text[digit] - '0')][static_cast<std::size_t>(row)];
  return (bits >> (2 - column % 4)) & 1;
}

/// The colour at (px, py): cloth, or a ball's paint (stripe band, white number disc, dark digits).
bsim::SrgbColor shade(const std::vector<DrawnBall>& balls, double radius, double px, double py) {
  for (const DrawnBall& b : balls) {
    const double dx = px - b.x, dy = py - b.y;
    if (dx * dx + dy * dy > radius * radius) continue;
    if (dx * dx + dy * dy > (radius - 1.5) * (radius - 1.5)) return {20, 20, 20};  // outline
    if (on_digits(b, px, py, radius / (b.number > 9 ? 7.5 : 6))) return {20, 20, 20};
    if (dx * dx + dy * dy < 0.36 * radius * radius) return bsim::kBallIvory;
    if (bsim::ball_striped(b.number) && std::abs(dy) > 0.55 * radius) return bsim::kBallIvory;
    return bsim::ball_srgb(b.number);
  }
  return {24, 98, 64};  // cloth
}

std::vector<DrawnBall> drawn_rack(bsim::RackGame game, std::uint64_t seed, int panel) {
  bsim::RackSpec spec;
  spec.game = game;
  spec.seed = seed;
  spec.tolerance *= kExaggerate;
  std::vector<DrawnBall> out;
  for (const bsim::RackedBall& b : bsim::rack_balls(spec))
    out.push_back({panel * kPanelWidth + 60 + (b.x - bsim::kFootSpotX) * kPixelsPerMetre,
                   kHeight / 2.0 - b.y * kPixelsPerMetre, b.number});
  return out;
}

int picture(const std::string& path) {
  std::vector<DrawnBall> balls;
  const bsim::RackGame games[] = {bsim::RackGame::eight_ball, bsim::RackGame::nine_ball, bsim::RackGame::ten_ball};
  const std::uint64_t seeds[] = {7, 0, 0};  // the built-in break's 8-ball rack; the others' default seed
  for (int panel = 0; panel < 3; ++panel) {
    const std::vector<DrawnBall> rack = drawn_rack(games[panel], seeds[panel], panel);
    balls.insert(balls.end(), rack.begin(), rack.end());
  }
  const double radius = bsim::PhysicsParams{}.ball_radius * kPixelsPerMetre;
  const int width = 3 * kPanelWidth;
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * kHeight * 3);
  for (int py = 0; py < kHeight; ++py)
    for (int px = 0; px < width; ++px) {
      int sum[3] = {0, 0, 0};
      for (int s = 0; s < kSamples * kSamples; ++s) {
        const bsim::SrgbColor c =
            shade(balls, radius, px + (s % kSamples + 0.5) / kSamples, py + (s / kSamples + 0.5) / kSamples);
        sum[0] += c.r;
        sum[1] += c.g;
        sum[2] += c.b;
      }
      for (int k = 0; k < 3; ++k)
        rgb[(static_cast<std::size_t>(py) * width + px) * 3 + k] =
            static_cast<std::uint8_t>(sum[k] / (kSamples * kSamples));
    }
  std::string error;
  if (!bsim::write_png(path, rgb, width, kHeight, error)) {
    std::fprintf(stderr, "break_stats: %s\n", error.c_str());
    return 1;
  }
  std::printf("wrote %s: 8-ball seed 7, 9-ball and 10-ball seed 0, diameters spread %.0f times the WPA tolerance\n",
              path.c_str(), kExaggerate);
  return 0;
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
    } else if (arg == "--picture" && k + 1 < argc) {
      return picture(argv[k + 1]);
    } else {
      std::fprintf(stderr, "usage: break_stats [--breaks N] [--sweep] [--picture FILE]\n");
      return 2;
    }
  }
  const BreakSetup setup;
  std::printf(
      "A player's break: the cue ball anywhere behind the head string, stroked (a `stroke`: strike.h) at the apex\n"
      "ball's centre, level, centre ball, for %.1f m/s, with the Computational Pool Olympiad's noise (standard\n"
      "deviations %.3f deg of heading, %.1f deg of elevation, %.1f mm of each tip offset, %.3f m/s of the stick's\n"
      "speed); a rack seed per break (seeds 1 to %d).\n",
      setup.speed, setup.heading_sd_deg, setup.elevation_sd_deg, setup.tip_sd * 1000, setup.stick_speed_sd, count);
  BreakSetup nine;
  nine.game = bsim::RackGame::nine_ball;
  report("9ball", nine, count, true);
  std::printf("  real: %.0f%% made a ball, legal, no foul (2016 WPA World 9-Ball, 75 of 105 breaks)\n",
              100 * bsim::breaks::kRealShare9Ball);
  BreakSetup eight;
  eight.game = bsim::RackGame::eight_ball;
  report("8ball", eight, count, true);
  std::printf("  real: %.0f%% made a ball, no foul (2024 Ultimate Pool Colorado Shootout, 82 of 124 breaks)\n",
              100 * bsim::breaks::kRealShare8Ball);
  if (do_sweep) {
    std::printf("What moves the share:\n");
    sweep(bsim::RackGame::nine_ball, count);
    sweep(bsim::RackGame::eight_ball, count);
  }
  return 0;
}
