// The animatic's frames as it hands them to ffmpeg (animatic_frames.h: drawn while the frame before is
// written, each read straight from the offscreen buffer it was drawn in) are byte for byte the frames
// drawn one at a time into the canvas and read from it, as the animatic made them before: every
// frame, in order, with and without overlays, at an odd size too; a sink that fails stops the drawing.
#include <doctest/doctest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <imgui.h>

#include "animatic_frames.h"
#include "frames.h"
#include "headless_canvas.h"
#include "overlays.h"
#include "preview_options.h"
#include "scene_renderer.h"
#include "shot.h"
#include "shots.h"

using namespace bsim;

namespace {

/// The cue ball runs into the 9 under a still camera, the stick striking first: 2.5 s.
const char* const kScene =
    "cue 0 0\n"
    "ball 0 -0.3 0 0.028575  0 0 0  1 0 0 0\n"
    "ball 9  0.2 0.05 0.028575  0 0 0  1 0 0 0\n"
    "stroke 0.8 0 0 0\n"
    "camera\nevent 0 0 0 hover -1.2 -1.0 0.9  0 0 0\nendcamera\n";

using Frames = std::vector<std::vector<std::uint8_t>>;

/// Each frame drawn into the canvas and read from it (bottom row first), one after another.
Frames drawn_one_by_one(const PreviewOptions& options, const Shot& shot, int frames) {
  HeadlessCanvas canvas;
  SceneRenderer renderer;
  std::string error;
  REQUIRE_MESSAGE(canvas.open(options.width, options.height, 14, error), error);
  REQUIRE_MESSAGE(renderer.init(error), error);
  renderer.set_scene(shot.scene);
  const OverlayPaths paths = overlay_paths(shot);
  Frames drawn;
  for (int k = 0; k < frames; ++k) {
    const MovieFrame shown = shot.movie.frame(k, options.fps);
    const FrameState frame = scripted_frame(shot, shown);
    renderer.draw(shot.scene, frame, options.width, options.height);
    if (options.overlays.any()) {
      ImDrawList* list = canvas.begin_2d();
      draw_overlays(*list,
                    OverlayFrame{shot, shown.time, frame.camera, double(options.width), double(options.height),
                                 canvas.fonts(), 0, 0, &paths},
                    options.overlays);
      canvas.end_2d();
    }
    drawn.push_back(canvas.pixels());
  }
  return drawn;
}

/// The frames as the animatic hands them on; `fail_at`: the sink fails at that frame.
Frames handed_on(const PreviewOptions& options, const Shot& shot, int frames, bool& ok, int fail_at = -1) {
  HeadlessCanvas canvas;
  SceneRenderer renderer;
  std::string error;
  REQUIRE_MESSAGE(canvas.open(options.width, options.height, 14, error), error);
  REQUIRE_MESSAGE(renderer.init(error), error);
  renderer.set_scene(shot.scene);
  Frames got;
  const FrameSink sink = [&](const std::uint8_t* pixels, std::size_t bytes) {
    if (static_cast<int>(got.size()) == fail_at) return false;
    got.emplace_back(pixels, pixels + bytes);
    return true;
  };
  ok = draw_animatic_frames(options, shot, canvas, renderer, frames, sink, nullptr);
  return got;
}

}  // namespace

TEST_SUITE("preview animatic") {
  TEST_CASE("the frames handed to ffmpeg are the frames drawn one by one, byte for byte") {
    const std::unique_ptr<Shot> shot = test::load_scene(kScene, "strike");
    struct Case {
      int width, height;
      bool overlays;
    };
    for (const Case c : {Case{160, 90, false}, Case{161, 91, false}, Case{160, 90, true}}) {
      CAPTURE(c.width);
      CAPTURE(c.overlays);
      PreviewOptions options;
      options.width = c.width;
      options.height = c.height;
      options.fps = 8;
      options.overlays.paths = options.overlays.events = c.overlays;
      const int frames = shot->movie.frame_count(options.fps);
      REQUIRE(frames >= 12);
      const Frames reference = drawn_one_by_one(options, *shot, frames);
      bool ok = false;
      const Frames got = handed_on(options, *shot, frames, ok);
      CHECK(ok);
      REQUIRE(got.size() == reference.size());
      int same = 0;
      for (std::size_t k = 0; k < got.size(); ++k) same += got[k] == reference[k];
      CHECK(same == frames);
      CHECK(reference.front() != reference.back());  // the frames differ: each must be its own
    }
  }

  TEST_CASE("a sink that fails stops the frames: none after it is drawn or handed on") {
    const std::unique_ptr<Shot> shot = test::load_scene(kScene, "strike");
    PreviewOptions options;
    options.width = 64;
    options.height = 36;
    options.fps = 8;
    bool ok = true;
    const Frames got = handed_on(options, *shot, shot->movie.frame_count(options.fps), ok, 3);
    CHECK_FALSE(ok);
    CHECK(got.size() == 3);
  }
}
