// Writing a camera description into a scene's text from the window (preview/camera_edit.h): the key
// that names a moment, where the line goes in the camera block, what stays untouched around it, the
// look / follow toggle, the ball under the cursor, and the file replaced with a backup for undo.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "builtin_scene.h"
#include "camera_edit.h"
#include "camera_key_text.h"
#include "camera_moment.h"
#include "director.h"
#include "files.h"
#include "fixtures.h"
#include "labels.h"
#include "shot.h"
#include "support.h"
#include "timeline_picture.h"

using namespace bsim;
using bsim::test::TempDir;

namespace {

const std::string kCluster = test::fixtures::kClusterBalls;
/// One ball fast along the table: cushion after cushion, so its later ones need ordinals.
const std::string kBouncing = "cue 0 0\nball 0 -0.5 0.1 0.028575 4 0.3 0 1 0 0 0\n";

std::unique_ptr<Shot> shot_of(const std::string& text) {
  ShotResult r = load_shot(text, "edit");
  REQUIRE(r.shot);
  return std::move(r.shot);
}

CameraPlacement hover_at(Vec3 eye, Vec3 look_at) {
  CameraPlacement p;
  p.eye = eye;
  p.look_at = look_at;
  return p;
}

/// The time of the first event of `type` (and, for a contact, of `ball`).
double first_time(const Timeline& timeline, EventType type) {
  for (const Event& e : timeline.events())
    if (e.type == type) return e.time;
  FAIL("no such event");
  return 0;
}

/// A time at least `gap` s from every event and pocket drop, if the shot has one.
std::optional<double> quiet_time(const Timeline& timeline, double gap) {
  for (double t = 0; t < timeline.duration(); t += 0.01) {
    bool near = false;
    for (const Event& e : timeline.events()) near = near || std::abs(e.time - t) < gap;
    for (const PocketDrop& d : timeline.pocket_drops()) near = near || std::abs(d.time - t) < gap;
    if (!near) return t;
  }
  return std::nullopt;
}

/// The instants of the scene's descriptions after loading `text` (which must load).
std::vector<double> description_times(const std::string& text) {
  const auto shot = shot_of(text);
  std::vector<double> times;
  for (const CameraShot& c : shot->scene.camera)
    times.push_back(resolve_camera_key(c, shot->scene, shot->timeline).instant->time);
  return times;
}

}  // namespace

