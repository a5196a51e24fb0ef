// A camera script that names events the shot lacks (or lists them out of order): `--timeline` still
// draws the shot's real events with the script laid against them as written, the faulty descriptions
// in red with their errors, prints the located errors, and exits 1. The other outputs keep failing.
#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <imgui.h>
#include <stb_image.h>

#include "fixtures.h"
#include "headless_canvas.h"
#include "script_as_written.h"
#include "shot.h"
#include "support.h"

using namespace bsim;
using bsim::test::bin;
using bsim::test::run_command;
using bsim::test::TempDir;

namespace {

// The cue ball sent into a small cluster: several collisions and cushions within a few seconds.
std::string scene_with_camera(const std::vector<std::string>& descriptions) {
  std::string text = std::string(test::fixtures::kClusterBalls) + "camera\n";
  for (const std::string& d : descriptions) text += d + "\n";
  return text + "endcamera\n";
}

std::string hover(int event) { return "event " + std::to_string(event) + " 0.3 0.3 hover -1.5 -1.1 1.0   0 0 0"; }
std::string follow(int event) { return "event " + std::to_string(event) + " 0.3 0.3 follow 0 -0.6 0 0.3"; }
std::string look(int event) { return "event " + std::to_string(event) + " 0.3 0.3 look 1.9 -1.2 1.0 1"; }

/// The number of events the cluster shot has (the camera script plays no part in simulating it).
int event_count() {
  const ShotResult loaded = load_shot(scene_with_camera({hover(0)}), "cluster");
  REQUIRE(loaded.shot);
  return static_cast<int>(loaded.shot->timeline.events().size());
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Strongly red: the error bars and their outlines, and nothing else the timeline draws without a cue row.
bool is_error_red(const unsigned char* rgb) { return rgb[0] > 120 && rgb[0] > 2.5 * rgb[1] && rgb[0] > 2.5 * rgb[2]; }

struct RedCount {
  long total = 0, right_fifth = 0;
};

RedCount draw_and_count_red(const TimelineData& data, int width, int height) {
  HeadlessCanvas canvas;
  std::string error;
  REQUIRE_MESSAGE(canvas.open(width, height, 14, error), error);
  ImDrawList* list = canvas.begin_2d();
  draw_timeline(*list, data, canvas.fonts(), {0, 0, float(width), float(height)});
  canvas.end_2d();
  RedCount count;
  const std::vector<std::uint8_t>& rgba = canvas.pixels();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      if (!is_error_red(p)) continue;
      ++count.total;
      count.right_fifth += x >= width * 4 / 5;
    }
  return count;
}

}  // namespace

