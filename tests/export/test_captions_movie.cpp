// A game's movie with its captions, through billiards-export and POV-Ray at a small size: the frames
// with and without captions differ only in the lower half of the picture; each captioned frame's
// caption is in frames/captions.txt and is its moment's; a farm's node develops the same bytes as a
// local run; a frame whose caption changed while its .pov did not is developed again from the traced
// picture of the same .pov, with no second trace; a scene without a game has no captions.
#include <doctest/doctest.h>

#include <stb_image.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "child_process.h"
#include "frame_captions.h"
#include "frames.h"
#include "movie_export.h"
#include "picture.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "render_jobs.h"
#include "shot.h"
#include "shots.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

/// Ann's break is written away from the rack (a foul: the cue ball missed every ball), and the game
/// stops there, its one shot filmed from a still camera: 7 s, the balls at rest from 5.65 s.
const char* const kGame =
    "game 9ball seed 2 shots 1\nplayer Ann\nplayer Bo\ncue 0 90\nstroke 0.4 0 0 0\n"
    "camera\nevent 0 0 0 hover 0 -2.2 1.6  0 0 0\nendcamera\n";
const char* const kOptions = " --size 160x90 --fps 2 --quality draft --quiet";

using test::Picture;
const auto load = test::load_png;

/// The first row in which the pictures differ (their height when none does).
int first_differing_row(const Picture& a, const Picture& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  const std::size_t row = 3 * static_cast<std::size_t>(a.width);
  for (int y = 0; y < a.height; ++y)
    if (!std::equal(a.rgb.begin() + static_cast<std::ptrdiff_t>(y * row),
                    a.rgb.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                    b.rgb.begin() + static_cast<std::ptrdiff_t>(y * row)))
      return y;
  return a.height;
}

test::CommandResult run_export(const test::TempDir& dir, const std::string& arguments) {
  return test::run_command("BSIM_CACHE_DIR=" + quoted((dir.path / "store").string()) + " " +
                           quoted(test::bin("billiards-export")) + " " + arguments);
}

int frames_in(const fs::path& frames) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(frames)) n += e.path().extension() == ".png";
  return n;
}

}  // namespace

