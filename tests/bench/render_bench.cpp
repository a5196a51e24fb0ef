// render_bench: where the time of a movie goes, for the built-in break at draft 1280x720.
//   cmake --build build --target render_bench && build/bin/render_bench [--every K] [--fps N]
// Reports the exporter's own work (loading, simulating, writing frames and sound, and its CPU
// while it waits) against the time inside POV-Ray and ffmpeg, and the speed-up of two POV-Ray
// processes over one, set against what two concurrent renders of one frame get on this machine
// (on a machine whose second core adds less than a whole core, that is the ceiling, not 2x).
// Other work on the machine while it runs skews every figure.
// --every K renders every K-th frame only (and skips the movie): a quicker estimate.
// Takes many minutes at K = 1; never run by ctest.
//
// --looks [--sheet FILE] does something else: the classic look against the photographic one, at
// final 1280x720 on one core, on a handful of instants of the default break (POV-Ray's CPU seconds a
// frame for each, side by side), the share of the break's frames drawn once and with motion-blur
// copies, and with --sheet a contact sheet of those instants (classic above, photographic below).
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "builtin_scene.h"
#include "child_process.h"
#include "export_options.h"
#include "ffmpeg_assemble.h"
#include "frame_cache.h"
#include "frames.h"
#include "movie_export.h"
#include "output_stage.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "render_jobs.h"
#include "shot.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// s of CPU this process itself has used (not its children).
double own_cpu() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

void remove_pictures(const std::string& frames_dir) {
  for (const auto& e : fs::directory_iterator(frames_dir))
    if (e.path().extension() == ".png") fs::remove(e.path());
}

struct RenderTiming {
  double wall = 0;     ///< s
  double own_cpu = 0;  ///< s of the exporter's CPU meanwhile
};

RenderTiming render(const std::string& frames_dir, const std::vector<bsim::FrameJob>& jobs,
                    const bsim::RenderSettings& settings) {
  remove_pictures(frames_dir);
  bsim::FrameCache cache("", frames_dir);  // no store: every frame is rendered
  std::string error;
  const double cpu = own_cpu();
  const auto start = Clock::now();
  if (bsim::render_frames(frames_dir, jobs, static_cast<int>(jobs.size()), settings, cache, error) !=
      bsim::RunOutcome::done) {
    std::fprintf(stderr, "render_bench: %s\n", error.c_str());
    std::exit(1);
  }
  return {seconds_since(start), own_cpu() - cpu};
}

/// s of CPU the finished child processes have used.
double children_cpu() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// The instants the looks are compared at: the still before the break, the break, the spread, the 8
/// dropping into its pocket, the wide closing shot (seconds of the default break).
constexpr double kLookInstants[] = {0.5, 2.64, 2.8, 5.35, 10.0};

/// Whether frame `frame` is drawn with motion blur: a ball's streak, a swept stick or its copies.
bool blurred_frame(const bsim::Shot& shot, int frame, int fps) {
  std::ostringstream out;
  bsim::write_pov_frame(shot, frame, fps, out);
  const std::string text = out.str();
  for (const char* blur : {"BallStreak(", "CueSweep(", "CueStickT("})
    if (text.find(blur) != std::string::npos) return true;
  return false;
}

/// One look's renders of the instants: CPU seconds for each.
struct LookRun {
  bsim::Look look;
  const char* name;
  std::vector<double> seconds;
};

/// Writes and renders `jobs` in each look of `runs` (in `dir`/the look's name), timing each frame.
bool render_looks(const bsim::Shot& shot, const std::string& povray, const fs::path& dir,
                  const std::vector<bsim::FrameJob>& jobs, int frames, LookRun (&runs)[2]) {
  const int fps = 30, width = 1280, height = 720;
  for (LookRun& run : runs) {
    const fs::path frames_dir = dir / run.name;
    fs::create_directories(frames_dir);
    {
      std::ofstream include(frames_dir / std::string(bsim::kPovIncludeName));
      bsim::write_pov_include(shot.scene, bsim::Quality::final, include, run.look);
    }
    for (const bsim::FrameJob& job : jobs) {
      std::ofstream out(frames_dir / (bsim::frame_name(job.frame) + ".pov"));
      bsim::write_pov_frame(shot, job.frame, fps, out, run.look);
    }
    const bsim::RenderSettings settings{povray, width, height, bsim::Quality::final, 1, "", true};
    for (const bsim::FrameJob& job : jobs) {
      bsim::FrameCache cache("", frames_dir.string());
      std::string error;
      const double before = children_cpu();
      if (bsim::render_frames(frames_dir.string(), {job}, frames, settings, cache, error) != bsim::RunOutcome::done) {
        std::fprintf(stderr, "render_bench: %s\n", error.c_str());
        return false;
      }
      run.seconds.push_back(children_cpu() - before);
    }
  }
  return true;
}

