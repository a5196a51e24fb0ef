// render_bench: where the time of a movie goes, for the built-in break at draft 1280x720.
//   cmake --build build --target render_bench && build/bin/render_bench [--every K] [--fps N]
// Reports the exporter's own work (loading, simulating, writing frames and sound, and its CPU
// while it waits) against the time inside POV-Ray and ffmpeg, and the speed-up of two POV-Ray
// processes over one, set against what two concurrent renders of one frame get on this machine
// (on a machine whose second core adds less than a whole core, that is the ceiling, not 2x).
// Other work on the machine while it runs skews every figure.
// --every K renders every K-th frame only (and skips the movie): a quicker estimate.
// Takes many minutes at K = 1; never run by ctest.
// --reuse [--size WxH] does something else: the default movie at final quality (640x360 unless
// --size says otherwise), every frame rendered with --jobs 2 twice, side by side: tracing every pixel
// (--whole-frames) and tracing only what changed (changed_region.h). It prints POV-Ray's CPU seconds
// (the children's user and system time) and the wall time of each, the share of the pixels traced,
// and checks that the two made the same pictures. --plan prints only the plan's line (the frames
// traced in part, the share of the pixels traced and the POV-Ray runs) and renders nothing.
// --alone [--every K]: each frame (or every K-th, a quicker estimate) traced whole and, when it is
// traced in part, each of its rectangles, one POV-Ray at a time, so the two ways see the same load on
// a shared machine; each rectangle is checked against the whole frame's pixels (linear light).
// --scene FILE: any of the above on that scene instead of the built-in break (e.g. --reuse --scene
// scenes/runout.scn --fps 5: a run of shots, a minute of movie).
#include <sys/resource.h>
#include <unistd.h>

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
#include <vector>

#include "builtin_scene.h"
#include "child_process.h"
#include "develop.h"
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

/// The exporter's own share of the run's time, and what --jobs 2 gains against what the machine gives.
void print_shares(double load_time, double write_time, double encode_time, const RenderTiming& one,
                  const RenderTiming& two, double machine, int every) {
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

/// s of CPU the child processes that have ended have used (POV-Ray's).
double children_cpu() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// The pictures of the frames in `frames_dir`, by name.
std::map<std::string, std::string> pictures(const std::string& frames_dir) {
  std::map<std::string, std::string> read;
  for (const auto& e : fs::directory_iterator(frames_dir)) {
    if (e.path().extension() != ".png") continue;
    std::ifstream in(e.path(), std::ios::binary);
    read[e.path().filename().string()] = std::string(std::istreambuf_iterator<char>(in), {});
  }
  return read;
}

/// s of POV-Ray's CPU for one run of it on `job` (`part` -1: the whole frame, else that rectangle),
/// alone; its linear picture in `picture`.
double trace_alone(const std::string& frames_dir, const bsim::RenderSettings& settings, const bsim::FrameJob& job,
                   int part, bsim::HdrImage& picture) {
  std::string error;
  const std::vector<std::string> args = bsim::povray_arguments(settings, job, part);
  const double cpu = children_cpu();
  const pid_t pid = bsim::start_process(args, frames_dir, frames_dir + "/.sample.log", error);
  const std::string hdr = frames_dir + "/" + args[5].substr(2);  // +O...
  if (pid < 0 || !bsim::wait_for(pid) || !bsim::read_hdr(hdr, picture, error)) {
    std::fprintf(stderr, "render_bench: frame %d, part %d: POV-Ray failed %s\n", job.frame, part, error.c_str());
    std::exit(1);
  }
  fs::remove(hdr);
  return children_cpu() - cpu;
}

/// --alone [--every K]: every K-th frame POV-Ray renders, traced whole and, when it is traced in part,
/// each of its rectangles, one POV-Ray at a time: the CPU of each way for those frames, and each
/// rectangle's pixels against the whole frame's (linear light, before developing).
int sampled_reuse(const std::vector<bsim::FrameJob>& reusing, int every, const std::string& frames_dir,
                  const bsim::RenderSettings& settings) {
  double whole_cpu = 0, reuse_cpu = 0, partial_whole_cpu = 0, partial_cpu = 0;
  int sampled = 0, partial = 0, runs = 0;
  long differ = 0;
  for (std::size_t k = 0; k < reusing.size(); k += static_cast<std::size_t>(every)) {
    const bsim::FrameJob& job = reusing[k];
    bsim::HdrImage whole, part_picture;
    const double cpu = trace_alone(frames_dir, settings, {job.frame, job.key, -1, {}}, -1, whole);
    ++sampled;
    whole_cpu += cpu;
    if (job.reference < 0) {
      reuse_cpu += cpu;
      ++runs;
      continue;
    }
    ++partial;
    partial_whole_cpu += cpu;
    for (std::size_t part = 0; part < job.rects.size(); ++part, ++runs) {
      const double part_cpu = trace_alone(frames_dir, settings, job, static_cast<int>(part), part_picture);
      reuse_cpu += part_cpu, partial_cpu += part_cpu;
      const bsim::PixelRect& r = job.rects[part];
      std::fprintf(stderr, "frame %d rectangle %zu: %ld pixels, %.3f s (whole %.3f s)\n", job.frame, part, r.area(),
                   part_cpu, cpu);
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x)
          for (int c = 0; c < 3; ++c) {
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(whole.width) +
                                       static_cast<std::size_t>(x)) +
                                  static_cast<std::size_t>(c);
            differ += whole.rgb[i] != part_picture.rgb[i];
          }
    }
  }
  std::printf("%d frames (every %d), %d of them traced in part, in %d POV-Ray runs in all, one POV-Ray at a time:\n",
              sampled, every, partial, runs);
  std::printf(
      "  POV-Ray CPU: whole %.1f s, reusing %.1f s: %.0f%%; the partial frames alone %.1f s against %.1f s: %.0f%%\n",
      whole_cpu, reuse_cpu, 100 * reuse_cpu / whole_cpu, partial_cpu, partial_whole_cpu,
      100 * partial_cpu / partial_whole_cpu);
  std::printf("  %ld values of the rectangles differ from the whole frames'\n", differ);
  return differ == 0 ? 0 : 1;
}

