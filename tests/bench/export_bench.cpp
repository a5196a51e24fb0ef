// export_bench: where `billiards-export --events-only` spends its time on the built-in break, part by
// part, beside a baseline run in the same process: the exporter as it was, every state integrated
// from its segment's start (test::DirectStates), the ball tracks' second pass over their samples, and
// every trajectory.csv row formatted anew. Both build the camera script from the same timeline.
//   export_bench [--fps N] [--runs N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "builtin_scene.h"
#include "direct_states.h"
#include "frames.h"
#include "number_format.h"
#include "outputs.h"
#include "shot.h"

namespace {

using Clock = std::chrono::steady_clock;

template <class F>
double median_ms(int runs, F&& f) {
  std::vector<double> ms;
  for (int k = 0; k < runs; ++k) {
    const auto t0 = Clock::now();
    f();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

/// trajectory.csv as the exporter wrote it before: every number of every row formatted on its own.
void write_trajectory_baseline(const bsim::Timeline& timeline, const bsim::test::DirectStates& states, int fps,
                               std::ostream& out) {
  out << "time,ball,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz,state\n";
  const int frames = bsim::frame_count(timeline.duration(), fps);
  std::string row;
  for (int k = 0; k < frames; ++k) {
    const double t = bsim::frame_time(k, fps);
    const std::string time = bsim::format_number(t);
    for (int i = 0; i < timeline.ball_count(); ++i) {
      const bsim::BallState s = states.state(i, t);
      const bsim::Quat& q = s.orientation;
      row = time + ',' + std::to_string(i);
      for (double v : {s.position.x(), s.position.y(), s.position.z(), s.velocity.x(), s.velocity.y(), s.velocity.z(),
                       s.spin.x(), s.spin.y(), s.spin.z(), q.w(), q.x(), q.y(), q.z()})
        row += ',' + bsim::format_number(v);
      row += ',';
      row += bsim::to_string(s.motion);
      row += '\n';
      out << row;
    }
  }
}

/// The second pass the camera's ball tracks made before: the position at every 2 ms sample of the
/// path, each from the timeline again (a pocketed ball's from its fall's entry up to where it drops
/// from sight).
double track_second_pass(const bsim::Timeline& timeline, const bsim::test::DirectStates& states,
                         const std::vector<std::pair<int, double>>& tracks) {
  double sum = 0;
  const double step = 1.0 / 500.0, duration = timeline.duration();
  const int samples = static_cast<int>(std::ceil(duration / step)) + 1;
  for (const auto& [ball, hidden] : tracks)
    for (int i = 0; i < samples; ++i)
      sum += states.motion_state(ball, std::min(std::min(i * step, duration), hidden)).position.x();
  return sum;
}

}  // namespace

int main(int argc, char** argv) {
  int fps = 30, runs = 50;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if ((arg == "--fps" || arg == "--runs") && k + 1 < argc) {
      const long value = std::strtol(argv[++k], nullptr, 10);
      if (value <= 0 || value > 1000) {
        std::fprintf(stderr, "export_bench: %s needs a count from 1 to 1000\n", arg.c_str());
        return 2;
      }
      (arg == "--fps" ? fps : runs) = static_cast<int>(value);
    } else {
      std::fprintf(stderr, "usage: export_bench [--fps N] [--runs N]\n");
      return 2;
    }
  }

  const bsim::ShotResult loaded = bsim::load_shot(bsim::builtin_scene_text(), bsim::kBuiltinSceneName);
  if (!loaded.scripted()) {
    std::fprintf(stderr, "export_bench: the built-in scene does not load\n");
    return 1;
  }
  const bsim::Shot& shot = *loaded.shot;
  bsim::Shot now, baseline;
  now.scene = baseline.scene = shot.scene;
  now.timeline = shot.timeline;
  baseline.timeline = shot.timeline;
  const bsim::test::DirectStates direct(shot.scene, shot.timeline);

  // The balls the camera watches, and when each drops from sight.
  std::vector<std::pair<int, double>> tracks;
  for (const bsim::CameraShot& camera : shot.camera->shots()) {
    if (camera.mode == bsim::CameraMode::hover) continue;
    if (std::none_of(tracks.begin(), tracks.end(), [&](const auto& t) { return t.first == camera.ball; }))
      tracks.emplace_back(camera.ball, bsim::BallTrack(shot.timeline, camera.ball, std::nullopt).hidden_time());
  }

  std::vector<bsim::Diagnostic> diagnostics;
  volatile double sink = 0;
  std::ostringstream out;
  std::string now_trajectory, now_camera, base_trajectory, base_camera;
  const double simulate = median_ms(runs, [&] { bsim::simulate(shot.scene); });
  const double camera_now = median_ms(runs, [&] {
    now.camera = bsim::CameraScript::build(now.scene, now.timeline, diagnostics);
    out.str("");
    bsim::write_camera_csv(now, fps, out);
    now_camera = out.str();
  });
  const double camera_base = median_ms(runs, [&] {
    baseline.camera = bsim::CameraScript::build(baseline.scene, baseline.timeline, diagnostics);
    sink = sink + track_second_pass(baseline.timeline, direct, tracks);
    out.str("");
    bsim::write_camera_csv(baseline, fps, out);
    base_camera = out.str();
  });
  const double trajectory_now = median_ms(runs, [&] {
    out.str("");
    bsim::write_trajectory_csv(now, fps, out);
    now_trajectory = out.str();
  });
  const double trajectory_base = median_ms(runs, [&] {
    out.str("");
    write_trajectory_baseline(baseline.timeline, direct, fps, out);
    base_trajectory = out.str();
  });

  std::printf("billiards-export --events-only, built-in break (%d balls, %g s), %d fps: median ms of %d runs\n",
              shot.timeline.ball_count(), shot.timeline.duration(), fps, runs);
  std::printf("%-28s %10s %10s\n", "part", "now", "baseline");
  std::printf("%-28s %10.3f %10.3f\n", "simulate (same code)", simulate, simulate);
  std::printf("%-28s %10.3f %10.3f\n", "camera script + camera.csv", camera_now, camera_base);
  std::printf("%-28s %10.3f %10.3f\n", "trajectory.csv", trajectory_now, trajectory_base);
  std::printf("%-28s %10.3f %10.3f\n", "total", simulate + camera_now + trajectory_now,
              simulate + camera_base + trajectory_base);
  // The baseline is only a yardstick if it writes the same files.
  const bool same = now_trajectory == base_trajectory && now_camera == base_camera;
  std::printf("files written now and by the baseline: %s\n", same ? "identical" : "DIFFERENT");
  return same ? 0 : 1;
}
