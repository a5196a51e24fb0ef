// The lens through billiards-export: frames/lens.txt holds the fixed scene and a line a movie frame,
// focused where the camera script looks; a frame whose lens (or number) differs from another's while
// its .pov does not is developed again from the traced picture of the same .pov, with no second trace,
// and gets its own grain; developing it again gives the same bytes.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "child_process.h"
#include "develop.h"
#include "ffmpeg_assemble.h"
#include "frame_lens.h"
#include "frames.h"
#include "movie_export.h"
#include "picture.h"
#include "png_file.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "render_jobs.h"
#include "shot.h"
#include "shots.h"
#include "soundtrack.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

/// Ann's break, written away from the rack, filmed from a still camera low over the bed: 7 s, the balls
/// at rest from 5.65 s (as in the captions' test).
const char* const kScene =
    "game 9ball seed 2 shots 1\nplayer Ann\nplayer Bo\ncue 0 90\nstroke 0.4 0 0 0\n"
    "camera\nevent 0 0 0 hover -0.7 0.3 0.25  0.1 0 0.028575\nendcamera\n";

/// A frame's text after its first line (its number and time).
std::string after_first_line(const std::string& text) { return text.substr(text.find('\n') + 1); }

/// The frames of `source` (frame_%05d.png or a movie) as 8-bit luma, one string a frame.
std::vector<std::string> luma_frames(const fs::path& dir, const std::string& source, int width, int height) {
  const test::CommandResult r = test::run_command("cd " + quoted(dir.string()) + " && ffmpeg -v error -i " +
                                                  quoted(source) + " -f rawvideo -pix_fmt gray luma.raw");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const std::string raw = test::require_file(dir / "luma.raw");
  fs::remove(dir / "luma.raw");
  std::vector<std::string> frames;
  const std::size_t size = static_cast<std::size_t>(width) * height;
  for (std::size_t at = 0; at + size <= raw.size(); at += size) frames.push_back(raw.substr(at, size));
  return frames;
}

/// The root mean square of the change of luma from each frame to the next: the grain, on a still picture.
double temporal_noise(const std::vector<std::string>& frames) {
  double sum = 0, n = 0;
  for (std::size_t k = 0; k + 1 < frames.size(); ++k)
    for (std::size_t i = 0; i < frames[k].size(); ++i) {
      const double d = static_cast<unsigned char>(frames[k][i]) - static_cast<unsigned char>(frames[k + 1][i]);
      sum += d * d;
      n += 1;
    }
  return std::sqrt(sum / n);
}

}  // namespace