/// The contact sheet: one row a look, the instants left to right, each a quarter of its size.
bool write_sheet(const std::string& ffmpeg, const fs::path& dir, const std::vector<bsim::FrameJob>& jobs,
                 const LookRun (&runs)[2], const std::string& sheet) {
  std::vector<std::string> args = {ffmpeg, "-loglevel", "error", "-y"};
  for (const LookRun& run : runs)
    for (const bsim::FrameJob& job : jobs)
      args.insert(args.end(), {"-i", (dir / run.name / (bsim::frame_name(job.frame) + ".png")).string()});
  std::string filter, layout;
  const std::size_t count = 2 * jobs.size();
  for (std::size_t i = 0; i < count; ++i) {
    filter += "[" + std::to_string(i) + "]scale=480:270[s" + std::to_string(i) + "];";
    const std::size_t col = i % jobs.size(), row = i / jobs.size();
    layout += (i ? "|" : "") + std::to_string(col * 480) + "_" + std::to_string(row * 270);
  }
  for (std::size_t i = 0; i < count; ++i) filter += "[s" + std::to_string(i) + "]";
  filter += "xstack=inputs=" + std::to_string(count) + ":layout=" + layout;
  // ffmpeg runs in the scratch directory: the sheet's name as given is relative to ours.
  args.insert(args.end(), {"-filter_complex", filter, "-frames:v", "1", "-q:v", "3", fs::absolute(sheet).string()});
  std::string error;
  const pid_t pid = bsim::start_process(args, dir.string(), (dir / "ffmpeg.log").string(), error);
  if (pid < 0 || !bsim::wait_for(pid)) {
    std::fprintf(stderr, "render_bench: ffmpeg could not write %s\n", sheet.c_str());
    return false;
  }
  std::printf("wrote %s\n", sheet.c_str());
  return true;
}

int compare_looks(const bsim::Shot& shot, const std::string& povray, const std::string& ffmpeg,
                  const std::string& sheet) {
  const int fps = 30, width = 1280, height = 720;
  const int frames = bsim::frame_count(shot.timeline.duration(), fps);
  std::vector<bsim::FrameJob> jobs;
  for (double t : kLookInstants) jobs.push_back({static_cast<int>(std::lround(t * fps)), 0});
  int blurred = 0;
  for (int k = 0; k < frames; ++k) blurred += blurred_frame(shot, k, fps);
  std::printf(
      "default break, final %dx%d, one POV-Ray process; %d frames: %d drawn once (%.0f%%), %d with motion blur "
      "(%.0f%%)\n",
      width, height, frames, frames - blurred, 100.0 * (frames - blurred) / frames, blurred, 100.0 * blurred / frames);
  const fs::path dir = fs::temp_directory_path() / ("render-bench-looks-" + std::to_string(::getpid()));
  LookRun runs[] = {{bsim::Look::classic, "classic", {}}, {bsim::Look::photo, "photographic", {}}};
  if (!render_looks(shot, povray, dir, jobs, frames, runs)) return 1;
  std::printf("%-8s %-7s %-10s %14s %14s\n", "frame", "t (s)", "blur", "classic (s)", "photographic (s)");
  double sum[2] = {0, 0};
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    std::printf("%-8d %-7.2f %-10s %14.2f %14.2f\n", jobs[i].frame, jobs[i].frame / double(fps),
                blurred_frame(shot, jobs[i].frame, fps) ? "blurred" : "none", runs[0].seconds[i], runs[1].seconds[i]);
    sum[0] += runs[0].seconds[i];
    sum[1] += runs[1].seconds[i];
  }
  const double n = static_cast<double>(jobs.size());
  std::printf("mean s a frame on one core: classic %.2f, photographic %.2f (%.0f%% of classic)\n", sum[0] / n,
              sum[1] / n, 100 * sum[1] / sum[0]);
  if (!sheet.empty() && !write_sheet(ffmpeg, dir, jobs, runs, sheet)) return 1;
  fs::remove_all(dir);
  return 0;
}

/// What the command line asks for.
struct BenchArgs {
  int every = 1;
  bsim::ExportOptions options;
  bool looks = false;
  std::string sheet;
};

BenchArgs read_args(int argc, char** argv) {
  BenchArgs a;
  a.options.quality = bsim::Quality::draft;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--looks")
      a.looks = true;
    else if (flag == "--sheet" && i + 1 < argc)
      a.sheet = argv[++i];
    else if (flag == "--every" && i + 1 < argc)
      a.every = std::max(1, std::atoi(argv[++i]));
    else if (flag == "--fps" && i + 1 < argc)
      a.options.fps = std::max(1, std::atoi(argv[++i]));
  }
  return a;
}

