// shots_bench: a scene of twenty shots on a full table, every one aimed (`cue 0 pot 5 2`) from where the
// one before left the balls, the cue ball and the 5 put back by `place` lines and every other ball left
// where the shots scatter it; strokes cycle through stun, draw, follow and english. Prints, side by
// side in one run:
//   - play: the twenty shots aimed and simulated into one timeline (play.h), the figure issue 27 bounds
//     (under a second);
//   - load: the whole of load_shot (play, then the camera script, the stick and their checks), what a
//     front end waits for;
//   - alone: the baseline, each shot aimed and simulated by itself from the same balls (the sum);
// and the timeline's size: events, motion segments and their bytes (it grows with the events, not the
// frames: nothing is sampled).
//   shots_bench [--runs N] [--shots K] [SCENE]   N runs (default 5, median); K shots (default 20); SCENE: time
//                                               a scene file instead
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "aim.h"
#include "play.h"
#include "shot.h"
#include "simulate.h"
#include "spread_balls.h"

namespace {

using Clock = std::chrono::steady_clock;

std::string twenty_shots(int shots) {
  std::string text = "ball 0 0.3 -0.2 0.028575 0 0 0 1 0 0 0\nball 5 0.7 0.1 0.028575 0 0 0 1 0 0 0\n";
  text += bsim::bench::spread_ball_lines();
  const char* strokes[4] = {"1.6 0 0 0", "1.8 0 -0.35 0", "1.5 0 0.3 0", "1.7 0.3 0 2"};
  for (int k = 0; k < shots; ++k) {
    text += "cue 0 pot 1 2\nstroke " + std::string(strokes[k % 4]) + "\n";
    if (k > 0) text += "place 0\nplace 1\n";
  }
  return text;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

int main(int argc, char** argv) {
  int runs = 5, shots = 20;
  std::string text;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--shots") == 0 && i + 1 < argc) {
      shots = std::max(1, std::atoi(argv[++i]));
    } else {
      std::ifstream in(argv[i]);
      std::stringstream buffer;
      buffer << in.rdbuf();
      text = buffer.str();
    }
  }
  if (text.empty()) text = twenty_shots(shots);
  const bsim::ParseResult parsed = bsim::parse_scene(text, "shots_bench");
  if (!parsed.scene) {
    for (const auto& d : parsed.diagnostics) std::fprintf(stderr, "%s\n", bsim::format_diagnostic(d, "scene").c_str());
    return 1;
  }
  std::vector<double> play_s, load_s, alone_s;
  bsim::Scene played_scene;
  bsim::Timeline timeline;
  for (int r = 0; r < runs; ++r) {
    bsim::Scene scene = *parsed.scene;
    Clock::time_point start = Clock::now();
    bsim::PlayResult played = bsim::play(scene);
    play_s.push_back(seconds_since(start));
    if (played.failure) {
      std::fprintf(stderr, "shot %d: %s\n", played.failure->shot + 1, played.failure->message.c_str());
      return 1;
    }
    played_scene = scene;
    timeline = played.timeline;

    start = Clock::now();
    const bsim::ShotResult loaded = bsim::load_shot(text, "shots_bench");
    load_s.push_back(seconds_since(start));
    if (!loaded.scripted()) return 1;

    // The baseline: each shot alone from where the chain found the balls, aimed and simulated.
    start = Clock::now();
    for (int k = 0; k < scene.shot_count(); ++k) {
      bsim::Scene alone = scene;
      alone.cues = {parsed.scene->cues[static_cast<std::size_t>(k)]};
      for (int b = 0; b < timeline.ball_count(); ++b) {
        const bsim::BallState s = timeline.motion_state(b, timeline.shots()[static_cast<std::size_t>(k)].start);
        auto& ball = alone.balls[static_cast<std::size_t>(b)];
        ball.position = s.position;
        ball.velocity.setZero();
        ball.spin.setZero();
        ball.pocket = s.motion == bsim::Motion::pocketed ? 0 : -1;
      }
      if (alone.cue().aims()) bsim::apply_aim(alone);
      (void)bsim::simulate_events(alone);
    }
    alone_s.push_back(seconds_since(start));
  }
  std::size_t segments = 0;
  for (int b = 0; b < timeline.ball_count(); ++b) segments += timeline.segments(b).size();
  std::size_t contacts = 0;
  for (const bsim::Event& e : timeline.events()) contacts += e.contacts.size();
  const double bytes =
      static_cast<double>(segments * sizeof(bsim::MotionSegment) + timeline.events().size() * sizeof(bsim::Event) +
                          contacts * sizeof(bsim::Contact));
  std::printf("%d shots, %d balls, %.1f s of play, median of %d runs\n", timeline.shot_count(), timeline.ball_count(),
              timeline.duration(), runs);
  std::printf("  %-44s %8.1f ms\n", "play (aim + simulate, one timeline)", 1e3 * median(play_s));
  std::printf("  %-44s %8.1f ms\n", "load_shot (play + camera, stick, checks)", 1e3 * median(load_s));
  std::printf("  %-44s %8.1f ms\n", "baseline: each shot aimed and simulated alone", 1e3 * median(alone_s));
  std::printf("  timeline: %zu events, %zu contacts, %zu motion segments, about %.0f kB (%.1f kB a shot)\n",
              timeline.events().size(), contacts, segments, bytes / 1024, bytes / 1024 / timeline.shot_count());
  std::printf("  pocketed: %zu balls; every shot pots: %s\n", timeline.pocket_drops().size(),
              timeline.pocket_drops().size() >= static_cast<std::size_t>(timeline.shot_count()) ? "yes" : "no");
  return 0;
}
