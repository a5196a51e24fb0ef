// The Timeline answers every query from steps saved once per segment (the orientation's integration
// grid, a pocket fall every few steps), and the camera's ball tracks read it. These tests hold them
// to the direct evaluation, bit for bit: each state worked out from its segment's start alone with
// evolve, advance_orientation and fall_state (test::DirectStates), each segment's starting
// orientation carried from the first segment. Any drift in the resumed path fails here
// (trajectory.csv and camera.csv print every number exactly and are compared byte for byte).
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "ball_track.h"
#include "builtin_scene.h"
#include "direct_states.h"
#include "files.h"
#include "motion.h"
#include "pocket_fall.h"
#include "shot.h"
#include "shots.h"
#include "support.h"

using namespace bsim;

namespace {

bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

bool same(const Vec3& a, const Vec3& b) { return same(a.x(), b.x()) && same(a.y(), b.y()) && same(a.z(), b.z()); }

bool same(const Quat& a, const Quat& b) {
  return same(a.w(), b.w()) && same(a.x(), b.x()) && same(a.y(), b.y()) && same(a.z(), b.z());
}

bool same(const BallState& a, const BallState& b) {
  return same(a.position, b.position) && same(a.velocity, b.velocity) && same(a.spin, b.spin) &&
         same(a.orientation, b.orientation) && a.motion == b.motion;
}

struct Coverage {
  long states = 0;
  long falling = 0;      ///< states queried inside a pocket fall
  long integrated = 0;   ///< segments whose orientation is integrated (the axis turns)
  long track_falls = 0;  ///< ball-track positions inside a pocket fall
};

/// Every query time: the frames at 24, 30 and 60 fps, dense steps through every pocket fall, every segment boundary,
/// and a third of them again in a shuffled order.
std::vector<double> query_times(const Timeline& timeline) {
  std::vector<double> times;
  const double duration = timeline.duration();
  for (int fps : {24, 30, 60})
    for (int k = 0; k / static_cast<double>(fps) < duration; ++k) times.push_back(k / static_cast<double>(fps));
  for (int b = 0; b < timeline.ball_count(); ++b) {
    const std::vector<MotionSegment>& list = timeline.segments(b);
    for (std::size_t k = 0; k < list.size(); ++k) {
      times.push_back(list[k].t0);
      if (list[k].start.motion != Motion::falling) continue;
      const double end = k + 1 < list.size() ? list[k + 1].t0 : duration;
      for (double t = list[k].t0; t <= end + 0.01; t += kFallStep * 0.37) times.push_back(t);
    }
  }
  times.push_back(duration);
  times.push_back(duration + 1);
  // A third of them again, shuffled: enough to show the answers do not depend on the order, and the
  // suite stays quick in the sanitizer build.
  std::vector<double> shuffled;
  for (std::size_t k = 0; k < times.size(); k += 3) shuffled.push_back(times[k]);
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
  times.insert(times.end(), shuffled.begin(), shuffled.end());
  return times;
}

Coverage check_shot(const Shot& shot) {
  Coverage coverage;
  const Timeline& timeline = shot.timeline;
  const test::DirectStates reference(shot.scene, timeline);
  for (int b = 0; b < timeline.ball_count(); ++b) {
    const std::vector<MotionSegment>& list = timeline.segments(b);
    for (std::size_t k = 0; k < list.size(); ++k) {
      CAPTURE(b);
      CAPTURE(k);
      CHECK(same(list[k].start.orientation, reference.segments(b)[k].start.orientation));
      const double end = k + 1 < list.size() ? list[k + 1].t0 : timeline.duration();
      if (!orientation_steps(list[k].start, timeline.physics(), end - list[k].t0).empty()) ++coverage.integrated;
    }
  }

  const std::vector<double> times = query_times(timeline);
  long mismatches = 0;
  for (double t : times)
    for (int b = 0; b < timeline.ball_count(); ++b) {
      const BallState expected = reference.state(b, t);
      const BallState got = timeline.state(b, t);
      const BallState motion = timeline.motion_state(b, t);
      ++coverage.states;
      if (reference.falling(b, t)) ++coverage.falling;
      if (!same(got, expected) || !same(motion.position, expected.position) ||
          !same(motion.velocity, expected.velocity) || !same(motion.spin, expected.spin) ||
          motion.motion != expected.motion) {
        if (++mismatches <= 5) {
          CAPTURE(b);
          CAPTURE(t);
          FAIL_CHECK("state differs from the direct evaluation");
        }
      }
    }
  CHECK(mismatches == 0);

  // The ball tracks: where a look or follow camera points, up to the moment the ball drops from sight.
  long track_mismatches = 0;
  for (int b = 0; b < timeline.ball_count(); ++b) {
    const BallTrack track(timeline, b, std::nullopt);
    for (double t : times) {
      const double shown = std::min(t, track.hidden_time());
      if (reference.falling(b, shown)) ++coverage.track_falls;
      const Vec3 position = track.position(t);
      if (!same(position, reference.state(b, shown).position) && ++track_mismatches <= 5) {
        CAPTURE(b);
        CAPTURE(t);
        FAIL_CHECK("ball track position differs from the direct evaluation");
      }
    }
  }
  CHECK(track_mismatches == 0);
  return coverage;
}

}  // namespace

