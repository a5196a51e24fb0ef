// bench: how fast the physics runs, and a soak that looks for faults in many random breaks.
//   bench                 figures for a break, a two-ball shot and a 100-ball table; a 1,000-break soak
//   bench --soak N        the soak over N seeded breaks (100000 for the full run)
//   bench --runs N        timed runs per scene (default 2000, fewer for the stress table)
//   bench --no-soak       the figures alone
//   bench --fingerprint N a hash of every bit the physics gives (segments, events, drops) for each scene
//                         and for N seeded random breaks and 100-ball tables: the same hashes from two
//                         builds mean the same events to the bit (tests/bench/physics_ab.sh)
//   bench --scene NAME    one scene's physics alone (break, tight-break, two-ball, stress-100): its events
//                         and the median us per shot, on one line; for tests/bench/physics_ab.sh and
//                         for profiling
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "group.h"
#include "motion.h"
#include "physics_fingerprint.h"
#include "random_scenes.h"
#include "shot_checks.h"
#include "simulate.h"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class F>
double median_us(int runs, F&& f) {
  std::vector<double> us;
  us.reserve(static_cast<std::size_t>(runs));
  for (int k = 0; k < runs; ++k) {
    const auto t0 = Clock::now();
    f();
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }
  return median(us);
}

void figures(const char* name, const bsim::Scene& scene, int runs) {
  const bsim::SimulationResult probe = bsim::simulate_events(scene);
  const long events = static_cast<long>(probe.events.size());
  long segments = 0;
  for (const auto& list : probe.segments) segments += static_cast<long>(list.size());
  for (int k = 0; k < 3; ++k) bsim::simulate_events(scene);  // warm the caches
  volatile std::size_t sink = 0;
  const double physics = median_us(runs, [&] { sink = sink + bsim::simulate_events(scene).events.size(); });
  const double full = median_us(runs, [&] { sink = sink + bsim::simulate(scene).events().size(); });
  std::printf(
      "%-12s %4zu balls %6ld events %6ld segments %7ld tests  %10.1f us/shot  %10.1f us with orientation  %9.0f "
      "events/s  %ld groups, %ld group steps\n",
      name, scene.balls.size(), events, segments, probe.candidates_tested, physics, full,
      static_cast<double>(events) / (physics * 1e-6), probe.groups, probe.group_steps);
}

/// One scene's physics alone, as physics_ab.sh compares two builds: its events and the median us per
/// shot of `runs` (4 + runs shots in all, so valgrind's count at two values of `runs` gives a shot's
/// instructions).
void one_scene(const char* name, const bsim::Scene& scene, int runs) {
  const long events = static_cast<long>(bsim::simulate_events(scene).events.size());
  volatile std::size_t sink = 0;
  for (int k = 0; k < 3; ++k) sink = sink + bsim::simulate_events(scene).events.size();  // warm the caches
  const double us = median_us(runs, [&] { sink = sink + bsim::simulate_events(scene).events.size(); });
  std::printf("%s events %ld us %.3f\n", name, events, us);
}

/// The fingerprints of the bench's scenes and of `count` seeded random breaks and 100-ball tables.
void fingerprints(long count) {
  const std::pair<const char*, bsim::Scene> scenes[] = {{"break", bsim::scenes::standard_break()},
                                                        {"tight-break", bsim::scenes::tight_break()},
                                                        {"two-ball", bsim::scenes::two_ball_shot()},
                                                        {"stress-100", bsim::scenes::stress_table(100, 7)}};
  for (const auto& [name, scene] : scenes) {
    bsim::test::PhysicsFingerprint f;
    f.add(bsim::simulate_events(scene));
    std::printf("fingerprint %s %016llx\n", name, static_cast<unsigned long long>(f.hash()));
  }
  bsim::test::PhysicsFingerprint breaks, tables;
  long events = 0;
  for (long seed = 1; seed <= count; ++seed) {
    const bsim::SimulationResult r =
        bsim::simulate_events(bsim::scenes::random_break(static_cast<std::uint64_t>(seed)));
    events += static_cast<long>(r.events.size());
    breaks.add(r);
    if (seed <= count / 20 + 1)
      tables.add(bsim::simulate_events(bsim::scenes::stress_table(100, static_cast<std::uint64_t>(seed))));
  }
  std::printf("fingerprint %ld-random-breaks %016llx (%ld events)\n", count,
              static_cast<unsigned long long>(breaks.hash()), events);
  std::printf("fingerprint %ld-stress-tables %016llx\n", count / 20 + 1,
              static_cast<unsigned long long>(tables.hash()));
}

bool scene_named(const std::string& name, bsim::Scene& scene) {
  if (name == "break")
    scene = bsim::scenes::standard_break();
  else if (name == "tight-break")
    scene = bsim::scenes::tight_break();
  else if (name == "two-ball")
    scene = bsim::scenes::two_ball_shot();
  else if (name == "stress-100")
    scene = bsim::scenes::stress_table(100, 7);
  else
    return false;
  return true;
}

