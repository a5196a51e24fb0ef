// Camera keys: descriptions that start at a moment named by what happens (start, cue, end, hit,
// cushion, pocket, at, with ordinals) instead of a global event number.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "camera_moment.h"
#include "files.h"
#include "fixtures.h"
#include "play.h"
#include "scene_parse.h"
#include "script_as_written.h"
#include "shot.h"
#include "shots.h"
#include "support.h"
#include "timeline_picture.h"

using namespace bsim;
namespace fx = bsim::test::fixtures;

namespace {

/// `billiards-export --events-only --fps 30` of `scene` into DIR/out; the named file it wrote.
std::string exported(const test::TempDir& dir, const std::string& scene, const std::string& out, const char* file) {
  const auto to = dir.path / out;
  const test::CommandResult r = test::run_command(test::bin("billiards-export") + " '" + scene +
                                                  "' --events-only --fps 30 -o '" + to.string() + "'");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  return test::require_file(to / file);
}

/// kTwoBalls with a camera of `descriptions` (lines 4 on; the first description on line 5).
std::string two_balls(std::initializer_list<std::string_view> descriptions) {
  return std::string(fx::kTwoBalls) + fx::camera(descriptions);
}

/// The instant `key` (e.g. "second cushion 0") names in the shot of `balls`, or nullopt.
std::optional<double> instant(const std::string& balls, const std::string& key) {
  const std::string text = balls + fx::camera({"event " + key + " 0 0 hover 0 -3 2 0 0 0"});
  const ParseResult parsed = parse_scene(text, "key");
  REQUIRE_MESSAGE(parsed.scene, text);
  const Timeline timeline = simulate(*parsed.scene);
  const KeyResolution r = resolve_camera_key(parsed.scene->camera.at(0), *parsed.scene, timeline);
  if (!r.instant) return std::nullopt;
  return r.instant->time;
}

/// The times of every cushion contact of `ball`, in order.
std::vector<double> cushion_times(const Timeline& timeline, int ball) {
  std::vector<double> out;
  for (const Event& e : timeline.events())
    if (e.type == EventType::ball_rail && e.balls.at(0) == ball) out.push_back(e.time);
  return out;
}

/// The only error loading `text` reports.
Diagnostic only_error(const std::string& text, const ParseOptions& options = {}) {
  const ShotResult result = load_shot(text, "bad", options);
  CHECK_FALSE(result.scripted());
  REQUIRE(result.diagnostics.size() == 1);
  CHECK(result.diagnostics[0].severity == Severity::error);
  return result.diagnostics[0];
}

std::string read_scene(const std::string& name) {
  const std::optional<std::string> text = test::read_file(test::source_path("scenes/" + name));
  REQUIRE(text);
  return *text;
}

/// The break's balls and cue without its camera script.
std::string break_balls() {
  const std::string text = read_scene("break.scn");
  return text.substr(0, text.find("\ncamera\n") + 1);
}

/// tests/scene/three_shots.scn (three aimed shots of the cue ball, 0), without a camera.
std::string three_shots() { return test::require_file(test::source_path("tests/scene/three_shots.scn")); }

/// The line the first description of a camera appended to `text` is on.
int first_description_line(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 2;
}

/// The scene's shots played (each `pot` aimed from where the balls stopped), and the key resolved.
struct PlayedKey {
  Scene scene;
  Timeline timeline;
  KeyResolution r;
};

PlayedKey played_key(const std::string& balls, const std::string& key) {
  const std::string text = balls + fx::camera({"event " + key + " 0 0 hover 0 -3 2 0 0 0"});
  ParseResult parsed = parse_scene(text, "key");
  REQUIRE_MESSAGE(parsed.scene, text);
  PlayedKey out{*parsed.scene, {}, {}};
  PlayResult played = play(out.scene);
  REQUIRE(!played.failure);
  out.timeline = std::move(played.timeline);
  out.r = resolve_camera_key(out.scene.camera.at(0), out.scene, out.timeline);
  return out;
}

/// The instant `key` names once every shot of `balls` is played, or nullopt.
std::optional<double> played_instant(const std::string& balls, const std::string& key) {
  const PlayedKey p = played_key(balls, key);
  if (!p.r.instant) return std::nullopt;
  return p.r.instant->time;
}

}  // namespace

