// Camera moments (script/camera_moment.h) on every example scene, the games included: each event
// named and the name resolved gives its very instant, every moment a key can name resolves back to
// it, each shot's stretch agrees with the keys that name its ends, and every description line the
// director writes parses back to the same description.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "camera_key_text.h"
#include "camera_moment.h"
#include "director.h"
#include "files.h"
#include "scene_parse.h"
#include "shot.h"
#include "support.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

struct Loaded {
  std::string name;
  std::string text;  ///< the file's text without its camera block
  std::unique_ptr<Shot> shot;
};

/// `text` without its `camera ... endcamera` block, if it has one.
std::string without_camera(std::string text) {
  const std::size_t begin = text.rfind("\ncamera\n");
  const std::size_t end = text.find("endcamera\n", begin == std::string::npos ? 0 : begin);
  if (begin == std::string::npos || end == std::string::npos) return text;
  return text.erase(begin + 1, end + std::string("endcamera\n").size() - begin - 1);
}

/// Every scene in scenes/ (a whole game in Release builds only) and the three-shot test scene, each
/// loaded (simulated, a game played) once.
const std::vector<Loaded>& example_scenes() {
  static const std::vector<Loaded> scenes = [] {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(test::source_path("scenes")))
      if (entry.path().extension() == ".scn") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    files.push_back(test::source_path("tests/scene/three_shots.scn"));
    std::vector<Loaded> out;
    for (const fs::path& file : files) {
      const std::string text = test::require_file(file);
      if (test::kSanitizedBuild && text.find("\ngame ") != std::string::npos) continue;
      ShotResult r = load_shot(text, file.stem().string());
      REQUIRE_MESSAGE(r.shot, file.string());
      out.push_back({file.filename().string(), without_camera(text), std::move(r.shot)});
    }
    return out;
  }();
  return scenes;
}

/// The description `key` (and event number `event`) starts, as a parsed scene holds it.
CameraShot keyed(const CameraKey& key, int event) {
  CameraShot shot;
  shot.key = key;
  if (key.kind == CameraKeyKind::event) shot.event = event;
  return shot;
}

/// A moment named, written, read back and resolved lands on `time` and `event`.
void check_round_trip(const NamedMoment& m, const Scene& scene, const Timeline& timeline, double time, int event) {
  CAPTURE(m.text());
  int number = -1;
  const std::optional<CameraKey> read = parse_camera_key(m.text(), &number);
  REQUIRE(read);
  CHECK(same_camera_key(*read, m.key));
  if (m.key.kind == CameraKeyKind::event) CHECK(number == m.event);
  const KeyResolution r = resolve_camera_key(keyed(*read, number), scene, timeline);
  REQUIRE_MESSAGE(r.instant, r.problem);
  CHECK(r.instant->time == time);
  CHECK(r.instant->event == event);
  const std::optional<KeyInstant> again = moment_instant(m.key, m.event, timeline);
  REQUIRE(again);
  CHECK(again->time == time);
}

}  // namespace