TEST_SUITE("preview camera script check") {
  TEST_CASE("an event the shot lacks leaves the simulated shot without camera or cue") {
    const int count = event_count();
    const ShotResult loaded = load_shot(scene_with_camera({hover(0), follow(count + 2)}), "cluster");
    CHECK_FALSE(loaded.scripted());
    REQUIRE(loaded.shot);
    CHECK(static_cast<int>(loaded.shot->timeline.events().size()) == count);
    CHECK_FALSE(loaded.shot->camera);
    CHECK_FALSE(loaded.shot->cue);
  }

  TEST_CASE("each description sits at the event it names, runs to the next later one, and carries its error") {
    const int count = event_count();
    REQUIRE(count >= 6);
    // In file order: event 0, event count-3, event 2 (listed after a later one), an event past the end.
    const ShotResult loaded =
        load_shot(scene_with_camera({hover(0), follow(count - 3), look(2), hover(count + 3)}), "cluster");
    REQUIRE(loaded.shot);
    const Timeline& timeline = loaded.shot->timeline;
    const auto time_of = [&](int k) { return timeline.events()[static_cast<std::size_t>(k)].time; };
    const std::vector<TimelineCameraSpan> spans =
        written_camera_spans(loaded.shot->scene, timeline, loaded.diagnostics);
    REQUIRE(spans.size() == 4);

    CHECK(spans[0].placed);
    CHECK(spans[0].event == 0);
    CHECK(spans[0].begin == time_of(0));
    CHECK(spans[0].end == time_of(2));
    CHECK(spans[0].problem.empty());
    CHECK(spans[0].label == "hover");

    CHECK(spans[1].placed);
    CHECK(spans[1].begin == time_of(count - 3));
    CHECK(spans[1].end == timeline.duration());
    CHECK(spans[1].problem.empty());
    CHECK(spans[1].label == "follow ball 0");

    CHECK(spans[2].placed);
    CHECK(spans[2].begin == time_of(2));
    CHECK(spans[2].end == time_of(count - 3));
    CHECK(contains(spans[2].problem, "increasing order"));
    CHECK(spans[2].label == "look ball 1");
    CHECK(spans[2].mode == CameraMode::look);

    CHECK_FALSE(spans[3].placed);
    CHECK(spans[3].event == count + 3);
    CHECK(spans[3].problem == "no such event \xE2\x80\x94 the shot has " + std::to_string(count) + " (0 to " +
                                  std::to_string(count - 1) + ")");
  }

  TEST_CASE("event 65535 is the last event") {
    const int count = event_count();
    const ShotResult loaded = load_shot(scene_with_camera({hover(0), follow(9999), look(65535)}), "cluster");
    REQUIRE(loaded.shot);
    const std::vector<TimelineCameraSpan> spans =
        written_camera_spans(loaded.shot->scene, loaded.shot->timeline, loaded.diagnostics);
    REQUIRE(spans.size() == 3);
    CHECK_FALSE(spans[1].placed);
    CHECK(spans[2].placed);
    CHECK(spans[2].begin == loaded.shot->timeline.events()[static_cast<std::size_t>(count - 1)].time);
    CHECK(spans[2].problem.empty());
  }

  TEST_CASE("the picture's contents: real events and drops, the script as written, every error as printed") {
    const int count = event_count();
    const ShotResult loaded = load_shot(scene_with_camera({hover(0), follow(count + 1)}), "cluster");
    REQUIRE(loaded.shot);
    const TimelineData data = unscripted_timeline_data(*loaded.shot, loaded.diagnostics, "cluster.scn");
    CHECK(static_cast<int>(data.events.size()) == count);
    CHECK(data.drops.size() == loaded.shot->timeline.pocket_drops().size());
    CHECK(data.camera.size() == 2);
    CHECK(data.windows.empty());
    CHECK(data.cue.empty());
    REQUIRE(data.script_errors.size() == 1);
    CHECK(data.script_errors[0] == "cluster.scn:8:7: error: event " + std::to_string(count + 1) +
                                       " does not exist: the shot has " + std::to_string(count) + " events (0 to " +
                                       std::to_string(count - 1) + ")");
  }

  TEST_CASE("the faulty descriptions are drawn in red, one naming no event after the time axis") {
    const int count = event_count();
    const ShotResult loaded = load_shot(scene_with_camera({hover(0), follow(count + 1)}), "cluster");
    REQUIRE(loaded.shot);
    TimelineData data = unscripted_timeline_data(*loaded.shot, loaded.diagnostics, "cluster.scn");
    const RedCount failed = draw_and_count_red(data, 1000, 360);
    CHECK(failed.right_fifth > 200);

    // The same picture with the fault taken away has no red at all.
    data.script_errors.clear();
    data.camera.pop_back();
    const RedCount fixed = draw_and_count_red(data, 1000, 360);
    CHECK(fixed.total == 0);
  }

  TEST_CASE("billiards-preview --timeline draws the picture anyway, prints the error and exits 1") {
    const int count = event_count();
    TempDir dir;
    const std::string scene = dir.file("bad.scn", scene_with_camera({hover(0), look(2), follow(count + 2)}));
    const std::string sized = (dir.path / "sized.png").string(), wide = (dir.path / "wide.png").string();
    const auto r = run_command(bin("billiards-preview") + " " + scene + " --timeline --size 1280x720 -o " + sized);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.err, scene + ":9:7: error: event " + std::to_string(count + 2) + " does not exist: the shot has " +
                              std::to_string(count) + " events"));
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(sized.c_str(), &width, &height, &channels, 3);
    REQUIRE_MESSAGE(pixels, "no picture at " << sized);
    CHECK(width == 1280);
    CHECK(height == 720);
    std::set<unsigned> colours;
    long red = 0;
    for (int k = 0; k < width * height; ++k) {
      const unsigned char* p = pixels + 3 * k;
      colours.insert(unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2]);
      red += is_error_red(p);
    }
    stbi_image_free(pixels);
    CHECK(colours.size() > 40);
    CHECK(red > 200);

    // Without --size it is the wide default.
    CHECK(run_command(bin("billiards-preview") + " " + scene + " --timeline -o " + wide).exit_code == 1);
    REQUIRE(stbi_info(wide.c_str(), &width, &height, &channels));
    CHECK(width == 1600);
  }

  TEST_CASE("snapshots and the animatic still refuse a camera script that does not fit, writing nothing") {
    TempDir dir;
    const std::string scene = dir.file("bad.scn", scene_with_camera({hover(0), follow(event_count() + 2)}));
    const std::string frame = (dir.path / "f.png").string(), movie = (dir.path / "m.mp4").string();
    const auto snapshot = run_command(bin("billiards-preview") + " " + scene + " --at 1 --size 160x90 -o " + frame);
    CHECK(snapshot.exit_code == 1);
    CHECK(contains(snapshot.err, scene + ":8:7: error: event "));
    CHECK_FALSE(std::ifstream(frame).good());
    const auto animatic = run_command(bin("billiards-preview") + " " + scene + " --movie " + movie + " --size 160x90");
    CHECK(animatic.exit_code == 1);
    CHECK(contains(animatic.err, scene + ":8:7: error: event "));
    CHECK_FALSE(std::ifstream(movie).good());
  }
}
