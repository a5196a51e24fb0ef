// Tracing only what changed (export/changed_region.h) makes the same pictures as tracing every pixel:
// every frame of five scenes (one of several shots, one of a ball falling into a pocket, one of a
// ball rolling past behind another that mirrors it), rendered
// both ways by POV-Ray at final quality (the preset whose adaptive antialiasing shares samples within
// a render block and whose area light is sampled adaptively: what could make a partial render differ),
// compared pixel for pixel; and rectangles of a larger frame where POV-Ray's shadow cache once made
// pixels differ.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include "camera_view.h"
#include "changed_region.h"
#include "child_process.h"
#include "develop.h"
#include "export_options.h"
#include "files.h"
#include "movie_export.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "render_jobs.h"
#include "shot.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  REQUIRE(std::regex_search(json, m, std::regex("\"" + key + "\": ?([0-9.]+)")));
  return std::stod(m[1]);
}

/// Renders `scene` (empty: the built-in break) into `out` with the frame store off, so that every
/// frame is traced in this run.
void render(const std::string& scene, const fs::path& out, int fps, const std::string& extra) {
  const test::CommandResult r = test::run_command(
      "BSIM_CACHE_DIR=off " + quoted(test::bin("billiards-export")) + " " + scene + " -o " + quoted(out.string()) +
      " --size 320x180 --quality final --quiet --fps " + std::to_string(fps) + " " + extra);
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
}

/// Renders the scene both ways and compares every frame. The PNGs are compared byte for byte: the
/// develop stage writes the same bytes for the same pixels (develop.h), so equal bytes are equal
/// pixels and any pixel that differs shows.
void same_both_ways(const std::string& scene, int fps) {
  test::TempDir dir;
  render(scene, dir.path / "whole", fps, "--whole-frames");
  render(scene, dir.path / "partial", fps, "");
  const std::string summary = test::require_file(dir.path / "partial" / "run.json");
  // The path under test was taken: some frames were traced in part, and less than every pixel.
  CHECK(json_number(summary, "partial") >= 3);
  CHECK(json_number(summary, "traced") < 0.9);
  CHECK(json_number(test::require_file(dir.path / "whole" / "run.json"), "partial") == 0);
  int frames = 0;
  for (const auto& e : fs::directory_iterator(dir.path / "whole" / "frames")) {
    if (e.path().extension() != ".png") continue;
    ++frames;
    const auto whole = test::read_file(e.path());
    const auto partial = test::read_file(dir.path / "partial" / "frames" / e.path().filename());
    REQUIRE(whole);
    REQUIRE_MESSAGE(partial, e.path().filename().string());
    const std::string name = e.path().filename().string();
    CHECK_MESSAGE(*whole == *partial, name);
  }
  CHECK(frames >= 8);
}

