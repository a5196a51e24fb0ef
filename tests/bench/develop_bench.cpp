// develop_bench: the develop stage's time a frame, step by step (export/develop.h): reading the .hdr,
// exposure and vignetting, the depth cast from the scene's geometry, the depth of field's gather,
// chromatic aberration, glare, grain, tone curve, PNG. On frames of a frames folder written by
// `billiards-export --no-render` (its lens.txt), each rendered by POV-Ray once (kept beside its .pov,
// or in --hdr DIR, as frame_NNNNN.hdr) at the size and quality given.
//   develop_bench FRAMES_DIR FRAME...|all [--size WxH] [--quality draft|final] [--runs N] [--hdr DIR]
//                 [--out DIR [--depth]]
// --out DIR also writes each frame developed with its lens (frame_NNNNN.png) and without it, as before
// the lens (frame_NNNNN_plain.png); --depth its depth too, as grey, near light and far dark
// (frame_NNNNN_depth.png), and the depth's edges drawn in red over the picture (frame_NNNNN_edges.png).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "child_process.h"
#include "depth_of_field.h"
#include "develop.h"
#include "frame_lens.h"
#include "png_file.h"
#include "pov_frame.h"
#include "render_jobs.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

struct Options {
  std::string frames_dir;
  std::string hdr_dir;  ///< empty: frames_dir
  std::vector<int> frames;
  bool all = false;
  bool depth = false;
  int width = 1280, height = 720;
  Quality quality = Quality::final;
  int runs = 3;
  std::string out;
};

/// ms of CPU this thread has used.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

/// The least of `runs` timings of f(), in ms of CPU (the machine may be shared: its wall time says
/// little, and the least CPU time is the one least disturbed).
template <class F>
double median_ms(int runs, F&& f) {
  std::vector<double> ms;
  for (int k = 0; k < runs; ++k) {
    const double t0 = cpu_ms();
    f();
    ms.push_back(cpu_ms() - t0);
  }
  std::sort(ms.begin(), ms.end());
  return ms.front();
}

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--size" && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) != 2) return false;
    } else if (a == "--quality" && i + 1 < argc) {
      o.quality = std::string(argv[++i]) == "draft" ? Quality::draft : Quality::final;
    } else if (a == "--runs" && i + 1 < argc) {
      o.runs = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--out" && i + 1 < argc) {
      o.out = argv[++i];
    } else if (a == "--hdr" && i + 1 < argc) {
      o.hdr_dir = argv[++i];
    } else if (a == "--depth") {
      o.depth = true;
    } else if (a == "all") {
      o.all = true;
    } else if (o.frames_dir.empty()) {
      o.frames_dir = a;
    } else {
      o.frames.push_back(std::atoi(a.c_str()));
    }
  }
  if (o.hdr_dir.empty()) o.hdr_dir = o.frames_dir;
  return !o.frames_dir.empty() && (o.all || !o.frames.empty());
}

/// The frame's .hdr, rendered by POV-Ray unless it is there already.
bool hdr_of(const Options& o, int frame, std::string& path) {
  path = o.hdr_dir + "/" + frame_name(frame) + ".hdr";
  if (fs::exists(path)) return true;
  path = fs::absolute(path).string();
  RenderSettings settings{find_program("povray"), o.width, o.height, o.quality, 1, "", true};
  std::vector<std::string> args = povray_arguments(settings, frame);
  for (std::string& arg : args)
    if (arg.rfind("+O", 0) == 0) arg = "+O" + path;
  std::string error;
  const pid_t pid = start_process(args, o.frames_dir, o.frames_dir + "/.bench.log", error);
  bool success = false;
  if (pid < 0 || wait_any(success, std::chrono::hours(1)) != pid || !success) {
    std::fprintf(stderr, "develop_bench: cannot render %s: %s\n", path.c_str(), error.c_str());
    return false;
  }
  return true;
}

/// The picture with the depth's edges (a step of over 3 % between neighbours) drawn in red over it.
void write_edges(const DepthPicture& depth, std::vector<std::uint8_t> picture, const std::string& path) {
  const int w = depth.width;
  for (int y = 0; y + 1 < depth.height; ++y)
    for (int x = 0; x + 1 < w; ++x) {
      const float z = depth.depth[static_cast<std::size_t>(y) * w + x];
      const float right = depth.depth[static_cast<std::size_t>(y) * w + x + 1];
      const float down = depth.depth[static_cast<std::size_t>(y + 1) * w + x];
      if (std::abs(right - z) > 0.03f * z || std::abs(down - z) > 0.03f * z) {
        std::uint8_t* p = picture.data() + 3 * (static_cast<std::size_t>(y) * w + x);
        p[0] = 255, p[1] = 0, p[2] = 0;
      }
    }
  std::string error;
  if (!write_png(path, picture, w, depth.height, error)) std::fprintf(stderr, "%s\n", error.c_str());
}

