// export_bench: where `billiards-export --events-only` spends its time on the built-in break, part by
// part, beside a baseline run in the same process: the exporter as it was, every state integrated
// from its segment's start (test::DirectStates), the ball tracks' second pass over their samples, and
// every trajectory.csv row formatted anew. Both build the camera script from the same timeline.
//   export_bench [--fps N] [--runs N]
// With --frames, the frames folder of a run that renders, before the frames are traced (the built-in
// break, or SCENE): writing frames/ and the sound track, the frame store's keys and the partial
// renders' plan, now (each frame's content computed once, the keys and the plan from memory) beside
// the exporter as it was (the .pov writer and lens.txt each computing every frame, the keys read back
// from the files, the plan computing each frame to trace again). It checks that both write the same
// files, make the same keys and the same plan.
//   export_bench --frames [SCENE.scn] [--fps N] [--runs N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "builtin_scene.h"
#include "depth_scene.h"
#include "direct_states.h"
#include "frame_captions.h"
#include "frame_lens.h"
#include "frames.h"
#include "loudness.h"
#include "movie_export.h"
#include "number_format.h"
#include "output_stage.h"
#include "outputs.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "run_summary.h"
#include "scene_file.h"
#include "shot.h"
#include "soundtrack.h"

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

namespace fs = std::filesystem;

void put_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// write_frames_and_sound as it was: the include, each .pov from its frame_content, captions.txt,
/// lens.txt from every frame_content again, the sound track.
void write_frames_before(const bsim::Shot& shot, const bsim::ExportOptions& options, const std::string& dir) {
  fs::create_directories(dir + "/frames");
  {
    std::ofstream include(dir + "/frames/" + std::string(bsim::kPovIncludeName), std::ios::binary);
    bsim::write_pov_include(shot.scene, options.quality, include);
  }
  const int frames = shot.movie.frame_count(options.fps);
  for (int k = 0; k < frames; ++k) {
    std::ofstream out(dir + "/frames/" + bsim::frame_name(k) + ".pov", std::ios::binary);
    bsim::write_pov_frame(shot, k, options.fps, out);
  }
  if (shot.game)
    put_file(dir + "/frames/" + bsim::kCaptionsName,
             bsim::captions_text(bsim::frame_captions(shot, bsim::movie_frame_moments(shot, options.fps), options.width,
                                                      options.height)));
  put_file(dir + "/frames/" + bsim::kLensName,
           bsim::lens_text(bsim::depth_scene(shot.scene), bsim::frame_lenses(shot, options.fps)));
  const auto samples = static_cast<std::size_t>(std::llround(shot.movie.duration() * bsim::kSampleRate));
  bsim::AudioBuffer audio;
  const bsim::SoundOptions sound{.lead = options.audio_lead, .music_path = options.music_path, .level = options.level};
  const bsim::SoundMovie movie{&shot.movie, shot.replay_camera ? &*shot.replay_camera : nullptr};
  std::string error;
  bsim::mix_movie_soundtrack({shot.scene, shot.timeline, *shot.camera}, movie, sound, samples, audio, error);
  volatile double sink = bsim::integrated_loudness(audio).value_or(0) + bsim::true_peak(audio);
  (void)sink;
  bsim::write_wav(dir + "/soundtrack.wav", audio, error);
}

/// The first of each set of frames alike, as a run with an empty store renders them.
std::vector<bsim::FrameJob> jobs_to_render(const std::vector<std::uint64_t>& keys) {
  std::vector<bsim::FrameJob> jobs;
  std::set<std::uint64_t> seen;
  for (std::size_t k = 0; k < keys.size(); ++k)
    if (seen.insert(keys[k]).second) jobs.push_back({static_cast<int>(k), keys[k]});
  return jobs;
}

/// Whether every file of `a` is in `b` with the same bytes, and the other way round.
bool same_files(const std::string& a, const std::string& b) {
  std::set<std::string> names;
  for (const std::string& dir : {a, b})
    for (const auto& e : fs::recursive_directory_iterator(dir))
      if (e.is_regular_file()) names.insert(fs::relative(e.path(), dir).string());
  for (const std::string& name : names)
    if (!fs::exists(a + "/" + name) || !fs::exists(b + "/" + name) ||
        bsim::read_text_file(a + "/" + name) != bsim::read_text_file(b + "/" + name))
      return false;
  return true;
}

struct FramesTimes {
  double write = 0, keys = 0, plan = 0;
  std::vector<std::uint64_t> keys_made;
  std::vector<bsim::FrameJob> jobs;
};