TEST_SUITE("captions") {
  TEST_CASE("--captions: a game's frames get a caption each, low in the picture; off, none; no game, none") {
    for (const char* tool : {"povray", "ffmpeg"}) test::require_program(tool);
    test::TempDir dir;
    const std::string scene = dir.file("game.scn", kGame);
    const fs::path on = dir.path / "on", off = dir.path / "off";
    test::CommandResult r = run_export(dir, quoted(scene) + " -o " + quoted(on.string()) + kOptions);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    r = run_export(dir, quoted(scene) + " -o " + quoted(off.string()) + kOptions + " --captions off");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK_FALSE(fs::exists(off / "frames" / kCaptionsName));

    // Every frame has its caption; the foul is called from the frame at which the balls rest (5.65 s).
    const std::map<int, std::string> lines = read_caption_lines((on / "frames").string());
    const int frames = frames_in(on / "frames");
    REQUIRE(static_cast<int>(lines.size()) == frames);
    for (const auto& entry : lines) {
      const int frame = entry.first;
      const std::string& line = entry.second;
      FrameCaption caption;
      REQUIRE(parse_caption(line, caption));
      CAPTURE(frame);
      CHECK(caption.caption.players == std::vector<std::string>{"Ann", "Bo"});
      const bool called = frame_time(frame, 2) >= 5.65;
      CHECK(caption.caption.calls.empty() != called);
      if (called) CHECK(caption.caption.calls[0].text == "the cue ball missed every ball \xC2\xB7 ball in hand");
    }

    // With and without: the same upper half in every frame, and the lower half of each differs.
    for (int k = 0; k < frames; ++k) {
      const std::string name = frame_name(k) + ".png";
      const Picture with = load(on / "frames" / name), without = load(off / "frames" / name);
      CAPTURE(k);
      const int row = first_differing_row(with, without);
      CHECK(row >= with.height / 2);
      CHECK(row < with.height);
    }
    // The same bytes again, from a store of its own.
    r = test::run_command("BSIM_CACHE_DIR=off " + quoted(test::bin("billiards-export")) + " " + quoted(scene) + " -o " +
                          quoted((dir.path / "again").string()) + kOptions);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    for (int k = 0; k < frames; ++k)
      CHECK(test::require_file(dir.path / "again/frames" / (frame_name(k) + ".png")) ==
            test::require_file(on / "frames" / (frame_name(k) + ".png")));

    // A scene with no game: no captions, whatever --captions says.
    const std::string plain = dir.file("plain.scn", "ball 0 0 0\nball 1 0.5 0\ncue 0 0\nstroke 1 0 0 0\n");
    r = run_export(dir, quoted(plain) + " -o " + quoted((dir.path / "plain").string()) + " --no-render --fps 2");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK_FALSE(fs::exists(dir.path / "plain/frames" / kCaptionsName));
  }

  TEST_CASE("--captions takes on or off, and does nothing with --events-only") {
    test::TempDir dir;
    const std::string scene = dir.file("game.scn", kGame);
    test::CommandResult r = run_export(dir, quoted(scene) + " --captions maybe");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--captions") != std::string::npos);
    CHECK(r.err.find("on or off") != std::string::npos);
    r = run_export(dir, quoted(scene) + " --events-only --captions off");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--captions does nothing with --events-only") != std::string::npos);
  }

  TEST_CASE("a frame whose caption changed and whose .pov did not is developed from the same trace") {
    test::require_program("povray");
    const std::unique_ptr<Shot> shot = test::load_scene(kGame, "game");
    test::TempDir dir;
    const std::string frames = dir.path.string();
    {
      std::ofstream include(dir.path / std::string(kPovIncludeName));
      write_pov_include(shot->scene, Quality::draft, include);
    }
    // Frames 12 and 13 (6 and 6.5 s): the balls at rest under the still camera, the same .pov; the
    // second a replay's frame, so its caption differs.
    const int fps = 2, total = 14;
    std::vector<FrameMoment> moments = movie_frame_moments(*shot, fps);
    REQUIRE(moments.size() >= static_cast<std::size_t>(total));
    moments.resize(total);
    moments[13].replay = true;
    const std::vector<FrameCaption> captions = frame_captions(*shot, moments, 160, 90);
    dir.file(kCaptionsName, captions_text(captions));
    for (int k : {12, 13}) {
      std::ofstream out(dir.path / (frame_name(k) + ".pov"));
      write_pov_frame(*shot, k, fps, out);
    }
    REQUIRE(test::require_file(dir.path / (frame_name(12) + ".pov")).find("camera") != std::string::npos);
    ExportOptions options;
    options.width = 160;
    options.height = 90;
    options.quality = Quality::draft;
    options.fps = fps;
    const std::vector<std::uint64_t> keys = frame_store_keys(frames, total, options);
    CHECK(keys[12] != keys[13]);  // the frame store never serves one for the other
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
    const Picture first = load(dir.path / (frame_name(12) + ".png")),
                  replay = load(dir.path / (frame_name(13) + ".png"));
    const int row = first_differing_row(first, replay);
    CHECK(row >= 45);
    CHECK(row < 90);
  }

  TEST_CASE("a farm's node draws the same captions: its frames are the local run's, byte for byte") {
    for (const char* tool : {"povray", "ffmpeg"}) test::require_program(tool);
    test::TempDir dir;
    const std::string scene = dir.file("game.scn", kGame);
    // A stand-in sbatch that takes every job: ids 41, 42.
    const std::string sbatch =
        dir.file("bin/sbatch",
                 "#!/bin/sh\ncase \"$*\" in *--test-only*) echo 'sbatch: Job 7 to start'; exit 0;; "
                 "esac\nn=$(cat " +
                     quoted((dir.path / "n").string()) +
                     " 2>/dev/null || echo 40)\n"
                     "echo $((n + 1)) > " +
                     quoted((dir.path / "n").string()) + "\necho $((n + 1))\n");
    fs::permissions(sbatch, fs::perms::owner_all);
    const fs::path farm = dir.path / "farm", local = dir.path / "local";
    const std::string env = "BSIM_CACHE_DIR=off TMPDIR=" + quoted(dir.path.string()) + " ";
    const std::string program = quoted(test::bin("billiards-export"));
    test::CommandResult r =
        test::run_command("PATH=" + quoted((dir.path / "bin").string()) + ":\"$PATH\" " + env + program + " " +
                          quoted(scene) + " --farm slurm -o " + quoted(farm.string()) + kOptions);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(fs::exists(farm / "frames" / kCaptionsName));
    r = test::run_command(env + program + " " + quoted(farm.string()) + " --farm render --frames 0-13");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    r = test::run_command(env + program + " " + quoted(scene) + " -o " + quoted(local.string()) + kOptions);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const int frames = frames_in(local / "frames");
    REQUIRE(frames == 14);
    for (int k = 0; k < frames; ++k) {
      CAPTURE(k);
      const std::string name = frame_name(k) + ".png";
      if (!fs::exists(farm / "frames" / name)) continue;  // a copy of an earlier frame, made by the movie job
      CHECK(test::require_file(farm / "frames" / name) == test::require_file(local / "frames" / name));
    }
  }
}
