// The interactive window: under Xvfb it opens, scrubs through the shot by itself, quits and leaves
// a screenshot that is a real picture; and its hot reload keeps the last good shot and the time
// when the file on disk turns bad, reporting the error's line and column.
#include <doctest/doctest.h>

#include <cstdio>
#include <set>
#include <string>

#include <stb_image.h>

#include "camera_edit.h"
#include "files.h"
#include "fixtures.h"
#include "shot.h"
#include "support.h"
#include "view.h"
#include "viewer_state.h"
#include "viewer_ui.h"

using namespace bsim;
using bsim::test::bin;
using bsim::test::run_command;
using bsim::test::TempDir;

namespace {

// Two balls, a hover and a follow camera; the follow description is on line 6.
const std::string kScene = test::fixtures::two_ball_scene();

}  // namespace

TEST_SUITE("preview window") {
  TEST_CASE("under Xvfb the window opens, scrubs, quits by itself and saves a screenshot") {
    test::require_program("xvfb-run");
    test::require_program("xauth");
    TempDir dir;
    const std::string scene = dir.file("tour.scn", kScene);
    const std::string shot = (dir.path / "window.png").string();
    const auto r = run_command("xvfb-run -a -s '-screen 0 1024x768x24' " + bin("billiards-preview") + " " + scene +
                               " --size 640x360 --overlay events --quit-after 1.5 --screenshot " + shot);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(shot.c_str(), &width, &height, &channels, 3);
    REQUIRE(pixels);
    CHECK(width == 640);
    CHECK(height == 360 + kControlsHeight);
    std::set<unsigned> colours;
    long long cloth = 0;
    for (int i = 0; i < width * height; ++i) {
      const unsigned char* p = pixels + 3 * i;
      colours.insert(unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2]);
      cloth += p[1] > p[0] + 30 && p[1] > p[2] + 20;  // green: the table is in view
    }
    stbi_image_free(pixels);
    CHECK(colours.size() > 500);
    CHECK(cloth > width * height / 20);
  }

  TEST_CASE("under Xvfb, keys write the free camera into the scene file, toggle a look at a ball, and undo") {
    test::require_program("xvfb-run");
    test::require_program("xauth");
    TempDir dir;
    const std::string original = kScene + "# my notes stay\n";
    const std::string path = dir.file("keyed.scn", original);
    // Where the window will be: event 2 (the cue ball meets ball 1), seen from the free camera as it opens.
    ViewerState state;
    state.source = scene_source(path, false);
    REQUIRE(load_into(state));
    const Timeline& timeline = state.shot->timeline;
    REQUIRE(timeline.events().size() > 2);
    REQUIRE(timeline.events()[2].type == EventType::ball_ball);
    const double hit = timeline.events()[2].time;
    const ViewCamera free = OrbitCamera{}.view();
    CameraPlacement hover;
    hover.eye = free.eye;
    hover.look_at = free.target;
    const CameraEdit keyed = place_camera(original, path, hit, hover);
    REQUIRE(keyed.error.empty());
    REQUIRE(keyed.description.rfind("event hit 0 1 0.3 0 hover ", 0) == 0);
    CameraPlacement look = hover;
    look.kind = CameraPlacement::Kind::ball;
    look.ball = 1;
    const CameraEdit looked = place_camera(keyed.text, path, hit, look);
    REQUIRE(looked.error.empty());
    // The pixel of ball 1 at that moment in the window's picture (640x360 at the top left).
    const ViewRect view = view_rect(640, 360 + kControlsHeight, 640, 360);
    const Eigen::Matrix4f vp = projection_matrix(free, view.width / view.height) * view_matrix(free);
    double x = 0, y = 0;
    REQUIRE(project_to_pixels(vp, timeline.state(1, hit).position, view.width, view.height, x, y));
    REQUIRE(ball_at_pixel(timeline, hit, free, view.width, view.height, x, y) == 1);

    auto run = [&](const std::string& keys) {
      return run_command("BSIM_WINDOW_INPUT=" + test::quoted(keys) + " xvfb-run -a -s '-screen 0 1024x768x24' " +
                         bin("billiards-preview") + " " + path + " --size 640x360");
    };
    // C: the free camera; . .: on to event 2; K: a hover there; L over ball 1: a look at it instead.
    char mouse[64];
    std::snprintf(mouse, sizeof mouse, "mouse:%.1f,%.1f", view.x + x, view.y + y);
    const auto placed = run(std::string("C . . K ") + mouse + " L");
    INFO(placed.err);
    REQUIRE(placed.exit_code == 0);
    CHECK(test::read_file(path) == looked.text);
    CHECK(test::read_file(path + ".bak") == keyed.text);
    CHECK(placed.err.find("wrote line " + std::to_string(keyed.line)) != std::string::npos);
    CHECK(placed.err.find("replaced line " + std::to_string(looked.line) + ": " + looked.description) !=
          std::string::npos);

    // In a new window: K writes, U puts the file back byte for byte (the undone version in the backup).
    REQUIRE(test::write_file(path, original));
    const auto undone = run("C . . K U");
    INFO(undone.err);
    REQUIRE(undone.exit_code == 0);
    CHECK(test::read_file(path) == original);
    CHECK(test::read_file(path + ".bak") == keyed.text);
    CHECK(undone.err.find("undone") != std::string::npos);
  }

  TEST_CASE("a camera key edits the file as it is on disk now, and the reloaded shot shows the new camera") {
    TempDir dir;
    const std::string path = dir.file("live.scn", kScene);
    ViewerState state;
    state.source = scene_source(path, false);
    REQUIRE(load_into(state));
    const double hit = state.shot->timeline.events().at(2).time;
    state.set_time(hit);
    CameraPlacement hover;
    hover.eye = Vec3(0.5, -1.5, 0.8);
    hover.look_at = Vec3(0.25, 0, 0);

    // Not with the scripted camera: nothing is written.
    CHECK_FALSE(write_camera_key(state, hover));
    CHECK(state.notice_is_error);
    CHECK(test::read_file(path) == kScene);

    // An editor saved a change since the last load: the key keeps it.
    const std::string edited = "# saved in an editor\n" + kScene;
    REQUIRE(test::write_file(path, edited));
    state.free_camera = true;
    REQUIRE(write_camera_key(state, hover));
    CHECK_FALSE(state.notice_is_error);
    const std::string written = *test::read_file(path);
    CHECK(written.rfind(edited.substr(0, edited.find("camera\n")), 0) == 0);
    CHECK(written.find("event hit 0 1 0.3 0 hover 0.5 -1.5 0.8  0.25 0 0\n") != std::string::npos);
    CHECK(test::read_file(path + ".bak") == edited);
    REQUIRE(load_into(state));
    const CameraPose pose = state.shot->camera->pose(hit);
    CHECK((pose.location - hover.eye).norm() < 1e-9);
    CHECK((pose.look_at - hover.look_at).norm() < 1e-9);

    // A file saved with an error is left alone, and says why.
    REQUIRE(test::write_file(path, edited + "ball 1\n"));
    CHECK_FALSE(write_camera_key(state, hover));
    CHECK(state.notice_is_error);
    CHECK(state.notice.find(path + ":") != std::string::npos);
    CHECK(test::read_file(path) == edited + "ball 1\n");

    // Undo: refused while the file is not what the window wrote; once it is again, it goes back.
    CHECK_FALSE(undo_camera_key(state));
    REQUIRE(test::write_file(path, written));
    CHECK(undo_camera_key(state));
    CHECK(test::read_file(path) == edited);
  }

  TEST_CASE("hot reload: a bad edit keeps the shot and the time and reports line and column; a fix reloads") {
    TempDir dir;
    const std::string path = dir.file("live.scn", kScene);
    ViewerState state;
    state.source = scene_source(path, false);
    FileWatch watch(path);
    CHECK_FALSE(watch.changed());
    REQUIRE(load_into(state));
    REQUIRE(state.shot);
    state.set_time(3.0);
    const Shot* first = state.shot.get();

    std::string broken = kScene;
    broken.replace(broken.find("follow 0"), 8, "follow 17");  // no ball 17
    REQUIRE(test::write_file(path, broken));
    CHECK(watch.changed());
    CHECK_FALSE(load_into(state));
    CHECK(state.load_failed);
    CHECK(state.shot.get() == first);
    CHECK(state.time == 3.0);
    REQUIRE_FALSE(state.messages.empty());
    CHECK(state.messages.front().find(path + ":6:") == 0);

    REQUIRE(test::write_file(path, kScene + "# edited\n"));
    CHECK(watch.changed());
    CHECK(load_into(state));
    CHECK_FALSE(state.load_failed);
    CHECK(state.shot.get() != first);
    CHECK(state.time == 3.0);
  }

  TEST_CASE("shot stepping lands on each shot's strike, and the shot in play follows the time") {
    // tests/scene/three_shots.scn: `]` and `[` step over Timeline::shots()[k].cue, as --at shot:K shows it.
    ViewerState state;
    state.source = scene_source(test::source_path("tests/scene/three_shots.scn").string(), false);
    REQUIRE(load_into(state));
    const std::vector<ShotSpan>& spans = state.shot->timeline.shots();
    REQUIRE(spans.size() == 3);
    CHECK(state.shot_count() == 3);
    state.set_time(0);
    CHECK(state.shot_in_play() == 0);
    state.step_shot(1);
    CHECK(state.time == spans[0].cue);
    state.step_shot(1);
    CHECK(state.time == spans[1].cue);
    CHECK(state.shot_in_play() == 1);
    state.step_shot(1);
    CHECK(state.time == spans[2].cue);
    state.step_shot(1);  // no shot after the last: stays
    CHECK(state.time == spans[2].cue);
    state.set_time((spans[1].cue + spans[1].rest) / 2);  // in the middle of shot 2: back to its strike
    state.step_shot(-1);
    CHECK(state.time == spans[1].cue);
    state.step_shot(-1);
    CHECK(state.time == spans[0].cue);
    CHECK(state.shot_in_play() == 0);
  }

  TEST_CASE("under Xvfb, ] and [ step the window shot by shot") {
    // `]` twice lands on shot 2's strike and K writes the free camera there; the key written names that
    // instant, so the file shows where the keys took the window.
    test::require_program("xvfb-run");
    test::require_program("xauth");
    TempDir dir;
    const std::string path =
        dir.file("three.scn", test::require_file(test::source_path("tests/scene/three_shots.scn")));
    ViewerState state;
    state.source = scene_source(path, false);
    REQUIRE(load_into(state));
    const double strike2 = state.shot->timeline.shots()[1].cue;
    const auto r =
        run_command("BSIM_WINDOW_INPUT=" + test::quoted("C ] ] ] [ K") + " xvfb-run -a -s '-screen 0 1024x768x24' " +
                    bin("billiards-preview") + " " + path + " --size 640x360");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CameraPlacement hover;
    const ViewCamera free = OrbitCamera{}.view();
    hover.eye = free.eye;
    hover.look_at = free.target;
    const CameraEdit expected =
        place_camera(test::require_file(test::source_path("tests/scene/three_shots.scn")), path, strike2, hover);
    REQUIRE(expected.error.empty());
    CHECK(test::read_file(path) == expected.text);
  }

  TEST_CASE("frame and event stepping land on frames and events") {
    ViewerState state;
    state.source = scene_source(std::nullopt, false);
    REQUIRE(load_into(state));
    state.fps = 30;
    state.set_time(0);
    state.step_frames(3);
    CHECK(state.time == doctest::Approx(0.1));
    state.step_event(1);
    const auto& events = state.shot->timeline.events();
    REQUIRE(events.size() >= 2);
    CHECK(state.time == events[1].time);
    state.step_event(-1);
    CHECK(state.time == events[0].time);
    state.set_time(1e9);
    CHECK(state.time == state.duration());
  }
}