TEST_SUITE("lens movie") {
  TEST_CASE("the movie keeps the grain: x264 passes on the frames' noise from one frame to the next") {
    for (const char* tool : {"ffmpeg"}) test::require_program(tool);
    test::TempDir dir;
    // A still picture of the cloth (the exposed light of the lit bed), its grain new in each frame.
    const int width = 320, height = 180, frames = 12, fps = 30;
    fs::create_directories(dir.path / "frames");
    for (int k = 0; k < frames; ++k) {
      HdrImage image{width, height, std::vector<float>(3 * static_cast<std::size_t>(width) * height)};
      for (std::size_t i = 0; i < image.rgb.size(); i += 3)
        image.rgb[i] = 0.05f, image.rgb[i + 1] = 0.2f, image.rgb[i + 2] = 0.08f;
      expose(image);
      add_grain(image, k);
      std::string error;
      REQUIRE_MESSAGE(
          write_png((dir.path / "frames" / (frame_name(k) + ".png")).string(), tone_map(image), width, height, error),
          error);
    }
    AudioBuffer silence;
    silence.left.assign(static_cast<std::size_t>(kSampleRate * frames / fps), 0.0f);
    silence.right = silence.left;
    std::string error;
    REQUIRE_MESSAGE(write_wav((dir.path / "soundtrack.wav").string(), silence, error), error);
    const MovieSettings settings{find_program("ffmpeg"), fps, static_cast<double>(frames) / fps, true};
    REQUIRE_MESSAGE(assemble_movie(dir.path.string(), settings, error) == RunOutcome::done, error);
    const double source = temporal_noise(luma_frames(dir.path, "frames/frame_%05d.png", width, height));
    const double movie = temporal_noise(luma_frames(dir.path, "movie.mp4", width, height));
    CAPTURE(source);
    CAPTURE(movie);
    CHECK(source > 1.0);  // a level or two of 255: seen
    CHECK(movie > 0.85 * source);
  }

  TEST_CASE("billiards-export writes frames/lens.txt: the scene, and each frame focused where the camera looks") {
    test::TempDir dir;
    const std::string scene = dir.file("shot.scn", kScene);
    const test::CommandResult r =
        test::run_command("BSIM_CACHE_DIR=off " + quoted(test::bin("billiards-export")) + " " + quoted(scene) + " -o " +
                          quoted((dir.path / "out").string()) + " --no-render --fps 10 --quiet");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const std::string frames = (dir.path / "out" / "frames").string();
    const LensFile file = read_lens_file(frames);
    DepthScene depth;
    std::string error;
    CHECK_MESSAGE(parse_depth_scene(file.scene, depth, error), error);
    CHECK(depth.solids.size() > 10);
    int count = 0;
    for (const auto& e : fs::directory_iterator(frames)) count += e.path().extension() == ".pov";
    REQUIRE(static_cast<int>(file.frames.size()) == count);
    FrameLens first;
    REQUIRE(parse_frame_lens(file.frames.at(0), first));
    const double distance = (Vec3(0.1, 0, 0.028575) - Vec3(-0.7, 0.3, 0.25)).norm();
    CHECK(first.lens.focus == doctest::Approx(distance).epsilon(1e-9));
    CHECK(first.lens.aperture == doctest::Approx(aperture_for(distance)));
    CHECK(first.lens.focal_mm == doctest::Approx(focal_length_mm(kCameraFovDeg)));
    CHECK(first.moving.balls.size() == 10);
    CHECK(first.pose.location.x() == doctest::Approx(-0.7));
  }

  TEST_CASE("a frame whose lens line differs and whose .pov does not is developed from the same trace") {
    test::require_program("povray");
    const std::unique_ptr<Shot> shot = test::load_scene(kScene, "shot");
    test::TempDir dir;
    const std::string frames = dir.path.string();
    const int fps = 2, total = 14;
    {
      std::ofstream include(dir.path / std::string(kPovIncludeName));
      write_pov_include(shot->scene, Quality::draft, include);
    }
    // Frames 12 and 13 (6 and 6.5 s): the balls at rest under the still camera, the same .pov.
    for (int k : {12, 13}) {
      std::ofstream out(dir.path / (frame_name(k) + ".pov"));
      write_pov_frame(*shot, k, fps, out);
    }
    std::vector<FrameLens> lenses = frame_lenses(*shot, fps);
    REQUIRE(static_cast<int>(lenses.size()) >= total);
    lenses.resize(total);
    dir.file(kLensName, lens_text(depth_scene(shot->scene), lenses));
    CHECK(after_first_line(test::require_file(dir.path / (frame_name(12) + ".pov"))) ==
          after_first_line(test::require_file(dir.path / (frame_name(13) + ".pov"))));
    ExportOptions options;
    options.width = 160;
    options.height = 90;
    options.quality = Quality::draft;
    options.fps = fps;
    const std::vector<std::uint64_t> keys = frame_store_keys(frames, total, options);
    CHECK(keys[12] != keys[13]);  // each its own grain: the store never serves one for the other
    std::vector<FrameJob> jobs = {{12, keys[12]}, {13, keys[13]}};
    plan_partial_frames(*shot, options, jobs);
    CHECK(jobs[1].reference == 12);  // laid over frame 12's traced picture, nothing traced
    CHECK(jobs[1].rects.empty());

    // POV-Ray through a stand-in that counts its runs.
    const std::string counter = (dir.path / "runs").string();
    const std::string povray = dir.file("bin/povray", "#!/bin/sh\necho run >> " + quoted(counter) + "\nexec " +
                                                          quoted(find_program("povray")) + " \"$@\"\n");
    fs::permissions(povray, fs::perms::owner_all);
    const RenderSettings settings{povray, 160, 90, Quality::draft, 1, "", true};
    FrameCache no_store("", frames);
    std::string error;
    REQUIRE_MESSAGE(render_frames(frames, jobs, total, settings, no_store, error) == RunOutcome::done, error);
    CHECK(test::require_file(counter) == "run\n");
    const std::string twelve = test::require_file(dir.path / (frame_name(12) + ".png"));
    const std::string thirteen = test::require_file(dir.path / (frame_name(13) + ".png"));
    CHECK(twelve != thirteen);
    // The two differ by their grain alone: a few levels of 255, everywhere.
    const test::Picture a = test::load_png(dir.path / (frame_name(12) + ".png")),
                        b = test::load_png(dir.path / (frame_name(13) + ".png"));
    int differ = 0, most = 0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
      const int d = std::abs(static_cast<int>(a.rgb[i]) - static_cast<int>(b.rgb[i]));
      differ += d > 0;
      most = std::max(most, d);
    }
    CHECK(differ > static_cast<int>(a.rgb.size() / 10));
    CHECK(most <= 24);

    // Rendered again, whole this time: the same bytes.
    fs::remove(dir.path / (frame_name(12) + ".png"));
    REQUIRE_MESSAGE(render_frames(frames, {{12, keys[12]}}, total, settings, no_store, error) == RunOutcome::done,
                    error);
    CHECK(test::require_file(dir.path / (frame_name(12) + ".png")) == twelve);
  }
}
