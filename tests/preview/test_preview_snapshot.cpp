// billiards-preview headless, end to end: snapshots of the requested size with real detail, the same
// bytes every run, `event:N` as the instant of event N, the timeline picture, the animatic, and the
// one-line refusal to open a window without a display.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <stb_image.h>

#include "files.h"
#include "fixtures.h"
#include "shot.h"
#include "support.h"

using namespace bsim;
using bsim::test::bin;
using bsim::test::require_file;
using bsim::test::run_command;
using bsim::test::TempDir;

namespace {

// The cue ball sent into a small cluster: a few collisions and a cushion within a couple of seconds.
const std::string kScene = test::fixtures::cluster_scene();

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  int distinct_colours() const {
    std::set<unsigned> seen;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
      seen.insert(unsigned(rgb[i]) << 16 | unsigned(rgb[i + 1]) << 8 | rgb[i + 2]);
    return static_cast<int>(seen.size());
  }
};

Image load_png(const std::string& path) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  REQUIRE_MESSAGE(data, "cannot read " << path);
  image.rgb.assign(data, data + static_cast<std::size_t>(image.width) * image.height * 3);
  stbi_image_free(data);
  return image;
}

std::string preview(const std::string& args) { return bin("billiards-preview") + " " + args; }

}  // namespace

