// events.json and trajectory.csv: the exact layout of the spec, numbers that read back to the same
// doubles, and the same bytes from the binary as from the library.
#include <doctest/doctest.h>

#include <algorithm>
#include <charconv>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "fixtures.h"
#include "frames.h"
#include "number_format.h"
#include "outputs.h"
#include "random_scenes.h"
#include "shot.h"
#include "strike.h"
#include "support.h"

using namespace bsim;

namespace {

std::unique_ptr<Shot> shot_of(Scene scene) {
  auto shot = std::make_unique<Shot>();
  shot->scene = std::move(scene);
  shot->timeline = simulate(shot->scene);
  return shot;
}

std::string events_json(const Shot& shot) {
  std::ostringstream out;
  write_events_json(shot, out);
  return out.str();
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, sep)) out.push_back(item);
  return out;
}

/// A turn of a hand-made game record.
GameTurn turn_of(int shot, int player, bool written, ShotCall planned, TurnVerdict verdict) {
  GameTurn turn;
  turn.shot = shot;
  turn.player = player;
  turn.written = written;
  turn.planned = planned;
  turn.verdict = std::move(verdict);
  return turn;
}

double parse(const std::string& s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  REQUIRE(ec == std::errc());
  REQUIRE(end == s.data() + s.size());
  return v;
}

}  // namespace