template <class F>
double seconds_of(F&& f) {
  const auto t0 = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

FramesTimes frames_now(const bsim::Shot& shot, const bsim::ExportOptions& options, const std::string& dir) {
  FramesTimes t;
  bsim::StagedFrames staged;
  bsim::OutputStage stage;
  std::string error;
  bsim::RunSummary summary;
  t.write = seconds_of([&] {
    if (!stage.open(dir, error) || !bsim::write_frames_and_sound(shot, options, stage, staged, summary, error) ||
        !stage.commit(error))
      std::fprintf(stderr, "export_bench: %s\n", error.c_str());
  });
  t.keys = seconds_of([&] { t.keys_made = bsim::frame_store_keys(staged, options); });
  t.jobs = jobs_to_render(t.keys_made);
  t.plan = seconds_of([&] { bsim::plan_partial_frames(shot.scene, staged, options, t.jobs); });
  return t;
}

FramesTimes frames_before(const bsim::Shot& shot, const bsim::ExportOptions& options, const std::string& dir) {
  FramesTimes t;
  const int frames = shot.movie.frame_count(options.fps);
  t.write = seconds_of([&] { write_frames_before(shot, options, dir); });
  t.keys = seconds_of([&] { t.keys_made = bsim::frame_store_keys(dir + "/frames", frames, options); });
  t.jobs = jobs_to_render(t.keys_made);
  t.plan = seconds_of([&] { bsim::plan_partial_frames(shot, options, t.jobs); });
  return t;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// --frames: the frames folder now and as it was, interleaved run by run.
int frames_bench(const std::string& scene_path, int fps, int runs) {
  const std::string name =
      scene_path.empty() ? std::string(bsim::kBuiltinSceneName) : fs::path(scene_path).stem().string();
  const bsim::ShotResult loaded = bsim::load_shot(
      scene_path.empty() ? std::string(bsim::builtin_scene_text()) : bsim::read_text_file(scene_path), name);
  if (!loaded.scripted()) {
    std::fprintf(stderr, "export_bench: %s does not load\n", name.c_str());
    return 1;
  }
  const bsim::Shot& shot = *loaded.scripted();
  bsim::ExportOptions options;  // 1280x720 final, as the default run
  options.fps = fps;
  options.no_render = true;  // no fonts needed to write captions.txt
  const fs::path root = fs::temp_directory_path() / ("export-bench-" + std::to_string(::getpid()));
  std::map<std::string, std::vector<double>> now, before;
  bool same = true;
  for (int r = 0; r < runs; ++r) {
    fs::remove_all(root);
    const FramesTimes a = frames_now(shot, options, (root / "now").string());
    const FramesTimes b = frames_before(shot, options, (root / "before").string());
    for (auto [times, t] : {std::pair{&now, &a}, std::pair{&before, &b}}) {
      (*times)["write"].push_back(t->write);
      (*times)["keys"].push_back(t->keys);
      (*times)["plan"].push_back(t->plan);
      (*times)["total"].push_back(t->write + t->keys + t->plan);
    }
    same = same && a.keys_made == b.keys_made && a.jobs.size() == b.jobs.size() &&
           std::equal(a.jobs.begin(), a.jobs.end(), b.jobs.begin(), [](const auto& x, const auto& y) {
             return x.frame == y.frame && x.reference == y.reference && x.rects == y.rects;
           });
    fs::remove((root / "now/run.json"));
    same = same && same_files((root / "now").string(), (root / "before").string());
  }
  fs::remove_all(root);
  std::printf("frames/ of %s (%d frames at %d fps, 1280x720 final): median s of %d runs\n", name.c_str(),
              shot.movie.frame_count(fps), fps, runs);
  std::printf("%-40s %10s %10s\n", "part", "now", "before");
  const std::pair<const char*, const char*> rows[] = {{"write", "frames/*.pov, captions, lens.txt, sound"},
                                                      {"keys", "the frame store's keys"},
                                                      {"plan", "partial renders planned"},
                                                      {"total", "total"}};
  for (const auto& [key, label] : rows)
    std::printf("%-40s %10.3f %10.3f\n", label, median(now[key]), median(before[key]));
  std::printf("files, keys and plan now and before: %s\n", same ? "identical" : "DIFFERENT");
  return same ? 0 : 1;
}

struct Args {
  int fps = 30, runs = 50;
  bool frames = false;
  std::string scene_path;
};

/// The command line; false (after saying why) when it is not one.
bool parse_args(int argc, char** argv, Args& a) {
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--frames") {
      a.frames = true;
      if (k + 1 < argc && argv[k + 1][0] != '-') a.scene_path = argv[++k];
    } else if ((arg == "--fps" || arg == "--runs") && k + 1 < argc) {
      const long value = std::strtol(argv[++k], nullptr, 10);
      if (value <= 0 || value > 1000) {
        std::fprintf(stderr, "export_bench: %s needs a count from 1 to 1000\n", arg.c_str());
        return false;
      }
      (arg == "--fps" ? a.fps : a.runs) = static_cast<int>(value);
    } else {
      std::fprintf(stderr, "usage: export_bench [--frames [SCENE.scn]] [--fps N] [--runs N]\n");
      return false;
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  if (!parse_args(argc, argv, args)) return 2;
  const int fps = args.fps, runs = args.runs;
  if (args.frames) return frames_bench(args.scene_path, fps, runs);

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