/// Frames `frames` of `scene_file` at `fps` and width x height, final quality: each frame's rectangles,
/// traced alone by POV-Ray as the exporter runs it, against the same pixels of the frame traced whole.
/// The pictures POV-Ray writes (linear light, before developing) are compared, so nothing can hide a
/// difference.
void rectangles_equal_whole(const std::string& scene_file, int fps, int width, int height,
                            const std::vector<int>& frames) {
  const std::string povray = find_program("povray");
  const auto text = test::read_file(test::source_path(scene_file));
  REQUIRE(text);
  ShotResult loaded = load_shot(*text, "shots");
  REQUIRE(loaded.scripted());
  ExportOptions options;
  options.fps = fps, options.width = width, options.height = height, options.quality = Quality::final;
  std::vector<FrameJob> jobs;
  for (int frame : frames) jobs.push_back({frame - 1, 0, -1, {}}), jobs.push_back({frame, 0, -1, {}});
  plan_partial_frames(*loaded.shot, options, jobs);

  test::TempDir dir;
  {
    std::ofstream include(dir.path / kPovIncludeName);
    write_pov_include(loaded.shot->scene, Quality::final, include);
  }
  const RenderSettings settings{povray, width, height, Quality::final, 1, "", true};
  const auto trace = [&](const FrameJob& job, int part) {
    std::string command = "cd " + quoted(dir.path.string()) + " &&", output;
    for (const std::string& arg : povray_arguments(settings, job, part)) {
      command += " " + quoted(arg);
      if (arg.rfind("+O", 0) == 0) output = arg.substr(2);
    }
    const test::CommandResult r = test::run_command(command + " 2>&1");
    REQUIRE_MESSAGE(r.exit_code == 0, r.out);
    HdrImage picture;
    std::string error;
    REQUIRE_MESSAGE(read_hdr((dir.path / output).string(), picture, error), error);
    return picture;
  };
  std::size_t compared = 0;  // every frame asked for is traced in rectangles: none is a whole frame
  for (const FrameJob& job : jobs) {
    if (job.reference < 0 || std::find(frames.begin(), frames.end(), job.frame) == frames.end()) continue;
    ++compared;
    {
      std::ofstream out(dir.path / (frame_name(job.frame) + ".pov"));
      write_pov_frame(*loaded.shot, job.frame, fps, out);
    }
    const HdrImage whole = trace({job.frame, 0, -1, {}}, -1);
    REQUIRE(!job.rects.empty());
    for (std::size_t part = 0; part < job.rects.size(); ++part) {
      const HdrImage traced = trace(job, static_cast<int>(part));
      const PixelRect& r = job.rects[part];
      int differ = 0;
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x)
          for (int c = 0; c < 3; ++c) {
            const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x) + c;
            differ += whole.rgb[i] != traced.rgb[i];
          }
      CAPTURE(job.frame);
      CAPTURE(part);
      CHECK(differ == 0);
    }
  }
  CHECK(compared == frames.size());
}

/// Frame `frame` and the one before it of tests/export/mirror_graze.scn traced whole at width x
/// height: every pixel on the 8 (its view meets the 8's sphere) that differs between the two lies,
/// where its view meets the 8, within the 8's mirror patch towards the cue ball (in either frame) or
/// within a pixel of it. Returns how many pixels on the 8 differ.
int mirror_differences_in_patch(int frame, int width, int height) {
  const auto text = test::read_file(test::source_path("tests/export/mirror_graze.scn"));
  REQUIRE(text);
  ShotResult loaded = load_shot(*text, "mirror_graze");
  REQUIRE(loaded.scripted());
  constexpr int kFps = 4;
  test::TempDir dir;
  {
    std::ofstream include(dir.path / kPovIncludeName);
    write_pov_include(loaded.shot->scene, Quality::final, include);
  }
  const RenderSettings settings{find_program("povray"), width, height, Quality::final, 1, "", true};
  std::vector<HdrImage> pictures;
  std::vector<FrameContent> contents;
  for (const int f : {frame - 1, frame}) {
    contents.push_back(frame_content(*loaded.shot, f, kFps));
    std::ofstream(dir.path / (frame_name(f) + ".pov")) << pov_frame_text(contents.back());
    std::string command = "cd " + quoted(dir.path.string()) + " &&", output;
    for (const std::string& arg : povray_arguments(settings, {f, 0, -1, {}}, -1)) {
      command += " " + quoted(arg);
      if (arg.rfind("+O", 0) == 0) output = arg.substr(2);
    }
    const test::CommandResult r = test::run_command(command + " 2>&1");
    REQUIRE_MESSAGE(r.exit_code == 0, r.out);
    std::string error;
    pictures.emplace_back();
    REQUIRE_MESSAGE(read_hdr((dir.path / output).string(), pictures.back(), error), error);
  }
  REQUIRE(contents[1].parts.size() >= 2);
  const FramePart& eight = contents[1].parts[1];  // the scene's second ball, still
  REQUIRE(eight.text == contents[0].parts[1].text);
  const BoundSphere ball = eight.seen.front().a;
  const double radius = ball.radius - kBoundSlack;
  std::vector<BoundSphere> patches;
  for (const FrameContent& content : contents)
    for (const BoundCapsule& c : content.parts[0].seen) {
      const Vec3 middle = 0.5 * (c.a.centre + c.b.centre);
      const BoundSphere target{middle, 0.5 * (c.b.centre - c.a.centre).norm() + std::max(c.a.radius, c.b.radius)};
      patches.push_back(mirror_patch(ball, contents[1].camera_pose.location, target));
    }
  const CameraView view(contents[1].camera_pose, kCameraFovDeg, static_cast<double>(width) / height);
  int differ = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x);
      if (std::equal(&pictures[0].rgb[i], &pictures[0].rgb[i] + 3, &pictures[1].rgb[i])) continue;
      const Vec3 d = view.ray(picture_point(x + 0.5, y + 0.5, width, height));
      const Vec3 to = ball.centre - view.eye();
      const double along = to.dot(d), miss = (to - along * d).norm();
      if (miss >= radius) continue;  // not on the 8
      const Vec3 p = view.eye() + (along - std::sqrt(radius * radius - miss * miss)) * d;
      const double pixel = 2 * view.half_width() * (p - view.eye()).norm() / width;  // m a pixel spans there
      ++differ;
      CAPTURE(x);
      CAPTURE(y);
      CHECK(std::any_of(patches.begin(), patches.end(),
                        [&](const BoundSphere& patch) { return (p - patch.centre).norm() <= patch.radius + pixel; }));
    }
  return differ;
}

}  // namespace