/// --reuse: the movie's frames rendered whole and reusing what did not change, side by side.
int reuse_bench(const bsim::Shot& shot, const bsim::ExportOptions& options, const std::string& frames_dir,
                const std::string& povray, const std::string& name, bool plan_only, int alone_every) {
  const int frames = bsim::frame_count(shot.timeline.duration(), options.fps);
  // Frames alike are rendered once, as in a run.
  const std::vector<std::uint64_t> keys = bsim::frame_store_keys(frames_dir, frames, options);
  std::vector<bsim::FrameJob> whole;
  std::set<std::uint64_t> seen;
  for (int k = 0; k < frames; ++k)
    if (seen.insert(keys[static_cast<std::size_t>(k)]).second) whole.push_back({k, keys[static_cast<std::size_t>(k)]});
  std::vector<bsim::FrameJob> reusing = whole;
  bsim::plan_partial_frames(shot, options, reusing);
  long traced = 0, pixels = static_cast<long>(options.width) * options.height;
  int partial = 0;
  std::size_t runs = 0;
  for (const bsim::FrameJob& job : reusing) {
    partial += job.reference >= 0;
    if (job.reference < 0) traced += pixels;
    for (const bsim::PixelRect& r : job.rects) traced += r.area();
    runs += job.reference < 0 ? 1 : job.rects.size();
    if (plan_only) {
      std::fprintf(stderr, "frame %d", job.frame);
      if (job.reference < 0) std::fprintf(stderr, " whole");
      for (const bsim::PixelRect& r : job.rects) std::fprintf(stderr, " %d,%d,%d,%d", r.x0, r.y0, r.x1, r.y1);
      std::fprintf(stderr, "\n");
    }
  }
  std::printf(
      "%s, final %dx%d at %d fps, %d frames, %zu rendered (the rest alike); reusing: %d traced in part, "
      "%.1f%% of the rendered frames' pixels traced, %zu POV-Ray runs\n",
      name.c_str(), options.width, options.height, options.fps, frames, whole.size(), partial,
      100.0 * static_cast<double>(traced) / static_cast<double>(pixels * static_cast<long>(whole.size())), runs);
  std::fflush(stdout);
  if (plan_only) return 0;
  bsim::RenderSettings settings{povray, options.width, options.height, options.quality, 2, ""};
  settings.quiet = true;
  if (alone_every > 0) return sampled_reuse(reusing, alone_every, frames_dir, settings);
  double cpu = children_cpu();
  const RenderTiming all = render(frames_dir, whole, settings);
  const double all_cpu = children_cpu() - cpu;
  const std::map<std::string, std::string> all_pictures = pictures(frames_dir);
  cpu = children_cpu();
  const RenderTiming changed = render(frames_dir, reusing, settings);
  const double changed_cpu = children_cpu() - cpu;
  const std::map<std::string, std::string> changed_pictures = pictures(frames_dir);
  int differ = 0;
  for (const auto& [picture, bytes] : all_pictures)
    differ += changed_pictures.count(picture) == 0 || changed_pictures.at(picture) != bytes;
  std::printf("%-16s %12s %10s\n", "", "POV-Ray CPU", "wall");
  std::printf("%-16s %10.1f s %8.1f s\n", "--whole-frames", all_cpu, all.wall);
  std::printf("%-16s %10.1f s %8.1f s\n", "reusing", changed_cpu, changed.wall);
  std::printf("reusing takes %.0f%% of the CPU of --whole-frames; %d of %zu pictures differ\n",
              100 * changed_cpu / all_cpu, differ, all_pictures.size());
  return differ == 0 ? 0 : 1;
}