TEST_SUITE("camera edit") {
  TEST_CASE("every event and pocket drop is named by a key that resolves back to its instant") {
    for (const std::string& balls : {kCluster, kBouncing}) {
      const auto shot = shot_of(balls + test::fixtures::kHoverCamera);
      const Timeline& timeline = shot->timeline;
      std::vector<double> instants;
      for (const Event& e : timeline.events()) {
        instants.push_back(e.time);
        for (const Contact& c : e.contacts) instants.push_back(c.time);
      }
      for (const PocketDrop& d : timeline.pocket_drops()) instants.push_back(d.time);
      bool ordinal_seen = false;
      for (double t : instants) {
        const NamedMoment m = name_moment(timeline, t, kKeySnap);
        CAPTURE(t);
        CAPTURE(m.text());
        CHECK(m.time == t);
        CHECK(m.text().rfind("at ", 0) != 0);
        ordinal_seen = ordinal_seen || m.text().rfind("second ", 0) == 0 || m.text().rfind("third ", 0) == 0;
        // The key in a scene resolves to the same instant.
        const std::string text = balls + "camera\nevent " + m.text() + " 0 0 hover 0 -3 2 0 0 0\nendcamera\n";
        const std::vector<double> times = description_times(text);
        REQUIRE(times.size() == 1);
        CHECK(times[0] == t);
      }
      CHECK(ordinal_seen == (balls == kBouncing));
      CHECK(name_moment(timeline, 0, kKeySnap).text() == "start");
      CHECK(name_moment(timeline, first_time(timeline, EventType::cue), kKeySnap).text() == "cue");
      CHECK(name_moment(timeline, timeline.duration(), kKeySnap).text() == "end");
    }
    const auto two = shot_of(std::string(test::fixtures::kTwoBalls) + test::fixtures::kHoverCamera);
    CHECK(
        name_moment(two->timeline, first_time(two->timeline, EventType::ball_ball) + 0.8 * kKeySnap, kKeySnap).text() ==
        "hit 0 1");
  }

  TEST_CASE("in a scene of several shots every moment is named within its shot, and resolves back to it") {
    const std::string balls = test::require_file(test::source_path("tests/scene/three_shots.scn"));
    const auto shot = shot_of(balls);
    const Timeline& timeline = shot->timeline;
    REQUIRE(timeline.shot_count() == 3);
    std::vector<double> instants;
    for (const Event& e : timeline.events()) {
      instants.push_back(e.time);
      for (const Contact& c : e.contacts) instants.push_back(c.time);
    }
    for (const PocketDrop& d : timeline.pocket_drops()) instants.push_back(d.time);
    for (const ShotSpan& span : timeline.shots()) instants.push_back(span.start);
    for (double t : instants) {
      const NamedMoment m = name_moment(timeline, t, kKeySnap);
      CAPTURE(t);
      CAPTURE(m.text());
      CHECK(m.time == t);
      CHECK(m.text().rfind("shot " + std::to_string(timeline.shot_at(t) + 1) + " ", 0) == 0);
      CHECK(m.text().find(" at ") == std::string::npos);
      const std::string text = balls + "camera\nevent " + m.text() + " 0 0 hover 0 -3 2 0 0 0\nendcamera\n";
      CHECK(description_times(text) == std::vector<double>{t});
    }
    // The oracles: the timeline's own shot spans.
    CHECK(name_moment(timeline, timeline.shots()[1].cue, kKeySnap).text() == "shot 2 cue");
    CHECK(name_moment(timeline, timeline.shots()[2].start, kKeySnap).text() == "shot 3 start");
    CHECK(name_moment(timeline, timeline.duration(), kKeySnap).text() == "shot 3 end");
    // Between events, `shot K at T` from the start of the shot in play.
    const double t = timeline.shots()[1].start + kKeySnap + 0.3123456;
    REQUIRE(t < timeline.shots()[1].cue - kKeySnap);
    const NamedMoment m = name_moment(timeline, t, kKeySnap);
    CHECK(m.text() == "shot 2 at 0.562");
    CHECK(t - m.time < 1.001e-3);
    const std::string text = balls + "camera\nevent " + m.text() + " 0 0 hover 0 -3 2 0 0 0\nendcamera\n";
    CHECK(description_times(text) == std::vector<double>{m.time});
  }

  TEST_CASE("far from every event the key is `at T`, to the millisecond, within the shot") {
    const auto shot = shot_of(std::string(test::fixtures::kTwoBalls) + test::fixtures::kHoverCamera);
    const std::optional<double> quiet = quiet_time(shot->timeline, kKeySnap + 0.05);
    REQUIRE(quiet);
    const double t = *quiet + 0.0123456;
    const NamedMoment m = name_moment(shot->timeline, t, kKeySnap);
    CHECK(m.text().rfind("at ", 0) == 0);
    CHECK(m.event == -1);
    CHECK(t - m.time < 1.001e-3);
    CHECK(m.time <= t);
    const std::string text =
        std::string(test::fixtures::kTwoBalls) + "camera\nevent " + m.text() + " 0 0 hover 0 -3 2 0 0 0\nendcamera\n";
    CHECK(description_times(text) == std::vector<double>{m.time});
  }

  TEST_CASE("a scene without a camera block gets one at its end") {
    const std::string text = std::string(test::fixtures::kTwoBalls) + "# no camera yet";  // no final newline
    const CameraEdit edit = place_camera(text, "s.scn", 0, hover_at({0, -2.5, 1.5}, {0.1, 0, 0}));
    REQUIRE(edit.error.empty());
    CHECK(edit.text == text + "\ncamera\nevent start 0.3 0 hover 0 -2.5 1.5  0.1 0 0\nendcamera\n");
    CHECK(edit.line == 6);
    CHECK(edit.description == "event start 0.3 0 hover 0 -2.5 1.5  0.1 0 0");
    CHECK_FALSE(edit.replaced);
    CHECK(load_shot(edit.text, "s").scripted());
  }

  TEST_CASE("an empty block, on its own lines or on one line") {
    const std::string balls = test::fixtures::kTwoBalls;
    const CameraPlacement p = hover_at({1, -2, 1.25}, {0, 0, 0});
    const CameraEdit lines = place_camera(balls + "camera\n  endcamera  # the end\n", "s.scn", 0, p);
    REQUIRE(lines.error.empty());
    CHECK(lines.text == balls + "camera\n  event start 0.3 0 hover 1 -2 1.25  0 0 0\n  endcamera  # the end\n");
    CHECK(lines.line == 5);
    const CameraEdit one = place_camera(balls + "camera endcamera\n", "s.scn", 0, p);
    REQUIRE(one.error.empty());
    CHECK(one.text == balls + "camera\nevent start 0.3 0 hover 1 -2 1.25  0 0 0\nendcamera\n");
    CHECK(load_shot(one.text, "s").scripted());
  }

  TEST_CASE("a file with CRLF line ends gets CRLF lines") {
    std::string text = std::string(test::fixtures::kTwoBalls) + "camera\nevent 0 0 0 hover 0 -3 2 0 0 0\nendcamera\n";
    for (std::size_t i = text.find('\n'); i != std::string::npos; i = text.find('\n', i + 2)) text.insert(i, "\r");
    const CameraEdit edit = place_camera(text, "s.scn", 99, hover_at({1, -2, 1}, {0, 0, 0}));
    REQUIRE(edit.error.empty());
    CHECK(edit.text.find("\r\nevent end 0.3 0 hover 1 -2 1  0 0 0\r\nendcamera\r\n") != std::string::npos);
    CHECK(edit.description == "event end 0.3 0 hover 1 -2 1  0 0 0");
    const std::string without = std::string(test::fixtures::kTwoBalls).insert(7, "\r");
    CHECK(place_camera(without, "s.scn", 0, hover_at({1, -2, 1}, {0, 0, 0})).text.find("camera\r\nevent start") !=
          std::string::npos);
  }

  TEST_CASE("a new description goes in time order; comments and odd spacing stay as they were") {
    const std::string head = std::string(test::fixtures::kTwoBalls) + "camera   # my script\n";
    const std::string first = "\tevent  start   0 0   hover 0 -3 2  0 0 0    # wide\n\n# the hit comes later\n";
    const std::string last = "\tevent end 0.5 0 hover 0 -2 3 0 0 0\nendcamera\n";
    const std::string text = head + first + last;
    const auto shot = shot_of(text);
    const double hit = first_time(shot->timeline, EventType::ball_ball);
    const CameraEdit edit = place_camera(text, "s.scn", hit, hover_at({0.5, -1, 0.5}, {0.25, 0, 0.03}));
    REQUIRE(edit.error.empty());
    CHECK(edit.text == head + first + "\tevent hit 0 1 0.3 0 hover 0.5 -1 0.5  0.25 0 0.03\n" + last);
    CHECK(edit.line == 8);
    const std::vector<double> times = description_times(edit.text);
    REQUIRE(times.size() == 3);
    CHECK(times[1] == hit);

    // After every description: before `endcamera`, indented like the last one.
    const std::string two = head + first + "endcamera\n";
    const CameraEdit after = place_camera(two, "s.scn", hit, hover_at({0.5, -1, 0.5}, {0.25, 0, 0.03}));
    CHECK(after.text == head + first + "\tevent hit 0 1 0.3 0 hover 0.5 -1 0.5  0.25 0 0.03\nendcamera\n");
    // Before every description.
    const std::string late = head + last;
    const CameraEdit early = place_camera(late, "s.scn", 0, hover_at({0.5, -1, 0.5}, {0.25, 0, 0.03}));
    CHECK(early.text == head + "\tevent start 0.3 0 hover 0.5 -1 0.5  0.25 0 0.03\n" + last);
  }

  TEST_CASE("a later contact is written with its ordinal") {
    const auto shot = shot_of(kBouncing + test::fixtures::kHoverCamera);
    // A ball's second cushion contact.
    std::map<int, int> seen;
    std::optional<std::pair<int, double>> second;
    for (const Event& e : shot->timeline.events())
      if (e.type == EventType::ball_rail && ++seen[e.balls[0]] == 2 && !second) second = {e.balls[0], e.time};
    REQUIRE(second);
    const std::string text = kBouncing + test::fixtures::kHoverCamera;
    const CameraEdit edit = place_camera(text, "s.scn", second->second, hover_at({1, 1, 1}, {0, 0, 0}));
    REQUIRE(edit.error.empty());
    const NamedMoment m = name_moment(shot->timeline, second->second, kKeySnap);
    CHECK(edit.description.rfind("event " + m.text() + " 0.3 0 hover 1 1 1  0 0 0", 0) == 0);
    CHECK(m.text() == "second cushion " + std::to_string(second->first));
    CHECK(description_times(edit.text).back() == second->second);
  }

  TEST_CASE("at a moment that already has a description, it is replaced, keeping its key, windows and comment") {
    const std::string head = std::string(test::fixtures::kTwoBalls) + "camera\nevent 0 0 0 hover 0 -3 2 0 0 0\n";
    const std::string text = head + "event hit  1 0 0.4 0.2 hover 1 1 1 0 0 0   # the hit\nendcamera\n";
    const auto shot = shot_of(text);
    const double hit = first_time(shot->timeline, EventType::ball_ball);
    const CameraEdit edit = place_camera(text, "s.scn", hit + 0.01, hover_at({0.5, -1, 0.5}, {0, 0, 0}));
    REQUIRE(edit.error.empty());
    CHECK(edit.replaced);
    CHECK(edit.text == head + "event hit  1 0 0.4 0.2 hover 0.5 -1 0.5  0 0 0   # the hit\nendcamera\n");
    CHECK(edit.description == "event hit  1 0 0.4 0.2 hover 0.5 -1 0.5  0 0 0");
    CHECK(edit.line == 6);
  }

  TEST_CASE("the ball key writes a look, then toggles it to a follow from the same place and back") {
    const std::string text = std::string(test::fixtures::kTwoBalls) + test::fixtures::kHoverCamera;
    const auto shot = shot_of(text);
    const double hit = first_time(shot->timeline, EventType::ball_ball);
    CameraPlacement p;
    p.kind = CameraPlacement::Kind::ball;
    p.ball = 1;
    p.eye = Vec3(0.6, -0.9, 0.7);
    const CameraEdit look = place_camera(text, "s.scn", hit, p);
    REQUIRE(look.error.empty());
    CHECK(look.description == "event hit 0 1 0.3 0 look 0.6 -0.9 0.7  1");
    const CameraEdit follow = place_camera(look.text, "s.scn", hit, p);
    REQUIRE(follow.error.empty());
    CHECK(follow.replaced);
    CHECK(follow.description.rfind("event hit 0 1 0.3 0 follow 1  ", 0) == 0);
    // The follow camera stands where the free camera stood, at the moment it was placed (to the mm).
    const auto followed = shot_of(follow.text);
    const CameraPose pose = followed->camera->shot_pose(1, hit);
    CHECK((pose.location - p.eye).norm() < 0.003);
    const CameraEdit back = place_camera(follow.text, "s.scn", hit, p);
    CHECK(back.text == look.text);
    // Another ball: a look at it in place of the follow.
    p.ball = 0;
    CHECK(place_camera(follow.text, "s.scn", hit, p).description == "event hit 0 1 0.3 0 look 0.6 -0.9 0.7  0");
  }

  TEST_CASE("a scene file with errors is not edited") {
    const std::string text = std::string(test::fixtures::kTwoBalls) + "ball 1 2\n";
    const CameraEdit edit = place_camera(text, "bad.scn", 0, hover_at({1, 1, 1}, {0, 0, 0}));
    CHECK(edit.text.empty());
    CHECK(edit.error.find("bad.scn:4:") != std::string::npos);
    // A camera script that does not fit the shot can still be added to.
    const std::string unfit =
        std::string(test::fixtures::kTwoBalls) + "camera\nevent 99 0 0 hover 0 -3 2 0 0 0\nendcamera\n";
    const CameraEdit fixed = place_camera(unfit, "s.scn", 0, hover_at({1, 1, 1}, {0, 0, 0}));
    CHECK(fixed.error.empty());
    CHECK(fixed.line == 6);
  }

  TEST_CASE("the ball under the cursor") {
    const auto shot = shot_of(std::string(test::fixtures::kTwoBalls) + test::fixtures::kHoverCamera);
    const Vec3 ball1 = shot->timeline.state(1, 0).position;
    ViewCamera camera;
    camera.eye = ball1 + Vec3(0, -1, 0.5);
    camera.target = ball1;
    CHECK(ball_at_pixel(shot->timeline, 0, camera, 640, 360, 320, 180) == 1);
    CHECK_FALSE(ball_at_pixel(shot->timeline, 0, camera, 640, 360, 5, 5));
    // Where the renderer's projection draws ball 0, seen from off to the side, is where the pick finds it.
    camera.eye = Vec3(0.4, -1.5, 0.6);
    camera.target = Vec3(0, 0, 0);
    const Eigen::Matrix4f vp = projection_matrix(camera, 640.0 / 360.0) * view_matrix(camera);
    double x = 0, y = 0;
    REQUIRE(project_to_pixels(vp, shot->timeline.state(0, 0).position, 640, 360, x, y));
    CHECK(ball_at_pixel(shot->timeline, 0, camera, 640, 360, x, y) == 0);
    CHECK_FALSE(ball_at_pixel(shot->timeline, 0, camera, 640, 360, x, y - 30));
  }

  TEST_CASE("the file is replaced whole, its permissions kept, the previous version in the backup; undo restores it") {
    TempDir dir;
    const std::string before = std::string(test::fixtures::kTwoBalls) + "# mine\n";
    const std::string path = dir.file("shot.scn", before);
    REQUIRE(::chmod(path.c_str(), 0640) == 0);
    const CameraEdit edit = place_camera(before, path, 0, hover_at({1, -2, 1}, {0, 0, 0}));
    REQUIRE(edit.error.empty());
    REQUIRE(replace_scene_file(path, before, edit.text).empty());
    SceneEdits edits;
    edits.record(before, edit.text);
    CHECK(test::read_file(path) == edit.text);
    CHECK(backup_path(path) == path + ".bak");
    CHECK(test::read_file(path + ".bak") == before);
    struct stat st {};
    REQUIRE(::stat(path.c_str(), &st) == 0);
    CHECK((st.st_mode & 07777) == 0640);
    CHECK(test::leftovers(dir.path).empty());  // no temporary file left beside it

    CHECK(edits.undo(path).empty());
    CHECK(test::read_file(path) == before);
    CHECK(test::read_file(path + ".bak") == edit.text);  // the undone version is not lost
    CHECK_FALSE(edits.undo(path).empty());               // nothing more to undo

    // Edited in an editor after the window wrote it: undo refuses and changes nothing.
    REQUIRE(replace_scene_file(path, before, edit.text).empty());
    edits.record(before, edit.text);
    const std::string mine = edit.text + "# edited by hand\n";
    REQUIRE(test::write_file(path, mine));
    const std::string refused = edits.undo(path);
    CHECK(refused.find("has changed since the window wrote it") != std::string::npos);
    CHECK(test::read_file(path) == mine);
  }

  TEST_CASE("a scene file that is a link: its target is replaced, the link stays") {
    TempDir dir;
    const std::string before = std::string(test::fixtures::kTwoBalls);
    const std::string target = dir.file("real/shot.scn", before);
    const std::filesystem::path link = dir.path / "link.scn";
    std::filesystem::create_symlink(target, link);
    REQUIRE(replace_scene_file(link.string(), before, before + "# more\n").empty());
    CHECK(std::filesystem::is_symlink(link));
    CHECK(test::read_file(target) == before + "# more\n");
    CHECK(test::read_file(target + ".bak") == before);
  }

  TEST_CASE("the timeline names balls with their painted numbers beside the indices, and drops by their keys") {
    CHECK(ball_index_text(11, {0, 1, 2, 3, 4, 8, 6, 7, 9, 10, 11, 12}) == "11 (12)");
    CHECK(ball_index_text(3, {0, 1, 2, 3}) == "3");
    CHECK(ball_index_text(7, {}) == "7");
    const std::vector<int> painted = {0, 1, 9, 12};
    CHECK(camera_key_label("hit 0 3", painted) == "hit 0 3 (12)");
    CHECK(camera_key_label("fourth cushion 2", painted) == "fourth cushion 2 (9)");
    CHECK(camera_key_label("drop 3", painted) == "drop 3 (12)");
    CHECK(camera_key_label("last jaw 3", painted) == "last jaw 3 (12)");
    CHECK(camera_key_label("pocket 3", painted) == "drop 3 (12)");  // the older spelling, written as keys are
    CHECK(camera_key_label("at 3", painted) == "at 3");
    CHECK(camera_key_label("cue", painted) == "cue");
    CHECK(camera_key_label("shot 2 second hit 3 1", painted) == "shot 2 second hit 3 (12) 1");
    CHECK(camera_key_label("7", painted) == "7");

    // The built-in break: its rack gives every ball its painted number as its index.
    ShotResult r = load_shot(builtin_scene_text(), "break");
    REQUIRE(r.shot);
    const TimelineData data = timeline_data(*r.shot);
    // The break is a stroke, and the title says so.
    CHECK(data.title.find(", stroke 8.04 m/s at side +0.00 height +0.00, 0\xC2\xB0 up") != std::string::npos);
    REQUIRE(data.camera.size() == 5);
    CHECK(data.camera[2].label == "follow ball 3");
    CHECK(data.camera[3].label == "look ball 1");
    CHECK(data.camera[4].key == "cushion 0");
    CHECK(camera_key_label(data.camera[2].key, data.painted) == "third cushion 3");
    bool group_named = false;
    for (const TimelineEventMark& e : data.events)
      group_named = group_named || e.label.find(" 15") != std::string::npos;
    CHECK(group_named);
    // Every drop is a moment a camera key names, and its pocket is named in words.
    REQUIRE_FALSE(data.drops.empty());
    for (const TimelineDrop& d : data.drops) {
      CHECK(name_moment(r.shot->timeline, d.time, kKeySnap).text() == "drop " + std::to_string(d.ball));
      CHECK(d.pocket_name == pocket_name(standard_pockets(), d.pocket));
    }
    CHECK(data.drops[0].pocket_name.find(" (pocket " + std::to_string(data.drops[0].pocket) + ")") !=
          std::string::npos);
    CHECK(data.drops[0].pocket_name.rfind("the ", 0) == 0);
  }
}