void write_depth(const DepthPicture& depth, const std::string& path) {
  std::vector<std::uint8_t> grey(3 * depth.depth.size());
  for (std::size_t i = 0; i < depth.depth.size(); ++i) {
    const double v = 255.0 / (1.0 + depth.depth[i]);  // 1 m: half, 4 m: a fifth
    std::fill_n(grey.begin() + static_cast<std::ptrdiff_t>(3 * i), 3, static_cast<std::uint8_t>(std::min(255.0, v)));
  }
  std::string error;
  if (!write_png(path, grey, depth.width, depth.height, error)) std::fprintf(stderr, "%s\n", error.c_str());
}

/// Times one frame's development step by step and prints its line; with --out, writes its pictures.
bool bench_frame(const Options& o, const LensFile& file, const DepthScene& scene, int frame) {
  std::string hdr, error;
  FrameLens lens;
  const auto line = file.frames.find(frame);
  if (line == file.frames.end() || !parse_frame_lens(line->second, lens) || !hdr_of(o, frame, hdr)) return false;
  HdrImage image;
  const double read = median_ms(o.runs, [&] { read_hdr(hdr, image, error); });
  HdrImage work = image;
  const double expose_ms = median_ms(o.runs, [&] { work = image, expose(work, lens.lens.aperture); });
  const HdrImage exposed = work;
  const CameraView view(lens.pose, CameraView::HalfWidth{0.5 * kSensorWidthMm / lens.lens.focal_mm},
                        static_cast<double>(image.width) / image.height);
  DepthPicture depth;
  const double depth_ms = median_ms(
      o.runs, [&] { depth = nearest_of_neighbours(cast_depth(scene, lens.moving, view, image.width, image.height)); });
  const double gather_ms =
      median_ms(o.runs, [&] { work = exposed, gather_blur(work, depth, blur_radii(depth, lens.lens)); });
  const HdrImage blurred = work;
  const double aberration = median_ms(o.runs, [&] { work = blurred, chromatic_aberration(work); });
  const HdrImage aberrated = work;
  const double glare = median_ms(o.runs, [&] { work = aberrated, add_glare(work); });
  const HdrImage glared = work;
  const double grain = median_ms(o.runs, [&] { work = glared, add_grain(work, frame); });
  std::vector<std::uint8_t> picture;
  const double tone = median_ms(o.runs, [&] { picture = tone_map(work); });
  const std::string png = o.out.empty() ? o.hdr_dir + "/.bench.png" : o.out + "/" + frame_name(frame) + ".png";
  const double png_ms = median_ms(o.runs, [&] { write_png(png, picture, image.width, image.height, error); });
  // The copies between steps are left out of each step's time (a few ms each).
  const double total = read + expose_ms + depth_ms + gather_ms + aberration + glare + grain + tone + png_ms;
  const DevelopLens with{&lens, &scene};
  const double whole = median_ms(o.runs, [&] { picture = develop(image, with); });
  const double before = median_ms(o.runs, [&] { picture = develop(image); });
  std::printf("%5d  %9.3f  %4.1f  %5.0f  %6.0f  %5.0f  %6.0f  %6.0f  %5.0f  %5.0f  %4.0f  %5.0f  %6.0f  %7.0f  %7.0f\n",
              frame, lens.lens.focus, lens.lens.aperture, read, expose_ms, depth_ms, gather_ms, aberration, glare,
              grain, tone, png_ms, total, whole, before);
  if (o.out.empty()) return true;
  write_png(o.out + "/" + frame_name(frame) + "_plain.png", picture, image.width, image.height, error);
  if (!o.depth) return true;
  write_edges(depth, picture, o.out + "/" + frame_name(frame) + "_edges.png");
  write_depth(depth, o.out + "/" + frame_name(frame) + "_depth.png");
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr,
                 "usage: develop_bench FRAMES_DIR FRAME...|all [--size WxH] [--quality draft|final] "
                 "[--runs N] [--hdr DIR] [--out DIR [--depth]]\n");
    return 2;
  }
  const LensFile file = read_lens_file(o.frames_dir);
  DepthScene scene;
  std::string error;
  if (!parse_depth_scene(file.scene, scene, error)) {
    std::fprintf(stderr, "develop_bench: %s/%s: %s\n", o.frames_dir.c_str(), kLensName, error.c_str());
    return 1;
  }
  if (o.all)
    for (const auto& entry : file.frames) o.frames.push_back(entry.first);
  std::printf(
      "ms of CPU a frame (the least of %d runs); develop(): the whole stage but reading and writing, with the\n"
      "lens and without it (as before the lens)\n",
      o.runs);
  std::printf(
      "frame  focus (m)  f/N   read   expose  depth  gather  aberr.  glare  grain  tone   png    total  develop  "
      "without\n");
  for (int frame : o.frames)
    if (!bench_frame(o, file, scene, frame)) return 1;
  return 0;
}