TEST_SUITE("camera_keys") {
  TEST_CASE("the parser reads every key kind and keeps it as written") {
    const ParseResult parsed = parse_scene(
        two_balls({"event start 0 0 hover 0 -3 2 0 0 0", "event cue 0 0 follow 0 -0.6 0 0.3",
                   "event hit 1 0 0.2 0.2 look 0 -2 1 1", "event second  cushion 0 0.2 0.2 follow 0 -0.6 0 0.3",
                   "event last cushion 1 0 0 look 0 -2 1 1", "event drop 1 0 0 look 0 -2 1 1",
                   "event at 4.25 0 0 hover 0 -3 2 0 0 0", "event end 0 0 hover 0 -3 2 0 0 0",
                   "event 3 0 0 hover 0 -3 2 0 0 0"}),
        "keys");
    REQUIRE(parsed.scene);
    const auto& c = parsed.scene->camera;
    REQUIRE(c.size() == 9);
    CHECK(c[0].key.kind == CameraKeyKind::start);
    CHECK(c[1].key.kind == CameraKeyKind::cue);
    CHECK(c[2].key.kind == CameraKeyKind::hit);
    CHECK(c[2].key.a == 1);
    CHECK(c[2].key.b == 0);
    CHECK(camera_key_text(c[2].key) == "hit 1 0");
    CHECK(c[2].pre == 0.2);
    CHECK(c[2].mode == CameraMode::look);
    CHECK(c[3].key.kind == CameraKeyKind::cushion);
    CHECK(c[3].key.ordinal == 2);
    CHECK(camera_key_text(c[3].key) == "second cushion 0");
    CHECK(c[3].event_loc.line == 8);
    CHECK(c[3].event_loc.column == 7);
    CHECK(c[3].key.a_loc.column == 23);
    CHECK(c[4].key.ordinal == CameraKey::kLast);
    CHECK(c[5].key.kind == CameraKeyKind::drop);
    CHECK(c[6].key.kind == CameraKeyKind::at);
    CHECK(c[6].key.seconds == 4.25);
    CHECK(camera_key_text(c[6].key) == "at 4.25");
    CHECK(c[7].key.kind == CameraKeyKind::end);
    CHECK(c[8].key.kind == CameraKeyKind::event);
    CHECK(c[8].event == 3);
    CHECK(camera_key_text(c[8].key, c[8].event) == "3");
  }

  TEST_CASE("start, cue, end and at resolve to the shot's start, cue strike, end and a time") {
    const std::string balls = fx::kTwoBalls;
    const Timeline timeline = simulate(*parse_scene(balls, "t").scene);
    CHECK(instant(balls, "start") == 0.0);
    CHECK(instant(balls, "cue") == timeline.cue_time());
    CHECK(instant(balls, "end") == timeline.duration());
    CHECK(instant(balls, "at 3.75") == 3.75);
    CHECK(instant(balls, "at 0") == 0.0);
  }

  TEST_CASE("hit names the first contact of the two balls, in either order") {
    const std::string balls = fx::kTwoBalls;
    const Timeline timeline = simulate(*parse_scene(balls, "t").scene);
    const Event& hit = timeline.events().at(2);
    REQUIRE(hit.type == EventType::ball_ball);
    CHECK(instant(balls, "hit 0 1") == hit.time);
    CHECK(instant(balls, "hit 1 0") == hit.time);
  }

  TEST_CASE("cushion and its ordinals: the first, second, ... and last cushion contact of a ball") {
    const std::string balls = break_balls();
    const Timeline timeline = simulate(*parse_scene(balls, "break").scene);
    // The ball with the most cushion contacts.
    int ball = 0;
    for (int b = 1; b < timeline.ball_count(); ++b)
      if (cushion_times(timeline, b).size() > cushion_times(timeline, ball).size()) ball = b;
    const std::vector<double> times = cushion_times(timeline, ball);
    REQUIRE(times.size() >= 2);
    const std::string which = " cushion " + std::to_string(ball);
    CHECK(instant(balls, which.substr(1)) == times[0]);
    CHECK(instant(balls, "second" + which) == times[1]);
    CHECK(instant(balls, "last" + which) == times.back());
    const char* ordinals[] = {"second", "third", "fourth", "fifth"};
    for (std::size_t k = 0; k < 4; ++k) {
      const std::optional<double> t = instant(balls, ordinals[k] + which);
      if (k + 1 < times.size())
        CHECK(t == times[k + 1]);
      else
        CHECK_FALSE(t);
    }
  }

  TEST_CASE("in the break, hit finds a contact inside the group collision, pocket the drop") {
    const std::string balls = break_balls();
    const Timeline timeline = simulate(*parse_scene(balls, "break").scene);
    const Event& group = timeline.events().at(2);
    REQUIRE_FALSE(group.contacts.empty());
    // Ball 4 behind the apex ball, the 2: its contact with the apex ball begins inside the group.
    std::optional<double> apex, second_row;
    for (const Contact& c : group.contacts) {
      if (c.a == 0 && c.b == 2 && !apex) apex = c.time;
      if (c.a == 2 && c.b == 4 && !second_row) second_row = c.time;
    }
    REQUIRE(apex);
    REQUIRE(second_row);
    CHECK(instant(balls, "hit 0 2") == *apex);
    CHECK(instant(balls, "hit 4 2") == *second_row);
    CHECK(*second_row > group.time);

    REQUIRE_FALSE(timeline.pocket_drops().empty());
    const PocketDrop& drop = timeline.pocket_drops().front();
    CHECK(instant(balls, "pocket " + std::to_string(drop.ball)) == drop.time);
    CHECK(instant(balls, "cushion 3") == cushion_times(timeline, 3).at(0));
  }

  TEST_CASE("the camera script blends on the keys' instants exactly as on event times") {
    const std::string keyed = two_balls({"event start 0 0 hover 0 -3 2 0 0 0", "event cue 0.5 0.5 follow 0 -0.6 0 0.3",
                                         "event hit 0 1 0.3 0.2 look 0 -2 1 1", "event end 0.4 0 hover 1 1 2 0 0 0"});
    const std::string numbered = two_balls({"event 0 0 0 hover 0 -3 2 0 0 0", "event 1 0.5 0.5 follow 0 -0.6 0 0.3",
                                            "event 2 0.3 0.2 look 0 -2 1 1", "event 65535 0.4 0 hover 1 1 2 0 0 0"});
    const auto a = test::load_clean(keyed), b = test::load_clean(numbered);
    REQUIRE(a->camera);
    REQUIRE(b->camera);
    REQUIRE(a->camera->windows().size() == b->camera->windows().size());
    for (std::size_t k = 0; k < a->camera->windows().size(); ++k) {
      CHECK(a->camera->windows()[k].begin == b->camera->windows()[k].begin);
      CHECK(a->camera->windows()[k].event_time == b->camera->windows()[k].event_time);
      CHECK(a->camera->windows()[k].end == b->camera->windows()[k].end);
    }
    for (double t = 0; t < a->timeline.duration(); t += 0.05) {
      const CameraPose p = a->camera->pose(t), q = b->camera->pose(t);
      CHECK(p.location == q.location);
      CHECK(p.look_at == q.look_at);
    }
  }

  TEST_CASE("an unrelated contact added before a keyed one: the key keeps its moment, a number shifts") {
    const std::string camera = fx::camera(
        {"event 0 0 0 hover 0 -3 2 0 0 0", "event hit 0 1 0 0 look 0 -2 1 1", "event 4 0 0 hover 1 1 2 0 0 0"});
    // Ball 2 far to the left, given a push into the near cushion at the strike: a cushion contact
    // before the cue ball reaches ball 1, and nothing to do with either.
    const std::string before = std::string(fx::kTwoBalls) + camera;
    const std::string after = std::string(fx::kTwoBalls) + "ball 2  -1.0 -0.5 0.028575   0 -0.6 0   1 0 0 0\n" + camera;
    const auto a = test::load_clean(before), b = test::load_clean(after);
    const auto time_of = [](const Shot& shot, int k) { return shot.timeline.events().at(std::size_t(k)).time; };
    REQUIRE(b->timeline.events().at(2).type == EventType::ball_rail);
    REQUIRE(b->timeline.events().at(2).balls.at(0) == 2);
    REQUIRE(time_of(*a, 3) > time_of(*a, 2));
    // The keyed description (window 0) stays on the hit; the numbered one (event 4) moves one event
    // earlier in the shot, to what was event 3.
    CHECK(a->camera->windows().at(0).event_time == time_of(*a, 2));
    CHECK(b->camera->windows().at(0).event_time == a->camera->windows().at(0).event_time);
    CHECK(b->camera->windows().at(0).event_time == time_of(*b, 3));
    CHECK(a->camera->windows().at(1).event_time == time_of(*a, 4));
    CHECK(b->camera->windows().at(1).event_time == time_of(*a, 3));
  }

  TEST_CASE("--strict rejects keys at the key") {
    ParseOptions strict;
    strict.strict = true;
    const ParseResult r = parse_scene(
        two_balls({"event 0 0 0 hover 0 -3 2 0 0 0", "  event hit 0 1 0 0 look 0 -2 1 1"}), "strict", strict);
    CHECK_FALSE(r.scene);
    bool found = false;
    for (const Diagnostic& d : r.diagnostics)
      if (d.message ==
          "the camera key 'hit' is an extension that --strict rejects (the seed names an event by its "
          "number)") {
        found = true;
        CHECK(d.loc.line == 6);
        CHECK(d.loc.column == 9);
      }
    CHECK(found);
    // Without --strict the same text loads.
    CHECK(parse_scene(two_balls({"event 0 0 0 hover 0 -3 2 0 0 0", "  event hit 0 1 0 0 look 0 -2 1 1"}), "t").scene);
  }

  TEST_CASE("a misspelled key: did you mean, at the word") {
    const ParseResult r = parse_scene(two_balls({"event cushon 0 0 0 hover 0 -3 2 0 0 0"}), "t");
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].loc.line == 5);
    CHECK(r.diagnostics[0].loc.column == 7);
    CHECK(r.diagnostics[0].message.find("found 'cushon'; did you mean 'cushion'?") != std::string::npos);
    const ParseResult ordinal = parse_scene(two_balls({"event second hti 0 1 0 0 hover 0 -3 2 0 0 0"}), "t");
    REQUIRE(ordinal.diagnostics.size() == 1);
    CHECK(ordinal.diagnostics[0].message ==
          "expected 'hit', 'cushion' or 'jaw' after 'second', found 'hti'; did you mean 'hit'?");
    const ParseResult jaw = parse_scene(two_balls({"event last jwa 1 0 0 hover 0 -3 2 0 0 0"}), "t");
    REQUIRE(jaw.diagnostics.size() == 1);
    CHECK(jaw.diagnostics[0].message ==
          "expected 'hit', 'cushion' or 'jaw' after 'last', found 'jwa'; did you mean 'jaw'?");
    CHECK(ordinal.diagnostics[0].loc.column == 14);
    // Numbers stay numbers: a fraction is still "an integer for the event number".
    const ParseResult fraction = parse_scene(two_balls({"event 1.5 0 0 hover 0 -3 2 0 0 0"}), "t");
    REQUIRE(fraction.diagnostics.size() == 1);
    CHECK(fraction.diagnostics[0].message == "expected an integer for the event number, found '1.5'");
    const ParseResult same = parse_scene(two_balls({"event hit 1 1 0 0 hover 0 -3 2 0 0 0"}), "t");
    REQUIRE(same.diagnostics.size() == 1);
    CHECK(same.diagnostics[0].message == "expected two different balls for 'hit', found ball 1 twice");
    CHECK(same.diagnostics[0].loc.column == 13);
  }

  TEST_CASE("a key the shot never reaches: an error after simulating, at the key") {
    const auto line = [](const std::string& key) {
      return two_balls({"event 0 0 0 hover 0 -3 2 0 0 0", "event " + key + " 0 0 hover 1 -3 2 0 0 0"});
    };
    Diagnostic d = only_error(line("fifth hit 0 1"));
    CHECK(d.message == "fifth hit 0 1 never happens: balls 0 and 1 touch once");
    CHECK(d.loc.line == 6);
    CHECK(d.loc.column == 7);
    CHECK(format_diagnostic(d, "bad.scn") ==
          "bad.scn:6:7: error: fifth hit 0 1 never happens: balls 0 and 1 touch once");
    d = only_error(line("at 1000"));
    CHECK(d.message.rfind("at 1000 never happens: the shot ends at ", 0) == 0);
    d = only_error(std::string(fx::kTwoBalls) + "ball 2 -1.0 0.5 0.028575 0 0 0 1 0 0 0\n" +
                   fx::camera({"event 0 0 0 hover 0 -3 2 0 0 0", "event cushion 2 0 0 hover 1 -3 2 0 0 0"}));
    CHECK(d.message == "cushion 2 never happens: ball 2 meets no cushion");
    CHECK(d.loc.line == 7);
    d = only_error(line("drop 7"));
    CHECK(d.message == "ball 7 does not exist: the scene has 2 balls (0 to 1)");
    CHECK(d.loc.column == 12);
    d = only_error(line("pocket 7"));  // the older spelling of drop
    CHECK(d.message == "ball 7 does not exist: the scene has 2 balls (0 to 1)");
    CHECK(d.loc.column == 14);
  }

  TEST_CASE("keys whose instants come out of order: one error naming both lines") {
    const Diagnostic d =
        only_error(two_balls({"event 0 0 0 hover 0 -3 2 0 0 0", "event cushion 0 0 0 hover 1 -3 2 0 0 0",
                              "event hit 0 1 0 0 hover 1 -3 2 0 0 0"}));
    CHECK(d.loc.line == 7);
    CHECK(d.loc.column == 7);
    CHECK(d.message.rfind("hit 0 1 on line 7 (at ", 0) == 0);
    CHECK(d.message.find("is listed after cushion 0 on line 6 (at ") != std::string::npos);
    CHECK(d.message.find("list the camera's descriptions in the order they happen") != std::string::npos);
    // A key and a number at the same event: the key is not after it.
    const Diagnostic same =
        only_error(two_balls({"event 1 0 0 hover 0 -3 2 0 0 0", "event cue 0 0 hover 1 -3 2 0 0 0"}));
    CHECK(same.message.find("cue on line 6") == 0);
    CHECK(same.message.find("event 1 on line 5") != std::string::npos);
  }

  TEST_CASE("billiards-export --events-only: camera.csv of a keyed script equals the numbered one's") {
    test::TempDir dir;
    const std::string keyed =
        dir.file("keyed.scn", two_balls({"event start 0 0 hover 0 -3 2 0 0 0", "event cue 0.5 0.5 follow 0 -0.6 0 0.3",
                                         "event hit 0 1 0.3 0.2 look 0 -2 1 1", "event end 0.4 0 hover 1 1 2 0 0 0"}));
    const std::string numbered =
        dir.file("numbered.scn", two_balls({"event 0 0 0 hover 0 -3 2 0 0 0", "event 1 0.5 0.5 follow 0 -0.6 0 0.3",
                                            "event 2 0.3 0.2 look 0 -2 1 1", "event 65535 0.4 0 hover 1 1 2 0 0 0"}));
    const std::string csv[2] = {exported(dir, keyed, "out0", "camera.csv"),
                                exported(dir, numbered, "out1", "camera.csv")};
    CHECK(csv[0].size() > 100);
    CHECK(csv[0] == csv[1]);
    // --strict refuses the keyed scene with the key's location.
    const test::CommandResult strict =
        test::run_command(test::bin("billiards-export") + " '" + keyed + "' --strict --events-only -o '" +
                          (dir.path / "strict").string() + "'");
    CHECK(strict.exit_code != 0);
    CHECK(strict.err.find("keyed.scn:5:7: error: the camera key 'start' is an extension") != std::string::npos);
  }

  TEST_CASE("the timeline picture labels each description by its key as written, with its mode") {
    const auto shot =
        test::load_clean(two_balls({"event start 0 0 hover 0 -3 2 0 0 0", "event hit 0 1 0.3 0.2 look 0 -2 1 1",
                                    "event 3 0 0 follow 1 -0.6 0 0.3", "event at 5.5 0 0 hover 0 -3 2 0 0 0"}));
    const TimelineData data = timeline_data(*shot);
    REQUIRE(data.camera.size() == 4);
    CHECK(data.camera[0].key == "start");
    CHECK(data.camera[1].key == "hit 0 1");
    CHECK(data.camera[1].label == "look ball 1");
    CHECK(data.camera[1].begin == shot->timeline.events().at(2).time);
    CHECK(data.camera[2].key.empty());
    CHECK(data.camera[2].event == 3);
    CHECK(data.camera[3].key == "at 5.5");
    CHECK(data.camera[3].begin == 5.5);

    // A script that does not fit: the unreached key is unplaced and says why.
    const ShotResult failed =
        load_shot(two_balls({"event 0 0 0 hover 0 -3 2 0 0 0", "event pocket 1 0 0 look 0 -2 1 1"}), "failed");
    CHECK_FALSE(failed.scripted());
    REQUIRE(failed.shot);
    const std::vector<TimelineCameraSpan> spans =
        written_camera_spans(failed.shot->scene, failed.shot->timeline, failed.diagnostics);
    REQUIRE(spans.size() == 2);
    CHECK_FALSE(spans[1].placed);
    CHECK(spans[1].key == "drop 1");
    CHECK(spans[1].problem == "drop 1 never happens: ball 1 drops into no pocket");

    test::TempDir dir;
    const std::string scene = dir.file("keys.scn", read_scene("break.scn"));
    const std::string png = (dir.path / "t.png").string();
    const test::CommandResult r =
        test::run_command(test::bin("billiards-preview") + " '" + scene + "' --timeline -o '" + png + "'");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(std::filesystem::file_size(png) > 1000);
  }

  TEST_CASE("shot K keys count within that shot; keys without it over the whole scene") {
    // Oracles: the played timeline's own ShotSpans, events (Event::shot) and pocket drops.
    const std::string balls = three_shots();
    ParseResult parsed = parse_scene(balls, "three_shots");
    REQUIRE(parsed.scene);
    PlayResult played = play(*parsed.scene);
    REQUIRE(!played.failure);
    const Timeline& timeline = played.timeline;
    REQUIRE(timeline.shot_count() == 3);
    const std::vector<ShotSpan>& shots = timeline.shots();
    CHECK(played_instant(balls, "shot 1 start") == 0.0);
    CHECK(played_instant(balls, "shot 2 start") == shots[1].start);
    CHECK(played_instant(balls, "shot 3 start") == shots[2].start);
    CHECK(played_instant(balls, "shot 1 cue") == shots[0].cue);
    CHECK(played_instant(balls, "shot 2 cue") == shots[1].cue);
    CHECK(played_instant(balls, "shot 3 cue") == shots[2].cue);
    CHECK(played_instant(balls, "cue") == shots[0].cue);  // over the scene: the first strike
    CHECK(played_instant(balls, "shot 1 end") == shots[1].start);
    CHECK(played_instant(balls, "shot 2 end") == shots[2].start);
    CHECK(played_instant(balls, "shot 3 end") == timeline.duration());
    CHECK(played_instant(balls, "end") == timeline.duration());
    CHECK(played_instant(balls, "shot 2 at 1") == shots[1].start + 1);
    CHECK(played_instant(balls, "shot 3 at 0.5") == shots[2].start + 0.5);
    CHECK(played_instant(balls, "at 1") == 1.0);
    CHECK_FALSE(played_instant(balls, "shot 1 at 100"));  // beyond the shot's end, the next one's start
    // Each shot pots its ball: `shot K pocket B` is that drop, and no other shot's.
    for (int shot = 1; shot <= 3; ++shot) {
      const int ball = shot;  // shot K pots the ball painted K, index K
      CAPTURE(shot);
      std::optional<double> drop;
      for (const PocketDrop& d : timeline.pocket_drops())
        if (d.ball == ball) drop = d.time;
      REQUIRE(drop);
      CHECK(timeline.shot_at(*drop) == shot - 1);
      const std::string key = "pocket " + std::to_string(ball);
      CHECK(played_instant(balls, "shot " + std::to_string(shot) + " " + key) == *drop);
      CHECK(played_instant(balls, key) == *drop);
      CHECK_FALSE(played_instant(balls, "shot " + std::to_string(shot % 3 + 1) + " " + key));
    }
    // Contacts: the first, second and last of the shot's own, by Event::shot.
    for (int shot = 0; shot < 3; ++shot) {
      CAPTURE(shot);
      std::vector<double> rails, hits;
      for (const Event& e : timeline.events()) {
        if (e.shot != shot) continue;
        if (e.type == EventType::ball_rail && e.balls.at(0) == 0) rails.push_back(e.time);
        if (e.type == EventType::ball_ball && e.balls.size() == 2 && e.balls[0] == 0 && e.balls[1] == shot + 1)
          hits.push_back(e.time);
      }
      const std::string prefix = "shot " + std::to_string(shot + 1) + " ";
      REQUIRE(!hits.empty());
      CHECK(played_instant(balls, prefix + "hit 0 " + std::to_string(shot + 1)) == hits.front());
      CHECK(played_instant(balls, prefix + "hit " + std::to_string(shot + 1) + " 0") == hits.front());
      if (rails.empty()) continue;
      CHECK(played_instant(balls, prefix + "cushion 0") == rails.front());
      CHECK(played_instant(balls, prefix + "last cushion 0") == rails.back());
      if (rails.size() >= 2) CHECK(played_instant(balls, prefix + "second cushion 0") == rails[1]);
    }
    // Without `shot`, cushion 0 counts over the scene: the first shot's first.
    std::vector<double> all_rails;
    for (const Event& e : timeline.events())
      if (e.type == EventType::ball_rail && e.balls.at(0) == 0) all_rails.push_back(e.time);
    REQUIRE(!all_rails.empty());
    CHECK(played_instant(balls, "cushion 0") == all_rails.front());
    CHECK(played_instant(balls, "last cushion 0") == all_rails.back());
  }

  TEST_CASE("shot K keys: located errors, nothing loaded") {
    const std::string balls = three_shots();
    const int line = first_description_line(balls);
    const auto error = [&](const std::string& key, const ParseOptions& options = {}) {
      const ParseResult r =
          parse_scene(balls + fx::camera({"event " + key + " 0 0 hover 0 -3 2 0 0 0"}), "bad", options);
      CHECK_FALSE(r.scene);
      REQUIRE(!r.diagnostics.empty());
      CHECK(r.diagnostics[0].severity == Severity::error);
      return r.diagnostics[0];
    };
    Diagnostic d = error("shot 0 cue");
    CHECK(format_diagnostic(d, "bad.scn") == "bad.scn:" + std::to_string(line) +
                                                 ":12: error: expected a shot from 1 (the first 'cue' line's shot), "
                                                 "found '0'");
    d = error("shot two cue");
    CHECK(d.loc.line == line);
    CHECK(d.loc.column == 12);
    CHECK(d.message ==
          "expected an integer for the shot number after 'shot' (from 1, one shot per 'cue' line), found 'two'");
    d = error("shot 1.5 cue");
    CHECK(d.loc.column == 12);
    d = error("shot 4 cue");
    CHECK(format_diagnostic(d, "bad.scn") ==
          "bad.scn:" + std::to_string(line) +
              ":12: error: expected a shot from 1 to 3 (the scene has 3 shots, one per 'cue' line), found 4");
    d = error("shot 2 shot 1 cue");
    CHECK(d.loc.column == 14);
    CHECK(d.message.rfind("expected a camera key after 'shot 2' (start, cue, ", 0) == 0);
    d = error("shot 2 cuhsion 0");
    CHECK(d.message.find("found 'cuhsion'; did you mean 'cushion'?") != std::string::npos);
    // A scene of one shot has shot 1 only.
    const ParseResult one = parse_scene(two_balls({"event shot 2 cue 0 0 hover 0 -3 2 0 0 0"}), "one");
    CHECK_FALSE(one.scene);
    REQUIRE(one.diagnostics.size() == 1);
    CHECK(one.diagnostics[0].message ==
          "expected a shot from 1 to 1 (the scene has 1 shot, one per 'cue' line), found 2");
    CHECK(one.diagnostics[0].loc.line == 5);
    CHECK(one.diagnostics[0].loc.column == 12);
    // --strict: `shot` is an extension, at the word.
    ParseOptions strict;
    strict.strict = true;
    const ParseResult s = parse_scene(two_balls({"event shot 1 cue 0 0 hover 0 -3 2 0 0 0"}), "strict", strict);
    CHECK_FALSE(s.scene);
    bool found = false;
    for (const Diagnostic& e : s.diagnostics)
      if (e.message ==
          "the camera key 'shot' is an extension that --strict rejects (the seed names an event by its number)") {
        found = true;
        CHECK(e.loc.line == 5);
        CHECK(e.loc.column == 7);
      }
    CHECK(found);
    // A key the shot never reaches says which shot.
    const ShotResult never = load_shot(balls + fx::camera({"event shot 2 pocket 1 0 0 hover 0 -3 2 0 0 0"}), "never");
    CHECK_FALSE(never.scripted());
    REQUIRE(never.diagnostics.size() == 1);
    CHECK(never.diagnostics[0].message == "shot 2 drop 1 never happens: ball 1 drops into no pocket in shot 2");
    CHECK(never.diagnostics[0].loc.line == line);
    CHECK(never.diagnostics[0].loc.column == 7);
  }

  TEST_CASE("a hand-written script over several shots: keys with and without shot, filmed in order") {
    const std::string text =
        three_shots() +
        fx::camera({"event start 0 0 hover 0 -3 2 0 0 0", "event shot 1 hit 0 1 0.3 0.3 look 0 -2 1 1",
                    "event shot 2 start 0 0 hover -1 -2 1.5 0 0 0", "event shot 2 cue 0.2 0.2 follow 0 -0.6 0 0.3",
                    "event shot 3 at 0 0.3 0.3 hover 1 -2 1.5 0 0 0", "event end 0 0 look 0 -2 2 3"});
    const ShotResult r = load_shot(text, "by_hand");
    REQUIRE(r.scripted());
    for (const Diagnostic& d : r.diagnostics) CHECK(d.severity != Severity::error);
    const Shot& shot = *r.shot;
    const std::vector<CameraSegment>& segments = shot.camera->segments();
    REQUIRE(segments.size() == 6);
    CHECK(segments[2].begin == shot.timeline.shots()[1].start);
    CHECK(segments[3].begin == shot.timeline.shots()[1].cue);
    CHECK(segments[4].begin == shot.timeline.shots()[2].start);
    CHECK(segments[5].begin == shot.timeline.duration());
  }

  TEST_CASE("billiards-export: a shot beyond the scene's, an error at the number, nothing written") {
    test::TempDir dir;
    const std::string balls = three_shots();
    const int line = first_description_line(balls);
    const std::string scene = dir.file("three.scn", balls + fx::camera({"event shot 4 cue 0 0 hover 0 -3 2 0 0 0"}));
    const auto out = dir.path / "out";
    const test::CommandResult r =
        test::run_command(test::bin("billiards-export") + " '" + scene + "' --events-only -o '" + out.string() + "'");
    CHECK(r.exit_code != 0);
    CHECK_MESSAGE(r.err.find("three.scn:" + std::to_string(line) +
                             ":12: error: expected a shot from 1 to 3 (the scene has 3 shots, one per 'cue' line), "
                             "found 4") != std::string::npos,
                  r.err);
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

TEST_SUITE("camera_keys: a pocket's jaws") {
  /// The 1 sent by the cue ball into the top-right corner 36 mm off its middle: it rattles in the jaws,
  /// five knocks in 0.7 s, and stays out; the cue ball then nudges it into the right-hand cushion.
  const std::string kRattle =
      "cue 0 45\n"
      "ball 0 0.5176 -0.1683 0.028575 1.7678 1.7678 0 1 0 0 0\n"
      "ball 1 0.9419 0.2560 0.028575 0 0 0 1 0 0 0\n";

  std::vector<double> jaw_times(const Timeline& timeline, int ball) {
    std::vector<double> out;
    for (const Event& e : timeline.events())
      if (e.type == EventType::ball_jaw && e.balls.at(0) == ball) out.push_back(e.time);
    return out;
  }

  TEST_CASE("jaw and its ordinals: a ball's contacts with pockets' jaws; cushion keeps meaning the rails") {
    const Timeline timeline = simulate(*parse_scene(kRattle, "rattle").scene);
    const std::vector<double> jaws = jaw_times(timeline, 1), rails = cushion_times(timeline, 1);
    REQUIRE(jaws.size() == 5);
    REQUIRE(rails.size() == 1);
    REQUIRE(rails[0] > jaws.back());
    CHECK(instant(kRattle, "jaw 1") == jaws[0]);
    CHECK(instant(kRattle, "second jaw 1") == jaws[1]);
    CHECK(instant(kRattle, "fifth jaw 1") == jaws[4]);
    CHECK(instant(kRattle, "last jaw 1") == jaws.back());
    // The rails alone: the first cushion of the 1 is the one after its rattle.
    CHECK(instant(kRattle, "cushion 1") == rails[0]);
    CHECK(instant(kRattle, "last cushion 1") == rails[0]);
    // As written and read back.
    const ParseResult parsed = parse_scene(
        kRattle + fx::camera({"event start 0 0 hover 0 -3 2 0 0 0", "event third  jaw 1 0.2 0 look 0 -2 1 1"}),
        "rattle");
    REQUIRE(parsed.scene);
    const CameraKey& key = parsed.scene->camera.at(1).key;
    CHECK(key.kind == CameraKeyKind::jaw);
    CHECK(key.ordinal == 3);
    CHECK(key.a == 1);
    CHECK(key.a_loc.column == 18);
    CHECK(camera_key_text(key) == "third jaw 1");
    // In the camera script: blends on the third knock as on its event's number.
    const std::string numbered =
        kRattle + fx::camera({"event start 0 0 hover 0 -3 2 0 0 0", "event 5 0.2 0 look 0 -2 1 1"});
    REQUIRE(timeline.events().at(5).time == jaws[2]);
    const ShotResult keyed = load_shot(
        kRattle + fx::camera({"event start 0 0 hover 0 -3 2 0 0 0", "event third jaw 1 0.2 0 look 0 -2 1 1"}), "keyed");
    const ShotResult by_number = load_shot(numbered, "numbered");
    REQUIRE(keyed.scripted());
    REQUIRE(by_number.scripted());
    for (double t = 2.5; t < 4.5; t += 0.05) {
      CAPTURE(t);
      CHECK((keyed.shot->camera->pose(t).location - by_number.shot->camera->pose(t).location).norm() < 1e-12);
    }
  }

  TEST_CASE("a jaw key the shot never reaches: an error after simulating, at the key, as for cushions") {
    const auto line = [](const std::string& balls, const std::string& key) {
      return balls + fx::camera({"event 0 0 0 hover 0 -3 2 0 0 0", "event " + key + " 0 0 hover 1 -3 2 0 0 0"});
    };
    const int lines = static_cast<int>(std::count(kRattle.begin(), kRattle.end(), '\n'));
    Diagnostic d = only_error(line(fx::kTwoBalls, "jaw 0"));
    CHECK(d.message == "jaw 0 never happens: ball 0 meets no pocket's jaw");
    CHECK(format_diagnostic(d, "bad.scn") == "bad.scn:6:7: error: jaw 0 never happens: ball 0 meets no pocket's jaw");
    d = only_error(line(kRattle, "last jaw 0"));
    CHECK(d.message == "last jaw 0 never happens: ball 0 meets no pocket's jaw");
    CHECK(d.loc.line == lines + 3);
    // Slower, the 1 knocks twice and drops.
    const std::string slower =
        "cue 0 45\n"
        "ball 0 0.5176 -0.1683 0.028575 1.2728 1.2728 0 1 0 0 0\n"
        "ball 1 0.9419 0.2560 0.028575 0 0 0 1 0 0 0\n";
    d = only_error(line(slower, "third jaw 1"));
    CHECK(d.message == "third jaw 1 never happens: ball 1 meets a pocket's jaw twice");
    CHECK(d.loc.column == 7);
    d = only_error(line(slower, "jaw 4"));
    CHECK(d.message == "ball 4 does not exist: the scene has 2 balls (0 to 1)");
    CHECK(d.loc.column == 11);
  }

  TEST_CASE("billiards-export: a jaw key films the knock it names; one the shot never reaches is an error at the key") {
    test::TempDir dir;
    const std::string keyed =
        dir.file("keyed.scn",
                 kRattle + fx::camera({"event start 0 0 hover 0 -3 2 0 0 0", "event third jaw 1 0.3 0 look 0 -2 1 1"}));
    const std::string numbered = dir.file(
        "numbered.scn", kRattle + fx::camera({"event start 0 0 hover 0 -3 2 0 0 0", "event 5 0.3 0 look 0 -2 1 1"}));
    const std::string csv[2] = {exported(dir, keyed, "out0", "camera.csv"),
                                exported(dir, numbered, "out1", "camera.csv")};
    CHECK(test::require_file(dir.path / "out0" / "events.json").find("\"type\": \"ball-jaw\"") != std::string::npos);
    CHECK(csv[0].size() > 100);
    CHECK(csv[0] == csv[1]);
    const std::string missing = dir.file(
        "missing.scn", kRattle + fx::camera({"event start 0 0 hover 0 -3 2 0 0 0", "event jaw 0 0.3 0 look 0 -2 1 1"}));
    const auto out = dir.path / "missing";
    const test::CommandResult r =
        test::run_command(test::bin("billiards-export") + " '" + missing + "' --events-only -o '" + out.string() + "'");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("missing.scn:6:7: error: jaw 0 never happens: ball 0 meets no pocket's jaw") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out / "camera.csv"));
  }
}