/// The command line: --every K, --fps N, --reuse, --plan, --alone, --size WxH, --scene FILE.
bsim::ExportOptions parse_bench_options(int argc, char** argv, int& every, bool& reuse, bool& plan, bool& alone,
                                        std::string& scene) {
  bsim::ExportOptions options;
  options.quality = bsim::Quality::draft;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--reuse" || flag == "--plan" || flag == "--alone") {
      reuse = true;
      plan = plan || flag == "--plan";
      alone = alone || flag == "--alone";
      options.quality = bsim::Quality::final;
      if (options.width == 1280) options.width = 640, options.height = 360;
    } else if (flag == "--size" && i + 1 < argc &&
               std::sscanf(argv[i + 1], "%dx%d", &options.width, &options.height) == 2)
      ++i;
    else if (flag == "--every" && i + 1 < argc)
      every = std::max(1, std::atoi(argv[++i]));
    else if (flag == "--scene" && i + 1 < argc)
      scene = argv[++i];
    else if (flag == "--fps" && i + 1 < argc)
      options.fps = std::max(1, std::atoi(argv[++i]));
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  int every = 1;
  bool reuse = false, plan = false, alone = false;
  std::string scene_file;
  const bsim::ExportOptions options = parse_bench_options(argc, argv, every, reuse, plan, alone, scene_file);
  std::string text(bsim::builtin_scene_text()), name = "default break";
  if (!scene_file.empty()) {
    std::ifstream in(scene_file);
    std::stringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    name = fs::path(scene_file).stem().string();
  }
  const std::string povray = bsim::find_program("povray"), ffmpeg = bsim::find_program("ffmpeg");
  if (povray.empty() || ffmpeg.empty()) {
    std::fprintf(stderr, "render_bench: povray and ffmpeg are needed; run `bash .ci/install-deps`\n");
    return 1;
  }

  // The exporter's own work: scene -> shot -> frame files and sound track.
  auto start = Clock::now();
  bsim::ShotResult loaded = bsim::load_shot(text, scene_file.empty() ? bsim::kBuiltinSceneName : name);
  if (!loaded.scripted()) {
    for (const auto& d : loaded.diagnostics) std::fprintf(stderr, "%s\n", bsim::format_diagnostic(d, name).c_str());
    return 1;
  }
  const double load_time = seconds_since(start);
  const fs::path dir = fs::temp_directory_path() / ("render-bench-" + std::to_string(::getpid()));
  bsim::OutputStage stage;
  std::string error;
  start = Clock::now();
  bsim::RunSummary written;
  bsim::StagedFrames staged;
  if (!stage.open(dir.string(), error) ||
      !bsim::write_frames_and_sound(*loaded.shot, options, stage, staged, written, error) || !stage.commit(error)) {
    std::fprintf(stderr, "render_bench: %s\n", error.c_str());
    return 1;
  }
  const double write_time = seconds_since(start);

  if (reuse) {
    const int status =
        reuse_bench(*loaded.shot, options, (dir / "frames").string(), povray, name, plan, alone ? every : 0);
    fs::remove_all(dir);
    return status;
  }
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

  print_shares(load_time, write_time, encode_time, one, two, machine, every);
  fs::remove_all(dir);
  return 0;
}
