// aim_bench: the time `cue I pot B P` takes to find its heading (aim.h) on a 16-ball table: the cue
// ball, the 5 to cut into the top-right corner, and fourteen more balls spread over the table (none in
// the way), so every shot the solver plays moves a full table's worth of balls.
//   aim_bench [--runs N] [SCENE]   N aims timed (default 50); prints the median and the shots played per
//                                  aim, and the ghost-ball heading beside the one found (SCENE: instead
//                                  of the 16-ball table, a scene file whose cue aims)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "aim.h"
#include "scene_parse.h"
#include "simulate.h"
#include "spread_balls.h"

namespace {

using Clock = std::chrono::steady_clock;

std::string sixteen_balls() {
  std::string text = "cue 0 pot 1 2\n";
  text += "ball 0 0.3 -0.2 0.028575 2 0 0 1 0 0 0\n";
  text += "ball 5 0.7 0.1 0.028575 0 0 0 1 0 0 0\n";
  text += bsim::bench::spread_ball_lines();
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 50;
  std::string text = sixteen_balls();
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else {
      std::ifstream in(argv[i]);
      std::stringstream buffer;
      buffer << in.rdbuf();
      text = buffer.str();
    }
  }
  const bsim::ParseResult parsed = bsim::parse_scene(text, "aim_bench");
  if (!parsed.scene || !parsed.scene->cue().aims()) {
    std::fprintf(stderr, "aim_bench: the scene does not parse or its cue does not aim\n");
    return 1;
  }
  const bsim::Scene& scene = *parsed.scene;
  const bsim::AimResult probe = bsim::aim_cue(scene);
  if (!probe.heading_deg) {
    std::fprintf(stderr, "aim_bench: %s\n", probe.failure.c_str());
    return 1;
  }
  std::vector<double> ms;
  for (int k = 0; k < runs; ++k) {
    const auto t0 = Clock::now();
    const bsim::AimResult aim = bsim::aim_cue(scene);
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    if (aim.heading_deg != probe.heading_deg) {
      std::fprintf(stderr, "aim_bench: the heading changed between runs\n");
      return 1;
    }
  }
  std::sort(ms.begin(), ms.end());
  const bsim::Vec3 from = scene.ball(scene.cue().target).position;
  const double ghost = std::atan2(probe.ghost.y() - from.y(), probe.ghost.x() - from.x()) * 180 / std::numbers::pi;
  std::printf("ghost-ball heading %.6f deg, found %.6f deg (%+.4f)\n", ghost, *probe.heading_deg,
              *probe.heading_deg - ghost);
  const double median = ms[ms.size() / 2];
  std::printf("aim, %zu balls: heading %.6f deg, %d shots played, %.2f ms per aim (median of %d), %.3f ms a shot\n",
              scene.balls.size(), *probe.heading_deg, probe.simulations, median, runs, median / probe.simulations);
  return 0;
}
