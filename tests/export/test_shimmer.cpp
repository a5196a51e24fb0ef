// No shimmer: under a still camera, two consecutive final frames of a moving ball differ only round
// the ball. The lamp's area light has no jitter, the tone curve and the exposure are fixed, and the
// glare spreads a ball's glints only a few dozen pixels, so the rest of the picture (the far cloth and
// rail, the room, the near rail and the floor) keeps its bytes but for a rounding step in a few
// values (the lamp's area light with jitter changes about 190 of them). Rendered by POV-Ray through the
// export's own render path at a small size.
#include <doctest/doctest.h>

#include <stb_image.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <vector>

#include "child_process.h"
#include "frame_cache.h"
#include "picture.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "render_jobs.h"
#include "shots.h"
#include "support.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

// The cue ball rolls along y = 0 across the picture, the 1 rests near the far rail; the camera hovers
// over the near long side at x = 0 looking at the table's centre, so the rolling ball stays on the
// picture's middle row.
const char* const kScene =
    "cue 0 0\n"
    "ball 0 -0.9 0 0.028575  1.4 0 0  1 0 0 0\n"
    "ball 1  0.5 0.5 0.028575  0 0 0  1 0 0 0\n"
    "camera\n"
    "event 0 0 0 hover 0 -2.2 1.6  0 0 0\n"
    "endcamera\n";

using test::Picture;
const auto load = test::load_png;

}  // namespace

TEST_SUITE("pov") {
  TEST_CASE("a still camera over a moving ball: the picture away from the ball does not change") {
    test::require_program("povray");
    const std::unique_ptr<Shot> shot = test::load_scene(kScene, "shimmer");
    const int fps = 30, first = 120;  // 4 s in: struck at 2.5 s, the stick is away, the ball rolls
    REQUIRE(shot->timeline.state(0, (first + 1.0) / fps).velocity.norm() > 0.5);
    test::TempDir dir;
    {
      std::ofstream include(dir.path / std::string(kPovIncludeName));
      write_pov_include(shot->scene, Quality::final, include);
    }
    std::vector<FrameJob> jobs;
    for (int k : {first, first + 1}) {
      std::ofstream out(dir.path / (frame_name(k) + ".pov"));
      write_pov_frame(*shot, k, fps, out);
      jobs.push_back({k, static_cast<std::uint64_t>(k)});
    }
    const int width = 320, height = 180;
    const RenderSettings settings{find_program("povray"), width, height, Quality::final, 2, "", true};
    FrameCache no_store("", dir.path.string());
    std::string error;
    REQUIRE_MESSAGE(render_frames(dir.path.string(), jobs, first + 2, settings, no_store, error) == RunOutcome::done,
                    error);
    const Picture a = load(dir.path / (frame_name(first) + ".png"));
    const Picture b = load(dir.path / (frame_name(first + 1) + ".png"));
    REQUIRE(a.width == width);
    REQUIRE(b.width == width);

    // The ball's band: its row, the middle one, and 40 rows either side (its shadow, its blur and
    // three times the widest glare's radius at this size).
    const int band_top = height / 2 - 40, band_bottom = height / 2 + 40;
    int changed_in_band = 0, most_outside = 0, changed_outside = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3; ++c) {
          const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x) + c;
          const int d = std::abs(int(a.rgb[i]) - int(b.rgb[i]));
          if (y >= band_top && y < band_bottom) {
            changed_in_band += d > 8;
          } else {
            most_outside = std::max(most_outside, d);
            changed_outside += d > 0;
          }
        }
    MESSAGE("frame-to-frame difference away from the ball: at most " << most_outside << " of 255, in "
                                                                     << changed_outside << " channel values");
    CHECK(changed_in_band > 20);  // the ball did move, in its band
    // At most a rounding step in a few values (the far tail of the ball's glare, its reflection in the
    // other ball); an area light with jitter changes about 190 values out there.
    CHECK(most_outside <= 1);
    CHECK(changed_outside <= 20);
  }
}