TEST_SUITE("camera moments") {
  TEST_CASE("every event of every example scene: named, then resolved, gives its instant") {
    for (const Loaded& loaded : example_scenes()) {
      CAPTURE(loaded.name);
      const Timeline& timeline = loaded.shot->timeline;
      REQUIRE(!timeline.events().empty());
      int keyed_events = 0;
      for (const Event& e : timeline.events()) {
        CAPTURE(e.index);
        const std::optional<NamedMoment> m = name_event(timeline, e.index);
        REQUIRE(m);
        CHECK(m->time == e.time);
        CHECK(m->event == e.index);
        if (m->key.kind != CameraKeyKind::event) ++keyed_events;
        check_round_trip(*m, loaded.shot->scene, timeline, e.time, e.index);
        // The window's naming at the event's instant: a key at it, else (a group collision's own
        // instant, between its contacts') `at T` to the millisecond before it.
        const NamedMoment near = name_moment(timeline, e.time, 0);
        CHECK(near.time <= e.time);
        CHECK(e.time - near.time < 1.001e-3);
      }
      // Events are named by what happens, not by their numbers: all but a sixth contact and beyond.
      CHECK(keyed_events * 10 >= static_cast<int>(timeline.events().size()) * 9);
      CHECK(!name_event(timeline, static_cast<int>(timeline.events().size())));
    }
  }

  TEST_CASE("every moment a key can name resolves back to its instant, in every example scene") {
    for (const Loaded& loaded : example_scenes()) {
      CAPTURE(loaded.name);
      const Timeline& timeline = loaded.shot->timeline;
      const std::vector<NamedMoment> moments = nameable_moments(timeline);
      CHECK(moments.size() >= timeline.pocket_drops().size());
      for (const NamedMoment& m : moments) {
        CHECK((m.key.shot >= 0) == (timeline.shot_count() > 1));
        check_round_trip(m, loaded.shot->scene, timeline, m.time, m.event);
      }
      for (const PocketDrop& d : timeline.pocket_drops()) {
        const int shot = timeline.shot_at(d.time);
        const std::optional<NamedMoment> drop = first_drop(timeline, d.ball, shot);
        REQUIRE(drop);
        CHECK(drop->time <= d.time);
        CHECK(timeline.shot_at(drop->time) == shot);
      }
    }
  }

  TEST_CASE("each shot's stretch: its start, strike and end are the moments its keys name") {
    for (const Loaded& loaded : example_scenes()) {
      CAPTURE(loaded.name);
      const Timeline& timeline = loaded.shot->timeline;
      const auto time_of = [&](const CameraKey& key) { return moment_instant(key, -1, timeline).value().time; };
      double previous_end = 0;
      for (int k = 0; k < timeline.shot_count(); ++k) {
        CAPTURE(k);
        const ShotStretch s = shot_stretch(timeline, k);
        CHECK(s.shot == k);
        CHECK(s.start == previous_end);  // the stretches tile the timeline
        CHECK(s.start < s.strike);
        CHECK(s.strike <= s.rest);
        CHECK(s.rest <= s.end);
        CHECK(s.strike == time_of(shot_key(timeline, k, CameraKeyKind::cue)));
        CHECK(s.end == time_of(shot_key(timeline, k, CameraKeyKind::end)));
        if (k > 0) CHECK(s.start == time_of(shot_key(timeline, k, CameraKeyKind::start)));
        for (const Event& e : timeline.events())
          if (e.shot == k && e.index > 0) CHECK(s.holds(e.time));
        previous_end = s.end;
      }
      CHECK(previous_end == timeline.duration());
      const ShotStretch whole = shot_stretch(timeline, -1);
      CHECK(whole.shot == -1);
      CHECK(whole.end == timeline.duration());
      CHECK(whole.last);
    }
  }

  TEST_CASE("the director's lines: each written description parses back to the same description") {
    for (const Loaded& loaded : example_scenes()) {
      CAPTURE(loaded.name);
      const DirectedCamera script = direct_camera(loaded.shot->scene, loaded.shot->timeline);
      const std::string text = camera_script_text(script, loaded.name);
      for (const CameraShot& written : script.shots) {
        const std::string line = camera_description_text(written);
        CAPTURE(line);
        // The script's text holds this very line, and the window writes its mode part the same way.
        CHECK(text.find("\n" + line + "   # ") != std::string::npos);
        CHECK(line.size() > camera_mode_text(written).size());
        CHECK(line.substr(line.size() - camera_mode_text(written).size()) == camera_mode_text(written));
        ParseResult parsed = parse_scene(loaded.text + "camera\n" + line + "\nendcamera\n", "line");
        if (!parsed.scene)
          for (const Diagnostic& d : parsed.diagnostics) MESSAGE(format_diagnostic(d, loaded.name));
        REQUIRE(parsed.scene);
        REQUIRE(parsed.scene->camera.size() == 1);
        const CameraShot& read = parsed.scene->camera[0];
        CHECK(same_camera_key(read.key, written.key));
        if (written.key.kind == CameraKeyKind::event) CHECK(read.event == written.event);
        CHECK(read.pre == written.pre);
        CHECK(read.post == written.post);
        CHECK(read.mode == written.mode);
        CHECK(read.location == written.location);
        if (written.mode == CameraMode::hover) CHECK(read.target == written.target);
        if (written.mode != CameraMode::hover) CHECK(read.ball == written.ball);
        CHECK(camera_description_text(read) == line);
      }
    }
  }

  TEST_CASE("a description line: one number format, set apart as the director writes it") {
    CameraShot s;
    s.key = CameraKey{};
    s.key.kind = CameraKeyKind::hit;
    s.key.a = 0;
    s.key.b = 5;
    s.pre = 0.3;
    s.post = 0;
    s.location = to_millimetre(Vec3(1.2345678, -0.0004, 2.0));
    s.target = Vec3(0.25, 0, 0.03);
    CHECK(camera_description_text(s) == "event hit 0 5 0.3 0 hover 1.235 0 2  0.25 0 0.03");
    s.mode = CameraMode::look;
    s.ball = 5;
    CHECK(camera_mode_text(s) == "look 1.235 0 2  5");
    s.mode = CameraMode::follow;
    s.location = Vec3(-0.7, 0.001, 0.35);
    CHECK(camera_mode_text(s) == "follow 5  -0.7 0.001 0.35");
    s.key.kind = CameraKeyKind::event;
    s.event = CameraShot::kLastEvent;
    CHECK(camera_description_text(s) == "event 65535 0.3 0 follow 5  -0.7 0.001 0.35");
  }
}