TEST_SUITE("camera edit: the window writes as the director does") {
  /// The description line of `text` (camera_script_text()'s) that starts with `head`, without its
  /// comment, from its mode word on ("hover 1 2 3  0 0 0").
  std::string director_mode_part(const std::string& text, const std::string& head, const std::string& mode) {
    const std::size_t line = text.find("\n" + head);
    REQUIRE(line != std::string::npos);
    const std::size_t comment = text.find("   # ", line);
    const std::size_t word = text.find(" " + mode + " ", line);
    REQUIRE(word < comment);
    return text.substr(word + 1, comment - word - 1);
  }

  TEST_CASE("a camera the director placed, placed again from the window, is written to the same text") {
    for (const char* file : {"tests/scene/three_shots.scn", "scenes/bank.scn"}) {
      CAPTURE(file);
      std::string text = test::require_file(test::source_path(file));
      if (const std::size_t block = text.find("\ncamera\n"); block != std::string::npos) text.erase(block + 1);
      const auto shot = shot_of(text);
      const DirectedCamera script = direct_camera(shot->scene, shot->timeline);
      const std::string written = camera_script_text(script, "s");
      int compared = 0;
      for (const CameraShot& d : script.shots) {
        if (d.mode == CameraMode::follow) continue;  // the window's follow comes from a look, in the ball's frame
        const double t = resolve_camera_key(d, shot->scene, shot->timeline).instant.value().time;
        CameraPlacement p = hover_at(d.location, d.target);
        if (d.mode == CameraMode::look) {
          p.kind = CameraPlacement::Kind::ball;
          p.ball = d.ball;
        }
        const CameraEdit edit = place_camera(text, "s.scn", t, p);
        REQUIRE(edit.error.empty());
        const std::string mode = d.mode == CameraMode::look ? "look" : "hover";
        const std::string head = "event " + camera_key_text(d.key, d.event) + " ";
        CAPTURE(edit.description);
        // The same camera, in the same words and numbers, as the director's line has it.
        const std::size_t word = edit.description.find(" " + mode + " ");
        REQUIRE(word != std::string::npos);
        CHECK(edit.description.substr(word + 1) == director_mode_part(written, head, mode));
        CHECK(edit.description.rfind("event " + name_moment(shot->timeline, t, kKeySnap).text() + " 0.3 0 ", 0) == 0);
        // And it reads back to that camera.
        const auto placed = shot_of(edit.text);
        REQUIRE(placed->scene.camera.size() == 1);
        const CameraShot& read = placed->scene.camera[0];
        CHECK(read.mode == d.mode);
        CHECK(read.location == d.location);
        if (d.mode == CameraMode::hover) CHECK(read.target == d.target);
        if (d.mode == CameraMode::look) CHECK(read.ball == d.ball);
        ++compared;
      }
      CHECK(compared >= 2);
    }
  }
}

