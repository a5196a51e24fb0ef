// Each frame's content is computed once: the exporter writes frames/*.pov from it, keys the frame
// store from the same text in memory and plans the partial renders from the same bounds. The keys are
// exactly those read back from the files (so a store filled by an earlier run is reused), and the
// plan is the one made from each frame computed anew.
#include <doctest/doctest.h>

#include <memory>
#include <string>
#include <vector>

#include "export_options.h"
#include "frame_captions.h"
#include "frame_lens.h"
#include "frames.h"
#include "movie_export.h"
#include "output_stage.h"
#include "pov_frame.h"
#include "run_summary.h"
#include "shot.h"
#include "shots.h"
#include "support.h"

using namespace bsim;

namespace {

/// Ann's break under a still camera, a game so that every frame has a caption: 7 s.
const char* const kGame =
    "game 9ball seed 2 shots 1\nplayer Ann\nplayer Bo\ncue 0 90\nstroke 0.4 0 0 0\n"
    "camera\nevent 0 0 0 hover 0 -2.2 1.6  0 0 0\nendcamera\n";

ExportOptions small_options() {
  ExportOptions options;
  options.width = 160;
  options.height = 90;
  options.quality = Quality::draft;
  options.fps = 4;
  options.no_render = true;  // no fonts needed to write captions.txt
  return options;
}

/// Writes the shot's frames into a stage of its own; `computed` gets how many frame contents that took.
StagedFrames write_frames(const Shot& shot, const ExportOptions& options, OutputStage& stage, long& computed) {
  std::string error;
  RunSummary summary;
  StagedFrames frames;
  const long before = frame_contents_computed();
  REQUIRE_MESSAGE(write_frames_and_sound(shot, options, stage, frames, summary, error), error);
  computed = frame_contents_computed() - before;
  return frames;
}

}  // namespace

TEST_SUITE("frames computed once") {
  TEST_CASE("a game's frames: each computed once, keyed in memory as from the files, planned as before") {
    const std::unique_ptr<Shot> shot = test::load_scene(kGame, "game");
    REQUIRE(shot->game);
    const ExportOptions options = small_options();
    const int frames = shot->movie.frame_count(options.fps);
    REQUIRE(frames >= 20);
    test::TempDir dir;
    OutputStage stage;
    std::string error;
    REQUIRE_MESSAGE(stage.open((dir.path / "out").string(), error), error);
    long computed = 0;
    const StagedFrames staged = write_frames(*shot, options, stage, computed);
    CHECK(computed == frames);  // not again for lens.txt
    REQUIRE(static_cast<int>(staged.contents.size()) == frames);
    CHECK(staged.captions == test::require_file(stage.path("frames/" + std::string(kCaptionsName))));
    CHECK(staged.lens == test::require_file(stage.path("frames/" + std::string(kLensName))));
    for (int k = 0; k < frames; ++k)
      CHECK(pov_frame_text(staged.contents[static_cast<std::size_t>(k)]) ==
            test::require_file(stage.path("frames/" + frame_name(k) + ".pov")));

    // The keys from memory are the keys read back from the files, and cost no frame again.
    const long before = frame_contents_computed();
    const std::vector<std::uint64_t> keys = frame_store_keys(staged, options);
    CHECK(keys == frame_store_keys(stage.path("frames"), frames, options));
    // Each frame's caption and lens line are in its key: a frame alike another in its .pov differs.
    CHECK(keys.front() != keys.back());

    // The partial renders planned from the frames as written, as from each frame computed anew.
    std::vector<FrameJob> jobs;
    for (int k = 0; k < frames; ++k) jobs.push_back({k, keys[static_cast<std::size_t>(k)]});
    std::vector<FrameJob> anew = jobs;
    plan_partial_frames(shot->scene, staged, options, jobs);
    CHECK(frame_contents_computed() == before);
    plan_partial_frames(*shot, options, anew);
    int partial = 0, traced_in_part = 0;
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      CAPTURE(i);
      CHECK(jobs[i].reference == anew[i].reference);
      CHECK(jobs[i].rects == anew[i].rects);
      partial += jobs[i].reference >= 0;
      traced_in_part += !jobs[i].rects.empty();
    }
    CHECK(partial > frames / 2);  // one still camera: most frames after the first
    CHECK(traced_in_part > 0);    // the break's balls move under it
  }

  TEST_CASE("a shot without a game: no captions in memory or on disk, the same keys") {
    const std::unique_ptr<Shot> shot = test::load_scene("ball 0 0 0\nball 1 0.5 0\ncue 0 0\nstroke 1 0 0 0\n", "plain");
    ExportOptions options = small_options();
    options.quality = Quality::final;
    test::TempDir dir;
    OutputStage stage;
    std::string error;
    REQUIRE_MESSAGE(stage.open((dir.path / "out").string(), error), error);
    long computed = 0;
    const StagedFrames staged = write_frames(*shot, options, stage, computed);
    const int frames = shot->movie.frame_count(options.fps);
    CHECK(computed == frames);
    CHECK(staged.captions.empty());
    CHECK(frame_store_keys(staged, options) == frame_store_keys(stage.path("frames"), frames, options));
  }
}