/// What this machine gives two processes: three frames one after another, then six neighbouring
/// frames (so as much work apiece) two at a time. The speed-up of the pair.
double machine_speedup(const std::string& frames_dir, int frames, bsim::RenderSettings settings) {
  std::vector<bsim::FrameJob> three, six;
  for (int k = 0; k < 6; ++k) {
    if (k % 2 == 0) three.push_back({frames / 2 + k, 0});
    six.push_back({frames / 2 + k, 0});
  }
  settings.processes = 1;
  const RenderTiming alone = render(frames_dir, three, settings);
  settings.processes = 2;
  const RenderTiming pair = render(frames_dir, six, settings);
  return 2 * alone.wall / pair.wall;
}

}  // namespace

int main(int argc, char** argv) {
  const BenchArgs args = read_args(argc, argv);
  const int every = args.every;
  const bsim::ExportOptions& options = args.options;
  const std::string povray = bsim::find_program("povray"), ffmpeg = bsim::find_program("ffmpeg");
  if (povray.empty() || ffmpeg.empty()) {
    std::fprintf(stderr, "render_bench: povray and ffmpeg are needed; run `bash .ci/install-deps`\n");
    return 1;
  }

  // The exporter's own work: scene -> shot -> frame files and sound track.
  auto start = Clock::now();
  bsim::ShotResult loaded = bsim::load_shot(bsim::builtin_scene_text(), bsim::kBuiltinSceneName);
  if (!loaded.shot) return 1;
  if (args.looks) return compare_looks(*loaded.shot, povray, ffmpeg, args.sheet);
  const double load_time = seconds_since(start);
  const fs::path dir = fs::temp_directory_path() / ("render-bench-" + std::to_string(::getpid()));
  bsim::OutputStage stage;
  std::string error;
  start = Clock::now();
  bsim::RunSummary written;
  if (!stage.open(dir.string(), error) || !bsim::write_frames_and_sound(*loaded.shot, options, stage, written, error) ||
      !stage.commit(error)) {
    std::fprintf(stderr, "render_bench: %s\n", error.c_str());
    return 1;
  }
  const double write_time = seconds_since(start);

  const int frames = bsim::frame_count(loaded.shot->timeline.duration(), options.fps);
  std::vector<bsim::FrameJob> jobs;
  for (int k = 0; k < frames; k += every) jobs.push_back({k, 0});
  const std::string frames_dir = (dir / "frames").string();
  std::printf("default break, draft %dx%d, %d frames at %d fps; rendering %zu of them\n", options.width, options.height,
              frames, options.fps, jobs.size());
  std::fflush(stdout);

  bsim::RenderSettings settings{povray, options.width, options.height, options.quality, 1, ""};
  const double machine = machine_speedup(frames_dir, frames, settings);
  settings.processes = 1;
  const RenderTiming one = render(frames_dir, jobs, settings);
  std::printf("POV-Ray, --jobs 1: %.1f s (%.2f s a frame)\n", one.wall, one.wall / static_cast<double>(jobs.size()));
  std::fflush(stdout);
  settings.processes = 2;
  const RenderTiming two = render(frames_dir, jobs, settings);
  std::printf("POV-Ray, --jobs 2: %.1f s (%.2f s a frame)\n", two.wall, two.wall / static_cast<double>(jobs.size()));

  double encode_time = 0;
  if (every == 1) {
    start = Clock::now();
    if (bsim::assemble_movie(dir.string(), {ffmpeg, options.fps, loaded.shot->timeline.duration()}, error) !=
        bsim::RunOutcome::done) {
      std::fprintf(stderr, "render_bench: %s\n", error.c_str());
      return 1;
    }
    encode_time = seconds_since(start);
    std::printf("ffmpeg: %.1f s\n", encode_time);
  }

  const double outside = load_time + write_time + two.own_cpu;
  const double inside = two.wall - two.own_cpu + encode_time;
  std::printf("exporter's own work: load and simulate %.2f s, frames and sound %.2f s, %.2f s CPU while rendering\n",
              load_time, write_time, two.own_cpu);
  std::printf("outside POV-Ray and ffmpeg: %.2f s; inside: %.1f s; own share %.2f%% (at --jobs 2%s)\n", outside, inside,
              100 * outside / (outside + inside), every == 1 ? "" : ", frames sampled");
  const double speedup = one.wall / two.wall;
  std::printf(
      "speed-up of --jobs 2 over --jobs 1: %.2fx; two concurrent renders of one frame: %.2fx; "
      "parallel efficiency %.0f%%\n",
      speedup, machine, 100 * speedup / machine);
  fs::remove_all(dir);
  return 0;
}