TEST_SUITE("preview snapshots") {
  TEST_CASE("a snapshot is a detailed picture of the requested size, the same bytes every time") {
    TempDir dir;
    const std::string scene = dir.file("cluster.scn", kScene);
    const std::string a = (dir.path / "a.png").string(), b = (dir.path / "b.png").string();
    const auto first = run_command(preview(scene + " --at 2.9 --size 320x180 -o " + a));
    INFO(first.err);
    REQUIRE(first.exit_code == 0);
    const Image image = load_png(a);
    CHECK(image.width == 320);
    CHECK(image.height == 180);
    CHECK(image.distinct_colours() > 200);
    REQUIRE(run_command(preview(scene + " --at 2.9 --size 320x180 -o " + b)).exit_code == 0);
    CHECK(require_file(a) == require_file(b));
  }

  TEST_CASE("a pocketed ball is drawn lying in its pocket's cup, where the POV-Ray frames show it") {
    // Ball 3 (red) rolls into a pocket under a camera looking straight down into it.
    TempDir dir;
    const std::string scene = dir.file("pocket.scn",
                                       "cue 1 0\n"
                                       "ball 0 -1 0.4 0.028575  0 0 0  1 0 0 0\n"
                                       "ball 3 -0.3 -0.3 0.028575  2 0 0  1 0 0 0\n"
                                       "rail -1.5 0.8 0.04   1.5 0.8 0.04\n"
                                       "rail 1.5 0.8 0.04   1.5 -0.8 0.04\n"
                                       "rail 1.5 -0.8 0.04   -1.5 -0.8 0.04\n"
                                       "rail -1.5 -0.8 0.04   -1.5 0.8 0.04\n"
                                       "pocket 0.2 -0.3 0 0.07\n"
                                       "camera\nevent 0 0 0 hover 0.2 -0.3 0.5  0.2 -0.3 0\nendcamera\n");
    const std::string out = (dir.path / "in_pocket.png").string();
    const auto run = run_command(preview(scene + " --at 3 --size 160x90 -o " + out));
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    const Image image = load_png(out);
    int red = 0;
    for (int y = 30; y < 60; ++y)
      for (int x = 65; x < 95; ++x) {
        const unsigned char* p = &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
        red += p[0] > 120 && p[1] < 70 && p[2] < 70;
      }
    CHECK(red > 20);
  }

  TEST_CASE("--at event:N shows the instant of event N, and a missing event is a usage error") {
    TempDir dir;
    const std::string scene = dir.file("cluster.scn", kScene);
    const ShotResult loaded = load_shot(kScene, "cluster");
    REQUIRE(loaded.shot);
    const auto& events = loaded.shot->timeline.events();
    REQUIRE(events.size() >= 4);
    // The time printed with enough digits to read back as the same double.
    std::ostringstream seconds;
    seconds.precision(17);
    seconds << events[2].time;
    const std::string by_event = (dir.path / "e.png").string(), by_time = (dir.path / "t.png").string();
    REQUIRE(run_command(preview(scene + " --at event:2 --size 160x90 -o " + by_event)).exit_code == 0);
    REQUIRE(run_command(preview(scene + " --at " + seconds.str() + " --size 160x90 -o " + by_time)).exit_code == 0);
    CHECK(require_file(by_event) == require_file(by_time));

    const std::string missing = (dir.path / "m.png").string();
    const auto bad = run_command(preview(scene + " --at event:" + std::to_string(events.size()) + " -o " + missing));
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("numbered 0 to " + std::to_string(events.size() - 1)) != std::string::npos);
    CHECK_FALSE(std::ifstream(missing).good());
  }

  TEST_CASE("--at shot:K shows shot K's strike; a shot the scene lacks is a usage error naming the range") {
    // tests/scene/three_shots.scn: three shots; shot 2's strike is Timeline::shots()[1].cue, its cue event.
    const std::string scene = test::quoted(test::source_path("tests/scene/three_shots.scn").string());
    const ShotResult loaded = load_shot(test::require_file(test::source_path("tests/scene/three_shots.scn")), "three");
    REQUIRE(loaded.shot);
    const Timeline& timeline = loaded.shot->timeline;
    REQUIRE(timeline.shot_count() == 3);
    std::ostringstream seconds;
    seconds.precision(17);
    seconds << timeline.shots()[1].cue;
    TempDir dir;
    const std::string by_shot = (dir.path / "s.png").string(), by_time = (dir.path / "t.png").string();
    const auto shot = run_command(preview(scene + " --at shot:2 --overlay aim --size 160x90 -o " + by_shot));
    INFO(shot.err);
    REQUIRE(shot.exit_code == 0);
    REQUIRE(run_command(preview(scene + " --at " + seconds.str() + " --overlay aim --size 160x90 -o " + by_time))
                .exit_code == 0);
    CHECK(require_file(by_shot) == require_file(by_time));
    // The aim overlay draws shot 2's aim at shot 2's strike (the first shot's aim ended at its first
    // contact): the picture differs from the one without it.
    const std::string bare = (dir.path / "bare.png").string();
    REQUIRE(run_command(preview(scene + " --at shot:2 --size 160x90 -o " + bare)).exit_code == 0);
    CHECK(require_file(bare) != require_file(by_shot));
    // Shot 1's strike is another picture (the balls are elsewhere).
    const std::string first = (dir.path / "f.png").string();
    REQUIRE(run_command(preview(scene + " --at shot:1 --overlay aim --size 160x90 -o " + first)).exit_code == 0);
    CHECK(require_file(first) != require_file(by_shot));

    for (const char* bad : {"shot:4", "shot:0"}) {
      const std::string missing = (dir.path / "m.png").string();
      const auto r =
          run_command(preview(scene + " --at shot:1 --at " + bad + " -o " + (dir.path / "m_%t.png").string()));
      CAPTURE(bad);
      CHECK(r.exit_code == 2);
      CHECK(r.err.find(bad) != std::string::npos);
      CHECK_FALSE(std::ifstream((dir.path / "m_shot_1.png").string()).good());  // nothing written
    }
    const auto beyond = run_command(preview(scene + " --at shot:4 -o " + (dir.path / "b.png").string()));
    CHECK(beyond.err.find("--at shot:4: this scene has 3 shots, numbered 1 to 3") != std::string::npos);
    CHECK_FALSE(std::ifstream((dir.path / "b.png").string()).good());
  }

  TEST_CASE("different times give different pictures; the overlays add to the picture") {
    TempDir dir;
    const std::string scene = dir.file("cluster.scn", kScene);
    const std::string early = (dir.path / "early.png").string(), late = (dir.path / "late.png").string();
    const std::string marked = (dir.path / "marked.png").string();
    REQUIRE(run_command(preview(scene + " --at 0.5 --size 160x90 -o " + early)).exit_code == 0);
    REQUIRE(run_command(preview(scene + " --at 3.5 --size 160x90 -o " + late)).exit_code == 0);
    REQUIRE(
        run_command(preview(scene + " --at 3.5 --size 160x90 --overlay paths,events,camera -o " + marked)).exit_code ==
        0);
    CHECK(require_file(early) != require_file(late));
    CHECK(require_file(late) != require_file(marked));
  }

  TEST_CASE("a scene error is reported with its location and writes nothing") {
    TempDir dir;
    const std::string scene =
        dir.file("bad.scn", "cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nball 99 0.5 0 0.028575 0 0 0 1 0 0 0\n");
    const std::string out = (dir.path / "x.png").string();
    const auto r = run_command(preview(scene + " --at 1 -o " + out));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find(scene + ":3:") != std::string::npos);
    CHECK_FALSE(std::ifstream(out).good());
  }

  TEST_CASE("the timeline picture has the requested size, or a wide default") {
    TempDir dir;
    const std::string scene = dir.file("cluster.scn", kScene);
    const std::string sized = (dir.path / "sized.png").string(), wide = (dir.path / "wide.png").string();
    REQUIRE(run_command(preview(scene + " --timeline --size 800x200 -o " + sized)).exit_code == 0);
    const Image small = load_png(sized);
    CHECK(small.width == 800);
    CHECK(small.height == 200);
    CHECK(small.distinct_colours() > 40);
    REQUIRE(run_command(preview(scene + " --timeline -o " + wide)).exit_code == 0);
    CHECK(load_png(wide).width == 1600);
  }

  TEST_CASE("the animatic is an MP4 with video and sound as long as its frames") {
    test::require_program("ffmpeg");
    test::require_program("ffprobe");
    TempDir dir;
    const std::string scene = dir.file("cluster.scn", kScene);
    const std::string movie = (dir.path / "a.mp4").string();
    const auto r = run_command(preview(scene + " --movie " + movie + " --size 160x90 --fps 8"));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto probe =
        run_command("ffprobe -v error -show_entries stream=codec_type,width,nb_frames -of csv=p=0 " + movie);
    REQUIRE_MESSAGE(probe.exit_code == 0, probe.err);
    CHECK(probe.out.find("video") != std::string::npos);
    CHECK(probe.out.find("audio") != std::string::npos);
    const ShotResult loaded = load_shot(kScene, "cluster");
    REQUIRE(loaded.shot);
    const int frames = static_cast<int>(std::llround(loaded.shot->timeline.duration() * 8));  // t < duration
    CHECK(probe.out.find("160," + std::to_string(frames)) != std::string::npos);
    CHECK_FALSE(std::ifstream(movie + ".partial").good());
  }

  TEST_CASE("without a display the window says so in one line and exits 2") {
    const auto r = run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + bin("billiards-preview"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("no display") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
}
