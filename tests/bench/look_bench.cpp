// look_bench: how bright the room comes out against the lit cloth in rendered frames, and a frame's
// .hdr developed into the movie's PNG, for looking at the look by hand.
//   cmake --build build --target look_bench
//   build/bin/look_bench stops [--scene FILE] FRAME.pov FRAME.hdr [FRAME.pov FRAME.hdr ...]
//     the median linear luma of the lit cloth, the walls and the floor in each rendered frame (which
//     pixel shows which is cast from the camera in the frame's .pov through the table description of
//     the scene, default the built-in break: look_regions.h), and how many stops (EV) the walls and
//     the floor lie under the cloth
//   build/bin/look_bench develop FILE.hdr FILE.png
//     the develop stage's PNG of one .hdr (export/develop.h)
//   build/bin/look_bench luma FILE.hdr X Y [HALF]
//     the mean linear luma of the square of pixels HALF (default 4) either side of pixel (X, Y)
//   build/bin/look_bench differ A.hdr B.hdr FILE.png
//     where two renders of one frame differ (e.g. with and without antialiasing: the pixels POV-Ray
//     supersampled), red over A developed and darkened; prints how many pixels differ
// tests/bench/look_cost.sh runs `stops` on the frames it renders.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "builtin_scene.h"
#include "develop.h"
#include "look_regions.h"
#include "shot.h"

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: look_bench stops [--scene FILE] FRAME.pov FRAME.hdr [FRAME.pov FRAME.hdr ...]\n"
               "       look_bench develop FILE.hdr FILE.png\n"
               "       look_bench luma FILE.hdr X Y [HALF]\n"
               "       look_bench differ A.hdr B.hdr FILE.png\n");
  return 2;
}

/// The camera a frame's .pov file gives POV-Ray: its `location` and `look_at` lines.
bool read_camera(const std::string& path, bsim::CameraPose& pose) {
  std::ifstream in(path);
  std::string line;
  int found = 0;
  while (std::getline(in, line)) {
    double x = 0, y = 0, z = 0;
    if (std::sscanf(line.c_str(), " location <%lf, %lf, %lf>", &x, &y, &z) == 3)
      pose.location = bsim::Vec3(x, y, z), ++found;
    if (std::sscanf(line.c_str(), " look_at <%lf, %lf, %lf>", &x, &y, &z) == 3)
      pose.look_at = bsim::Vec3(x, y, z), ++found;
  }
  return found == 2;
}

double stops(double cloth, double other) { return other > 0 && cloth > 0 ? std::log2(cloth / other) : NAN; }

int print_stops(int argc, char** argv) {
  std::string text(bsim::builtin_scene_text()), name(bsim::kBuiltinSceneName);
  int i = 2;
  if (i + 1 < argc && std::string(argv[i]) == "--scene") {
    std::ifstream in(argv[i + 1]);
    std::stringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    name = argv[i + 1];
    i += 2;
  }
  if (i >= argc || (argc - i) % 2 != 0) return usage();
  bsim::ShotResult loaded = bsim::load_shot(text, name);
  if (!loaded.scripted()) {
    std::fprintf(stderr, "look_bench: the scene does not load\n");
    return 1;
  }
  std::printf("%-12s %10s %10s %10s %12s %12s\n", "frame", "cloth", "wall", "floor", "wall (EV)", "floor (EV)");
  for (; i + 1 < argc; i += 2) {
    bsim::CameraPose pose;
    if (!read_camera(argv[i], pose)) {
      std::fprintf(stderr, "look_bench: %s has no camera location and look_at\n", argv[i]);
      return 1;
    }
    bsim::HdrImage picture;
    std::string error;
    if (!bsim::read_hdr(argv[i + 1], picture, error)) {
      std::fprintf(stderr, "look_bench: %s\n", error.c_str());
      return 1;
    }
    const bsim::test::LookLuma l =
        bsim::test::look_luma(loaded.shot->scene, pose, picture.width, picture.height, picture.rgb);
    const std::string frame = std::filesystem::path(argv[i]).stem().string();
    std::printf("%-12s %10.4f %10.4f %10.4f %12.2f %12.2f   (pixels: %d, %d, %d)\n", frame.c_str(), l.cloth, l.wall,
                l.floor, stops(l.cloth, l.wall), stops(l.cloth, l.floor), l.cloth_pixels, l.wall_pixels,
                l.floor_pixels);
  }
  return 0;
}

int print_luma(int argc, char** argv) {
  bsim::HdrImage picture;
  std::string error;
  if (!bsim::read_hdr(argv[2], picture, error)) {
    std::fprintf(stderr, "look_bench: %s\n", error.c_str());
    return 1;
  }
  const int cx = std::atoi(argv[3]), cy = std::atoi(argv[4]), half = argc > 5 ? std::atoi(argv[5]) : 4;
  double sum = 0;
  int n = 0;
  for (int y = std::max(0, cy - half); y <= std::min(picture.height - 1, cy + half); ++y)
    for (int x = std::max(0, cx - half); x <= std::min(picture.width - 1, cx + half); ++x, ++n) {
      const std::size_t p =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(picture.width) + static_cast<std::size_t>(x);
      sum += 0.2126 * picture.rgb[3 * p] + 0.7152 * picture.rgb[3 * p + 1] + 0.0722 * picture.rgb[3 * p + 2];
    }
  std::printf("%.5f\n", n > 0 ? sum / n : 0.0);
  return 0;
}

int print_differ(const char* a_path, const char* b_path, const char* png) {
  bsim::HdrImage a, b;
  std::string error;
  if (!bsim::read_hdr(a_path, a, error) || !bsim::read_hdr(b_path, b, error)) {
    std::fprintf(stderr, "look_bench: %s\n", error.c_str());
    return 1;
  }
  if (a.width != b.width || a.height != b.height) {
    std::fprintf(stderr, "look_bench: the two pictures differ in size\n");
    return 1;
  }
  bsim::HdrImage marked = a;
  long differ = 0;
  for (std::size_t p = 0; p < a.rgb.size() / 3; ++p) {
    bool same = true;  // within the .hdr's own rounding (its 8-bit mantissas)
    for (int c = 0; c < 3; ++c)
      same =
          same && std::abs(a.rgb[3 * p + c] - b.rgb[3 * p + c]) <= 0.01f * std::max(a.rgb[3 * p + c], b.rgb[3 * p + c]);
    differ += !same;
    for (int c = 0; c < 3; ++c) marked.rgb[3 * p + c] = same ? 0.3f * a.rgb[3 * p + c] : (c == 0 ? 1.0f : 0.0f);
  }
  std::printf("%ld of %d pixels differ (%.1f%%)\n", differ, a.width * a.height, 100.0 * differ / (a.width * a.height));
  if (!bsim::develop_to_png(std::move(marked), png, error)) {
    std::fprintf(stderr, "look_bench: %s\n", error.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string mode = argv[1];
  if (mode == "stops") return print_stops(argc, argv);
  if (mode == "luma" && (argc == 5 || argc == 6)) return print_luma(argc, argv);
  if (mode == "differ" && argc == 5) return print_differ(argv[2], argv[3], argv[4]);
  if (mode == "develop" && argc == 4) {
    std::string error;
    if (!bsim::develop_file(argv[2], argv[3], error)) {
      std::fprintf(stderr, "look_bench: %s\n", error.c_str());
      return 1;
    }
    return 0;
  }
  return usage();
}