TEST_SUITE("partial frames") {
  TEST_CASE("the built-in break, traced only where it changed, is the whole-frame render pixel for pixel") {
    test::require_program("povray");
    test::require_program("ffmpeg");
    same_both_ways("", 1);  // 11 frames: the stick's strokes, the spread, the balls coming to rest
  }

  TEST_CASE("a bank shot with the stick, traced only where it changed, is the whole-frame render pixel for pixel") {
    test::require_program("povray");
    test::require_program("ffmpeg");
    same_both_ways(quoted(test::source_path("scenes/bank.scn").string()), 2);
  }

  TEST_CASE("three shots, the stick coming and going between them, traced only where they changed") {
    test::require_program("povray");
    test::require_program("ffmpeg");
    same_both_ways(quoted(test::source_path("tests/scene/three_shots.scn").string()), 1);
  }

  TEST_CASE("a ball knocked off a corner's shelf through the hole into the cup, traced only where it changed") {
    // The shelf's cloth, the slate's rounded lip, the hole behind the mouth and the lamp's light in the
    // cup, all in the picture, with the ball's shadow crossing them and the ball falling in.
    test::require_program("povray");
    test::require_program("ffmpeg");
    same_both_ways(quoted(test::source_path("tests/export/shelf_drop.scn").string()), 5);
  }

  TEST_CASE("a still ball mirroring a ball rolling past behind it, at grazing angles, traced only where it changed") {
    // Seen low and close, the cue ball rolls past behind the 8 and beside it: the 8's clear coat
    // shows it near the 8's rim, and only the patch of the 8 where it can show is traced again
    // (changed_region.h, mirror_patch), not the whole ball.
    test::require_program("povray");
    test::require_program("ffmpeg");
    same_both_ways(quoted(test::source_path("tests/export/mirror_graze.scn").string()), 4);
  }

  TEST_CASE("where POV-Ray's picture of a still ball changes, it lies within the ball's mirror patch") {
    // The 8 traced whole in two frames as the cue ball rolls past behind it and to its side: the
    // pixels of the 8 that differ are its mirror image of the cue ball, all within the patch.
    test::require_program("povray");
    int differ = 0;
    for (const int frame : {15, 16, 17}) differ += mirror_differences_in_patch(frame, 480, 270);
    CHECK(differ >= 10);  // the 8 does show the cue ball
  }

  TEST_CASE("a rectangle traced alone is the whole frame's pixels where shadow rays graze a ball") {
    // Frames 42 and 71 of the run of shots at 10 fps, 640x360, the camera still: balls of the spreading
    // rack near one another and by a cushion. POV-Ray's shadow cache for a global light once made 2
    // pixels of such frames differ (room.inc, LampLight).
    test::require_program("povray");
    rectangles_equal_whole("scenes/runout.scn", 10, 640, 360, {42, 71});
  }
}