TEST_SUITE("timeline sampling") {
  TEST_CASE("every state is the direct evaluation's, bit for bit, in every scene and in any order") {
    Coverage total;
    // The built-in break (what billiards-export runs without a scene) and every other gallery scene.
    std::vector<std::string> names = {"", "bank", "camera_tour", "cut_corner", "draw", "follow"};
    for (const std::string& name : names) {
      CAPTURE(name);
      const auto shot = name.empty()
                            ? test::load_scene(builtin_scene_text(), kBuiltinSceneName)
                            : test::load_scene(test::require_file(test::source_path("scenes/" + name + ".scn")), name);
      const Coverage c = check_shot(*shot);
      total.states += c.states;
      total.falling += c.falling;
      total.integrated += c.integrated;
      total.track_falls += c.track_falls;
    }
    // A cue ball with side spin: its axis turns, so its orientation is integrated step by step.
    const auto english = test::load_scene(
        "cue 0 10\nball 0 -0.6 -0.1 0.028575 1.4 0.25 0 1 0 0 0\nball 1 0.3 0.05 0.028575 0 0 0 1 0 0 0\n"
        "spin 0 -8 40 35\n");
    const Coverage c = check_shot(*english);
    total.integrated += c.integrated;
    // The checks above only mean something if they reached the integrated parts.
    MESSAGE("states compared: " << total.states);
    CHECK(total.states > 50000);
    CHECK(total.falling > 1000);
    CHECK(total.integrated > 0);
    CHECK(total.track_falls > 100);
  }

  TEST_CASE("a fall resumed from its saves is fall_state from the entry") {
    const PhysicsParams physics;
    const Pocket pocket{Vec3(0.9, 0.45, 0), 0.06, {}};
    for (double speed : {0.02, 0.4, 2.5}) {
      CAPTURE(speed);
      BallState entry;
      entry.position = Vec3(0.87, 0.42, physics.ball_radius);
      entry.velocity = Vec3(speed, 0.6 * speed, 0);
      entry.spin = Vec3(-3, 5, 2);
      entry.motion = Motion::falling;
      const double duration = fall_duration(entry, pocket, physics);
      // Saved over all of it, over part of it (later queries step on from the last save), and not at all.
      for (double saved : {duration, 0.4 * duration, 0.0}) {
        const FallPath path(entry, pocket, physics, saved);
        long mismatches = 0;
        for (double dt = -kFallStep; dt <= duration + 0.05; dt += kFallStep * 0.29) {
          const BallState expected = fall_state(entry, pocket, physics, dt), got = path.state(dt);
          if (!same(got, expected)) ++mismatches;
        }
        for (long i = 0; i * kFallStep <= duration + 0.01; ++i) {
          const double dt = static_cast<double>(i) * kFallStep;  // exactly on the grid
          if (!same(path.state(dt), fall_state(entry, pocket, physics, dt))) ++mismatches;
        }
        CHECK(mismatches == 0);
      }
    }
  }

  TEST_CASE("an orientation resumed from its saved steps is advance_orientation from the start") {
    const PhysicsParams physics;
    BallState s;
    s.velocity = Vec3(1.2, 0.3, 0);
    s.spin = Vec3(-5, 30, 25);
    s.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    for (Motion motion : {Motion::sliding, Motion::rolling}) {
      s.motion = motion;
      if (motion == Motion::rolling) s = classify(s, physics);
      CAPTURE(static_cast<int>(s.motion));
      const double end = std::min(transition_time(s, physics), 4.0);
      for (double saved : {end, 0.3 * end, 0.0}) {
        const std::vector<Quat> steps = orientation_steps(s, physics, saved);
        if (saved > kOrientationStep) CHECK_FALSE(steps.empty());
        long mismatches = 0;
        for (double dt = 0; dt <= end; dt += kOrientationStep * 0.173) {
          if (!same(advance_orientation(s, physics, dt, steps), advance_orientation(s, physics, dt))) ++mismatches;
        }
        for (long i = 0; static_cast<double>(i) * kOrientationStep <= end; ++i) {
          const double dt = static_cast<double>(i) * kOrientationStep;  // exactly on the grid
          if (!same(advance_orientation(s, physics, dt, steps), advance_orientation(s, physics, dt))) ++mismatches;
        }
        CHECK(mismatches == 0);
      }
    }
    // Where the axis is fixed there is nothing to save.
    BallState rolling;
    rolling.velocity = Vec3(1, 0, 0);
    rolling.motion = Motion::rolling;
    CHECK(orientation_steps(classify(rolling, physics), physics, 1.0).empty());
  }
}