TEST_SUITE("events.json") {
  TEST_CASE("a ball left at rest: the whole file, byte for byte") {
    Scene scene = scenes::standard_table();
    scene.balls.push_back(scenes::ball_at(7, 0.1, -0.2, scene.physics));
    const std::string expected =
        "{\n"
        "  \"duration\": 3,\n"
        "  \"events\": [\n"
        "    {\"index\": 0, \"time\": 0, \"type\": \"start\", \"shot\": 1},\n"
        "    {\"index\": 1, \"time\": 2.5, \"type\": \"cue\", \"shot\": 1, \"balls\": [0], \"speed\": 0, \"heading\": "
        "0},\n"
        "    {\"index\": 2, \"time\": 3, \"type\": \"end\", \"shot\": 1}\n"
        "  ],\n"
        "  \"shots\": [\n"
        "    {\"shot\": 1, \"cue\": 2.5, \"rest\": 2.5}\n"
        "  ],\n"
        "  \"pocketed\": [],\n"
        "  \"final\": [\n"
        "    {\"ball\": 0, \"number\": 7, \"position\": [0.1, -0.2, 0.028575], \"pocketed\": false}\n"
        "  ]\n"
        "}\n";
    CHECK(events_json(*shot_of(scene)) == expected);
  }

  TEST_CASE("a ball meeting a pocket's jaw is a ball-jaw event naming the pocket") {
    Scene scene = scenes::standard_table();
    // Rolled at the top side pocket's jaw point, just inside it: it meets the jaw, not the rail.
    scene.balls.push_back(scenes::ball_at(3, standard_rails()[1].a.x() - 0.002, 0.3, scene.physics, Vec3(0, 1, 0)));
    const std::unique_ptr<Shot> owner = shot_of(scene);
    const std::string json = events_json(*owner);
    bool jaw = false;
    for (const Event& e : owner->timeline.events()) {
      if (e.type != EventType::ball_jaw) continue;
      jaw = true;
      CHECK(json.find("{\"index\": " + std::to_string(e.index) + ", \"time\": " + format_number(e.time) +
                      ", \"type\": \"ball-jaw\", \"shot\": 1, \"balls\": [0], \"pocket\": 1, \"speed\": " +
                      format_number(e.speed) + "}") != std::string::npos);
    }
    CHECK(jaw);
  }

  TEST_CASE("every event type, pocket drops and final states are written with numbers that read back exactly") {
    Scene scene = scenes::standard_table();
    // Ball 0 sends ball 1 straight into the top-right corner pocket, at its mouth's middle; ball 2 runs
    // into the left cushion.
    const Vec3 toward = Vec3(0.2788, 0.1938, 0).normalized();
    scene.balls.push_back(
        scenes::ball_at(0, 0.95 - 0.4 * toward.x(), 0.4 - 0.4 * toward.y(), scene.physics, 2 * toward));
    scene.balls.push_back(scenes::ball_at(5, 0.95, 0.4, scene.physics));
    scene.balls.push_back(scenes::ball_at(12, -0.8, -0.3, scene.physics, Vec3(-1.0, 0, 0)));
    const std::unique_ptr<Shot> owner = shot_of(scene);
    const Shot& shot = *owner;
    const std::string json = events_json(shot);
    bool rail = false, ball_ball = false;
    for (const Event& e : shot.timeline.events()) {
      const std::string head = "{\"index\": " + std::to_string(e.index) + ", \"time\": " + format_number(e.time) +
                               ", \"type\": \"" + std::string(to_string(e.type)) + "\", \"shot\": 1";
      CHECK(json.find(head) != std::string::npos);
      if (e.type == EventType::ball_rail) {
        rail = true;
        CHECK(json.find(head + ", \"balls\": [" + std::to_string(e.balls[0]) + "], \"rail\": " +
                        std::to_string(e.rail) + ", \"speed\": " + format_number(e.speed) + "}") != std::string::npos);
      }
      if (e.type == EventType::ball_ball) {
        ball_ball = true;
        CHECK(json.find(head + ", \"balls\": [0, 1], \"speed\": " + format_number(e.speed) + "}") != std::string::npos);
      }
      CHECK(parse(format_number(e.time)) == e.time);
    }
    CHECK(rail);
    CHECK(ball_ball);
    REQUIRE(shot.timeline.pocket_drops().size() == 1);
    const PocketDrop& drop = shot.timeline.pocket_drops()[0];
    CHECK(json.find("\"pocketed\": [\n    {\"time\": " + format_number(drop.time) +
                    ", \"ball\": 1, \"pocket\": 2}\n  ]") != std::string::npos);
    CHECK(json.find("{\"ball\": 1, \"number\": 5, \"position\": [") != std::string::npos);
    CHECK(json.find("\"pocketed\": true}") != std::string::npos);
    CHECK(json.find("\"duration\": " + format_number(shot.timeline.duration()) + ",") != std::string::npos);
  }

  TEST_CASE("the cue event gives the stick's heading, and with a stroke the stroke and the struck ball's speed") {
    // spec.md "events.json": "heading" on every cue event; "stroke" {speed, side, height, elevation}.
    Scene scene = scenes::standard_table();
    scene.balls.push_back(scenes::ball_at(0, -0.5, 0.1, scene.physics));
    scene.cue().heading_deg = 12.5;
    Stroke stroke;
    stroke.speed = 2;
    stroke.side = 0.1;
    stroke.height = -0.25;
    stroke.elevation_deg = 5;
    scene.cue().stroke = stroke;
    const std::unique_ptr<Shot> shot = shot_of(scene);
    const Event& cue = shot->timeline.events()[1];
    REQUIRE(cue.type == EventType::cue);
    // The struck ball's speed just after the strike, squirt and bed included (strike.h).
    CHECK(cue.speed == doctest::Approx(strike(stroke, 12.5, scene.physics).velocity.norm()).epsilon(1e-15));
    CHECK(cue.speed > 2);
    CHECK(events_json(*shot).find(
              "\"type\": \"cue\", \"shot\": 1, \"balls\": [0], \"speed\": " + format_number(cue.speed) +
              ", \"heading\": 12.5, \"stroke\": {\"speed\": 2, \"side\": 0.1, \"height\": -0.25, "
              "\"elevation\": 5}}") != std::string::npos);
  }

  TEST_CASE("a group collision lists every ball and each contact with its time and speed") {
    // The cue ball strikes the first of three balls in a touching row: one group event.
    Scene scene = scenes::standard_table();
    const double d = 2 * scene.physics.ball_radius;
    scene.balls.push_back(scenes::ball_at(0, -0.4, 0, scene.physics, Vec3(2.0, 0, 0)));
    scene.balls.push_back(scenes::ball_at(1, 0.0, 0, scene.physics));
    scene.balls.push_back(scenes::ball_at(2, d, 0, scene.physics));
    scene.balls.push_back(scenes::ball_at(3, 2 * d, 0, scene.physics));
    const std::unique_ptr<Shot> owner = shot_of(scene);
    const Event& hit = owner->timeline.events()[2];
    REQUIRE(hit.type == EventType::ball_ball);
    CHECK(hit.balls == std::vector<int>{0, 1, 2, 3});
    REQUIRE(hit.contacts.size() >= 3);
    std::string contacts;
    double fastest = 0;
    for (const Contact& c : hit.contacts) {
      contacts += std::string(contacts.empty() ? "" : ", ") + "{\"balls\": [" + std::to_string(c.a) + ", " +
                  std::to_string(c.b) + "], \"time\": " + format_number(c.time) +
                  ", \"speed\": " + format_number(c.speed) + "}";
      CHECK(c.time >= hit.time);
      CHECK(c.time < hit.time + 0.01);
      fastest = std::max(fastest, c.speed);
    }
    CHECK(hit.speed == fastest);
    CHECK(events_json(*owner).find("{\"index\": 2, \"time\": " + format_number(hit.time) +
                                   ", \"type\": \"ball-ball\", \"shot\": 1, \"balls\": [0, 1, 2, 3], \"speed\": " +
                                   format_number(hit.speed) + ", \"contacts\": [" + contacts + "]}") !=
          std::string::npos);
  }

  TEST_CASE("a played game: the whole file with its game object, byte for byte") {
    // spec.md Additions 2026-11-27, events.json `game`: rules, players, winner (null: unfinished, here
    // at the shot limit), one turn per shot; a planned cue event carries `planned`.
    Scene scene = scenes::standard_table();
    scene.balls.push_back(scenes::ball_at(0, 0.1, -0.2, scene.physics));
    const std::unique_ptr<Shot> shot = shot_of(scene);
    GameRecord game;
    game.rules = RackGame::eight_ball;
    game.players = {"Ann \"the hammer\"", "Bo"};
    game.shot_limit = true;
    TurnVerdict v;
    v.break_shot = true;
    v.legal = false;
    v.foul = "the cue ball went into a pocket";
    v.pocketed = {3, 11};
    v.in_hand = InHand::kitchen;
    v.call = "foul: the cue ball went into a pocket; ball in hand behind the head string";
    game.turns.push_back(turn_of(0, 0, false, ShotCall{-1, -1, true, false}, v));
    shot->game = game;
    const std::string expected =
        "{\n"
        "  \"duration\": 3,\n"
        "  \"events\": [\n"
        "    {\"index\": 0, \"time\": 0, \"type\": \"start\", \"shot\": 1},\n"
        "    {\"index\": 1, \"time\": 2.5, \"type\": \"cue\", \"shot\": 1, \"balls\": [0], \"speed\": 0, \"heading\": "
        "0, \"planned\": {\"safety\": true}},\n"
        "    {\"index\": 2, \"time\": 3, \"type\": \"end\", \"shot\": 1}\n"
        "  ],\n"
        "  \"shots\": [\n"
        "    {\"shot\": 1, \"cue\": 2.5, \"rest\": 2.5}\n"
        "  ],\n"
        "  \"pocketed\": [],\n"
        "  \"final\": [\n"
        "    {\"ball\": 0, \"number\": 0, \"position\": [0.1, -0.2, 0.028575], \"pocketed\": false}\n"
        "  ],\n"
        "  \"game\": {\n"
        "    \"rules\": \"8ball\",\n"
        "    \"players\": [\"Ann \\\"the hammer\\\"\", \"Bo\"],\n"
        "    \"winner\": null,\n"
        "    \"shot_limit\": true,\n"
        "    \"turns\": [\n"
        "      {\"shot\": 1, \"player\": 0, \"break\": true, \"legal\": false, \"foul\": \"the cue ball went into a "
        "pocket\", \"pocketed\": [3, 11], \"continues\": false, \"ball_in_hand\": true, \"in_hand\": \"kitchen\", "
        "\"call\": \"foul: the cue ball went into a pocket; ball in hand behind the head string\"}\n"
        "    ]\n"
        "  }\n"
        "}\n";
    CHECK(events_json(*shot) == expected);
  }

  TEST_CASE("a game's turns: planned cue events only, push-outs, the winner; the rest of the file unchanged") {
    const std::string text =
        "ball 0 -0.6 -0.1 0.028575  2.4 0.42 0  1 0 0 0\n"
        "ball 9 0.2 0.05 0.028575  0 0 0  1 0 0 0\n"
        "cue 0 10\n"
        "cue 0 200\n"
        "stroke 1.5 0 0 0\n" +
        std::string(test::fixtures::kHoverCamera);
    ShotResult loaded = load_shot(text, "two");
    REQUIRE(loaded.shot);
    Shot& shot = *loaded.shot;
    REQUIRE(shot.timeline.shots().size() == 2);
    const std::string plain = events_json(shot);
    GameRecord game;
    game.players = {"Player 1", "Player 2"};
    game.winner = 1;
    TurnVerdict first;
    first.pocketed = {9};
    first.continues = true;
    first.call = "";
    TurnVerdict push;
    push.shooter = 0;
    push.push_out = true;
    push.call = "push-out";
    // The first shot a player's plan (the 9 in pocket 2), the second written (no `planned`).
    game.turns = {turn_of(0, 0, false, ShotCall{9, 2, false, false}, first),
                  turn_of(1, 0, true, ShotCall{-1, -1, false, true}, push)};
    shot.game = game;
    const std::string json = events_json(shot);
    // Everything but the game object and the planned call is as without a game.
    const std::string planned = ", \"planned\": {\"ball\": 9, \"pocket\": 2}";
    const std::size_t at = json.find(planned);
    REQUIRE(at != std::string::npos);
    CHECK(json.find("\"planned\"", at + planned.size()) == std::string::npos);
    std::string without = json;
    without.erase(at, planned.size());
    const std::size_t game_at = without.find(",\n  \"game\": {");
    REQUIRE(game_at != std::string::npos);
    CHECK(without.substr(0, game_at) + "\n}\n" == plain);
    CHECK(json.substr(json.find("\"game\"")) ==
          "\"game\": {\n"
          "    \"rules\": \"9ball\",\n"
          "    \"players\": [\"Player 1\", \"Player 2\"],\n"
          "    \"winner\": 1,\n"
          "    \"turns\": [\n"
          "      {\"shot\": 1, \"player\": 0, \"break\": false, \"legal\": true, \"foul\": null, \"pocketed\": [9], "
          "\"continues\": true, \"ball_in_hand\": false, \"call\": \"\"},\n"
          "      {\"shot\": 2, \"player\": 0, \"break\": false, \"legal\": true, \"foul\": null, \"pocketed\": [], "
          "\"continues\": false, \"ball_in_hand\": false, \"push_out\": true, \"call\": \"push-out\"}\n"
          "    ]\n"
          "  }\n"
          "}\n");
    // And it is JSON: the planned call sits on the first shot's cue event.
    const nlohmann::json doc = nlohmann::json::parse(json);
    for (const auto& e : doc["events"]) {
      if (e["type"] != "cue") continue;
      CHECK(e.contains("planned") == (e["shot"] == 1));
    }
    CHECK(doc["game"]["turns"].size() == 2);
  }

  TEST_CASE("trajectory.csv: one row per ball per frame from 0 to the duration, exact states, named motions") {
    const std::unique_ptr<Shot> owner = shot_of(scenes::two_ball_shot());
    const Shot& shot = *owner;
    const int fps = 24;
    std::ostringstream out;
    write_trajectory_csv(shot, fps, out);
    const std::vector<std::string> lines = split(out.str(), '\n');
    REQUIRE(!lines.empty());
    CHECK(lines[0] == "time,ball,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz,state");
    const int frames = frame_count(shot.timeline.duration(), fps);
    CHECK(frames == static_cast<int>(shot.timeline.duration()) * fps);  // t = k/fps below the duration
    REQUIRE(lines.size() == 1 + static_cast<std::size_t>(frames * shot.timeline.ball_count()));
    const std::set<std::string> names = {"stationary", "sliding", "rolling", "spinning", "falling", "pocketed"};
    for (std::size_t row = 1; row < lines.size(); row += 37) {
      const std::vector<std::string> cells = split(lines[row], ',');
      REQUIRE(cells.size() == 16);
      const int frame = static_cast<int>((row - 1) / 2), ball = static_cast<int>((row - 1) % 2);
      CHECK(parse(cells[0]) == frame_time(frame, fps));
      CHECK(cells[1] == std::to_string(ball));
      const BallState s = shot.timeline.state(ball, frame_time(frame, fps));
      CHECK(parse(cells[2]) == s.position.x());
      CHECK(parse(cells[7]) == s.velocity.z());
      CHECK(parse(cells[11]) == s.orientation.w());
      CHECK(names.count(cells[15]) == 1);
      CHECK(cells[15] == to_string(s.motion));
    }
  }

  TEST_CASE("billiards-export --events-only writes the same bytes as the library, twice") {
    test::TempDir dir;
    const std::string text =
        "cue 0 10\n"
        "ball 0 -0.6 -0.1 0.028575  2.4 0.42 0  1 0 0 0\n"
        "ball 9 0.2 0.05 0.028575  0 0 0  1 0 0 0\n" +
        std::string(test::fixtures::kHoverCamera);
    const std::string scene = dir.file("shot.scn", text);
    for (const char* out : {"a", "b"}) {
      const test::CommandResult r = test::run_command(test::bin("billiards-export") + " '" + scene +
                                                      "' --events-only -o '" + (dir.path / out).string() + "'");
      INFO(r.err);
      REQUIRE(r.exit_code == 0);
    }
    const ShotResult loaded = load_shot(text, "shot");
    REQUIRE(loaded.shot);
    CHECK(test::require_file(dir.path / "a" / "events.json") == events_json(*loaded.shot));
    CHECK(test::require_file(dir.path / "a" / "events.json") == test::require_file(dir.path / "b" / "events.json"));
    CHECK(test::require_file(dir.path / "a" / "trajectory.csv") ==
          test::require_file(dir.path / "b" / "trajectory.csv"));
  }
}