/// The group phase alone: the cue ball at 10 m/s touching the apex of the first `count` - 1 balls of a
/// tight rack (whole rows first), all in one group.
void group_cost(int runs) {
  std::printf("group phase (cue ball at 10 m/s on a tight rack of the first N-1 balls):\n");
  for (int count : {2, 3, 4, 7, 11, 16}) {
    const bsim::Scene rack = bsim::scenes::tight_break(10.0);
    const bsim::PhysicsParams params;
    std::vector<bsim::BallState> balls;
    for (int i = 0; i < count; ++i) {
      bsim::BallState s;
      s.position = rack.balls[static_cast<std::size_t>(i)].position;
      balls.push_back(s);
    }
    balls[0].position = balls[1].position - bsim::Vec3(2 * params.ball_radius, 0, 0);
    balls[0].velocity = bsim::Vec3(10, 0, 0);
    balls[0] = bsim::classify(balls[0], params);
    const bsim::GroupResult probe = bsim::resolve_group(balls, params);
    volatile long sink = 0;
    const double us = median_us(runs, [&] { sink = sink + bsim::resolve_group(balls, params).steps; });
    std::printf("  N = %2d balls: %5ld steps, %3zu contacts, %8.1f us, %6.3f us a step\n", count, probe.steps,
                probe.contacts.size(), us, us / static_cast<double>(probe.steps));
  }
}

int soak(long count) {
  bsim::checks::Faults sum;
  long events = 0, drops = 0, faulty = 0, cut_offs = 0;
  const auto t0 = Clock::now();
  for (long seed = 1; seed <= count; ++seed) {
    const bsim::Scene scene = bsim::scenes::random_break(static_cast<std::uint64_t>(seed));
    bsim::SimulationResult result = bsim::simulate_events(scene);
    cut_offs += result.cut_off ? 1 : 0;
    const bsim::Timeline timeline(scene, std::move(result.segments), std::move(result.events), std::move(result.drops));
    const bsim::checks::Faults f = bsim::checks::find_faults(scene, timeline);
    events += static_cast<long>(timeline.events().size());
    drops += static_cast<long>(timeline.pocket_drops().size());
    sum.overlaps += f.overlaps;
    sum.escapes += f.escapes;
    sum.nans += f.nans;
    sum.missed += f.missed;
    sum.energy_gains += f.energy_gains;
    sum.deepest = std::max(sum.deepest, f.deepest);
    if (f.total() > 0 && faulty++ < 10)
      std::printf("  seed %ld: %ld overlaps, %ld escapes, %ld NaN, %ld missed, %ld energy gains\n", seed, f.overlaps,
                  f.escapes, f.nans, f.missed, f.energy_gains);
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("soak: %ld random breaks, %ld events, %ld balls pocketed, %.1f s\n", count, events, drops, seconds);
  std::printf(
      "soak: %ld overlaps, %ld rail escapes, %ld NaN, %ld missed contacts, %ld energy gains, %ld cut off "
      "(%ld faulty breaks)\n",
      sum.overlaps, sum.escapes, sum.nans, sum.missed, sum.energy_gains, cut_offs, faulty);
  std::printf("soak: deepest overlap of two balls or a ball and a cushion: %.3g m (faults from %.3g m)\n", sum.deepest,
              bsim::checks::kFaultTolerance);
  return sum.total() == 0 && cut_offs == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  long soak_count = 1000;
  int runs = 2000;
  bool soak_only = false, figures_only = false;
  std::string only;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--scene" && k + 1 < argc) {
      only = argv[++k];
    } else if (arg == "--no-soak") {
      figures_only = true;
    } else if ((arg == "--soak" || arg == "--runs" || arg == "--fingerprint") && k + 1 < argc) {
      const long value = std::strtol(argv[++k], nullptr, 10);
      if (value <= 0) {
        std::fprintf(stderr, "bench: %s needs a positive count\n", arg.c_str());
        return 2;
      }
      if (arg == "--fingerprint") {
        fingerprints(value);
        return 0;
      }
      if (arg == "--soak") {
        soak_count = value;
        soak_only = true;
      } else {
        runs = static_cast<int>(value);
      }
    } else {
      std::fprintf(stderr, "usage: bench [--soak N | --no-soak] [--runs N] [--scene NAME] [--fingerprint N]\n");
      return 2;
    }
  }
  if (!only.empty()) {
    bsim::Scene scene;
    if (!scene_named(only, scene)) {
      std::fprintf(stderr, "bench: no scene %s (break, tight-break, two-ball, stress-100)\n", only.c_str());
      return 2;
    }
    one_scene(only.c_str(), scene, runs);
    return 0;
  }
  if (!soak_only) {
    figures("break", bsim::scenes::standard_break(), runs);
    figures("tight-break", bsim::scenes::tight_break(), runs);
    figures("two-ball", bsim::scenes::two_ball_shot(), runs);
    figures("stress-100", bsim::scenes::stress_table(100, 7), std::max(5, runs / 50));
    group_cost(std::max(5, runs / 4));
  }
  return figures_only ? 0 : soak(soak_count);
}