TEST_SUITE("camera edit: a pocket's jaws") {
  /// The 1 rattles in the top-right corner's jaws, five knocks in 0.7 s, and stays out; the cue ball
  /// then nudges it into the right-hand cushion.
  const std::string kRattle =
      "cue 0 45\n"
      "ball 0 0.5176 -0.1683 0.028575 1.7678 1.7678 0 1 0 0 0\n"
      "ball 1 0.9419 0.2560 0.028575 0 0 0 1 0 0 0\n";

  TEST_CASE("each knock on a jaw is named `jaw I` with its ordinal, written so, and resolves back") {
    const auto shot = shot_of(kRattle + test::fixtures::kHoverCamera);
    const char* expected[] = {"jaw 1", "second jaw 1", "third jaw 1", "fourth jaw 1", "fifth jaw 1"};
    std::size_t k = 0;
    for (const Event& e : shot->timeline.events()) {
      if (e.type != EventType::ball_jaw) continue;
      REQUIRE(k < 5);
      const NamedMoment m = name_moment(shot->timeline, e.time, kKeySnap);
      CAPTURE(e.time);
      CHECK(m.text() == expected[k]);
      CHECK(m.time == e.time);
      CHECK(m.event == e.index);
      ++k;
    }
    CHECK(k == 5);
    // Pausing on the third knock and placing a camera writes that key; the file reads back to that moment.
    double third = 0;
    for (const Event& e : shot->timeline.events())
      if (e.type == EventType::ball_jaw && name_moment(shot->timeline, e.time, kKeySnap).text() == "third jaw 1")
        third = e.time;
    const std::string text = kRattle + test::fixtures::kHoverCamera;
    const CameraEdit edit = place_camera(text, "rattle.scn", third + 0.01, hover_at({1, 1, 1}, {1.2, 0.6, 0}));
    REQUIRE(edit.error.empty());
    CHECK(edit.description.rfind("event third jaw 1 0.3 0 hover 1 1 1  1.2 0.6 0", 0) == 0);
    CHECK(description_times(edit.text).back() == third);
    // The rails keep `cushion`: the 1's one cushion contact, after the rattle.
    for (const Event& e : shot->timeline.events())
      if (e.type == EventType::ball_rail && e.balls[0] == 1)
        CHECK(name_moment(shot->timeline, e.time, kKeySnap).text() == "cushion 1");
  }
}
