// Several shots: each played from where the one before left the balls, laid end to end into one
// timeline (play.h), with the spec's numbering, spans, put-back and placing.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "files.h"
#include "play.h"
#include "scene_parse.h"
#include "simulate.h"
#include "support.h"

using namespace bsim;

namespace {

Scene parsed(const std::string& text) {
  ParseResult r = parse_scene(text, "t");
  INFO(text);
  for (const Diagnostic& d : r.diagnostics) INFO(format_diagnostic(d, "t"));
  REQUIRE(r.scene.has_value());
  return std::move(*r.scene);
}

std::string three_shots() { return test::require_file(test::source_path("tests/scene/three_shots.scn")); }

/// Two balls on the long axis: the cue ball sends the 1 straight into the right end's side... a
/// straight shot down the table; the second shot strikes the cue ball again from where it stopped.
const std::string kTwoStraight =
    "ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\n"
    "ball 1 0.3 0.2 0.028575 0 0 0 1 0 0 0\n"
    "cue 0 0\nstroke 1.5 0 0 0\n"
    "cue 0 90\nstroke 1.0 0 0 0\n";

}  // namespace

TEST_SUITE("several shots") {
  TEST_CASE("one timeline: one start, one end, events numbered over the scene, each with its shot") {
    Scene scene = parsed(three_shots());
    const PlayResult played = play(scene);
    REQUIRE_FALSE(played.failure);
    const Timeline& t = played.timeline;
    REQUIRE(t.shot_count() == 3);
    const auto& events = t.events();
    int starts = 0, ends = 0, cues = 0, last_shot = 0;
    for (std::size_t i = 0; i < events.size(); ++i) {
      const Event& e = events[i];
      CHECK(e.index == static_cast<int>(i));
      if (i > 0) CHECK(e.time >= events[i - 1].time);
      CHECK(e.shot >= last_shot);  // shots in order
      last_shot = e.shot;
      starts += e.type == EventType::start;
      ends += e.type == EventType::end;
      if (e.type == EventType::cue) {
        CHECK(e.shot == cues);
        CHECK(e.time == t.shots()[static_cast<std::size_t>(cues)].cue);
        ++cues;
      }
    }
    CHECK(starts == 1);
    CHECK(ends == 1);
    CHECK(cues == 3);
    CHECK(events.front().shot == 0);
    CHECK(events.back().shot == 2);
    // Each shot's every ball is at rest at its `rest`, and the next starts there (spec: "A later shot
    // starts when every ball is at rest after the one before"); its strike kCueLeadTime later.
    for (int k = 0; k < 3; ++k) {
      const ShotSpan& span = t.shots()[static_cast<std::size_t>(k)];
      CHECK(span.cue == doctest::Approx(span.start + kCueLeadTime).epsilon(1e-12));
      CHECK(span.rest > span.cue);
      if (k > 0) CHECK(span.start == t.shots()[static_cast<std::size_t>(k - 1)].rest);
      for (int b = 0; b < t.ball_count(); ++b) {
        const BallState s = t.motion_state(b, span.rest);
        CHECK((s.motion == Motion::stationary || s.motion == Motion::pocketed));
        if (k > 0) CHECK(t.motion_state(b, span.cue - 1e-9).velocity.norm() == 0);
      }
      CHECK(t.shot_at(span.cue) == k);
    }
    // The end event: kEndHold after the last rest, on a whole second.
    CHECK(t.duration() == shot_end(t.shots().back().rest));
    // Each shot pots its ball: the 1, the 2, the 3, into the named pockets, within its own span.
    REQUIRE(t.pocket_drops().size() == 3);
    const int pockets[] = {2, 3, 2};
    for (int k = 0; k < 3; ++k) {
      const PocketDrop& d = t.pocket_drops()[static_cast<std::size_t>(k)];
      CHECK(d.ball == k + 1);
      CHECK(d.pocket == pockets[k]);
      CHECK(t.shot_at(d.time) == k);
    }
  }

  TEST_CASE("a later shot is aimed from where the balls stopped, and the heading found is returned") {
    Scene scene = parsed(three_shots());
    const Scene written = scene;
    const PlayResult played = play(scene);
    REQUIRE_FALSE(played.failure);
    CHECK(scene.cues[1].heading_deg == written.cues[1].heading_deg);  // the scene stays as written
    write_found(scene, played.found);
    // Shot 2 played alone from the balls where shot 1 left them, at the heading found, gives the same
    // motion (the chain adds no physics of its own).
    Scene alone = parsed(three_shots());
    alone.cues = {scene.cues[1]};
    alone.cues[0].pot_ball = -1;
    const Timeline& t = played.timeline;
    for (int b = 0; b < t.ball_count(); ++b) {
      const BallState s = t.motion_state(b, t.shots()[1].start);
      alone.balls[static_cast<std::size_t>(b)].position = s.position;
      alone.balls[static_cast<std::size_t>(b)].pocket = s.motion == Motion::pocketed ? 2 : -1;
    }
    const SimulationResult own = simulate_events(alone);
    const double offset = t.shots()[1].start;
    CHECK(own.rest + offset == doctest::Approx(t.shots()[1].rest).epsilon(1e-12));
    const BallState there = t.motion_state(0, t.shots()[1].rest);
    const BallState here = own.segments[0].back().start;
    CHECK((there.position - here.position).norm() < 1e-12);
    // Each pot cue's heading differs from the others (found, not left at 0).
    CHECK(scene.cues[0].heading_deg != 0);
    CHECK(scene.cues[1].heading_deg != scene.cues[0].heading_deg);
    CHECK(scene.cues[2].heading_deg != scene.cues[1].heading_deg);
    // Played again at the headings found (no aiming), the same timeline, bit for bit.
    CHECK(simulate(scene) == t);
  }

  TEST_CASE("a struck ball that went down comes back on the head spot, or behind it when that is taken") {
    // Shot 1 sends the cue ball straight into pocket 2 (top right, centred on the nose corner
    // (1.27, 0.635)) from near it.
    const std::string scratch =
        "ball 0 1.0 0.45 0.028575 0 0 0 1 0 0 0\n"
        "ball 1 -0.3 0.3 0.028575 0 0 0 1 0 0 0\n"
        "ball 2 -0.635 0.0 0.028575 0 0 0 1 0 0 0\n"
        "cue 0 34.4\nstroke 1.0 0 0 0\n"
        "cue 0 0\nstroke 0.5 0 0 0\n";
    Scene scene = parsed(scratch);
    const PlayResult played = play(scene);
    REQUIRE_FALSE(played.failure);
    const Timeline& t = played.timeline;
    REQUIRE(t.pocket_drops().size() == 1);
    CHECK(t.pocket_drops()[0].ball == 0);
    const BallState before = t.motion_state(0, t.shots()[1].start - 1e-6);
    CHECK((before.motion == Motion::falling || before.motion == Motion::pocketed));  // settling until then
    // The head spot (-0.635, 0) holds the 2: the nearest free place behind it on y = 0 is one
    // diameter further toward the head cushion.
    const BallState back = t.motion_state(0, t.shots()[1].start);
    const double d = 2 * scene.physics.ball_radius;
    CHECK(back.motion == Motion::stationary);
    CHECK(back.position.y() == 0);
    CHECK(back.position.x() < -0.635 - d + 1e-3);
    CHECK(back.position.x() > -0.635 - d - 1e-3);
    // With the spot free it goes on the spot itself.
    std::vector<Ball> free = scene.balls;
    free[2].position = Vec3(0.5, 0.5, scene.physics.ball_radius);
    const Vec3 spot = respot_place(scene, free, 0);
    CHECK(spot.x() == kHeadSpotX);
    CHECK(spot.y() == kHeadSpotY);
  }

  TEST_CASE("place lines put balls back before their shot; a place onto a ball is an error at its line") {
    const std::string drill =
        "ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\n"
        "ball 1 0.3 0.0 0.028575 0 0 0 1 0 0 0\n"
        "cue 0 0\nstroke 2.0 0 0 0\n"
        "cue 0 0\nstroke 2.0 0 -0.3 0\nplace 0\nplace 1\n";
    Scene scene = parsed(drill);
    const PlayResult played = play(scene);
    REQUIRE_FALSE(played.failure);
    const Timeline& t = played.timeline;
    for (int b = 0; b < 2; ++b)
      CHECK(
          (t.motion_state(b, t.shots()[1].start).position - scene.balls[static_cast<std::size_t>(b)].position).norm() <
          1e-12);
    // The same stroke but draw: the cue ball ends elsewhere, the 1 the same (a straight hit passes all
    // of the cue ball's speed along the line of centres either way).
    CHECK((t.motion_state(0, t.shots()[0].rest).position - t.motion_state(0, t.shots()[1].rest).position).norm() >
          0.05);

    Scene onto = parsed(
        "ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\nball 1 0.3 0.0 0.028575 0 0 0 1 0 0 0\n"
        "cue 1 90\nstroke 0.3 0 0 0\ncue 0 0\nstroke 1 0 0 0\nplace 1 -0.6 0\n");
    const PlayResult failed = play(onto);
    REQUIRE(failed.failure);
    CHECK(failed.failure->shot == 1);
    CHECK(failed.failure->loc.line == 7);
    CHECK(failed.failure->message.find("shot 2 places ball index 1 (the 1) at (-0.600, 0.000)") != std::string::npos);
  }

  TEST_CASE("a later pot that cannot be played names its shot and where the balls were") {
    // Shot 2 asks for the 1 again after shot 1 potted it; shot 2 of another scene asks for a cut too thin.
    Scene again = parsed(three_shots() + "cue 0 pot 1 0\nstroke 2 0 0 0\n");
    const PlayResult a = play(again);
    REQUIRE(a.failure);
    CHECK(a.failure->shot == 3);
    CHECK(a.failure->loc.line == 13);
    CHECK(a.failure->message.find(
              "shot 4 cannot pot ball index 1 (the 1): it is already down, in the top-right corner (pocket 2)\n") == 0);
    CHECK(a.failure->message.find("\n  after shot 3 the balls stood:\n    ball index 0 (the cue ball) at (") !=
          std::string::npos);
    CHECK(
        a.failure->message.ends_with("\n  down:\n    in the top-right corner (pocket 2): the 1, the 3"
                                     "\n    in the bottom-right corner (pocket 3): the 2"));
    CHECK(a.timeline.shot_count() == 3);  // what was played before it

    Scene thin = parsed(kTwoStraight + "cue 0 pot 1 5\nstroke 1 0 0 0\n");
    const PlayResult b = play(thin);
    REQUIRE(b.failure);
    CHECK(b.failure->loc.line == 7);
    CHECK(b.failure->message.rfind("shot 3: ", 0) == 0);
    CHECK(b.failure->message.find("\n  after shot 2 the balls stood:\n") != std::string::npos);
  }

  TEST_CASE("a later pot that fails on a full table lists the balls that matter to it, a line each") {
    // The break scatters a 9-ball rack; shot 2 then asks for the 9 in the top-left corner, a long way
    // back up the table behind the cue ball. The struck ball and the ball to pot are listed, and those near
    // their paths; the rest are counted, not listed.
    Scene scene = parsed(
        "ball 0 -0.635 0.03 0.028575 0 0 0 1 0 0 0\nrack 9ball seed 2\ncue 0 -1.5\nstroke 8.0 0 -0.15 0\n"
        "cue 0 pot 9 top-left\nstroke 0.2 0 0 0\n");
    const PlayResult r = play(scene);
    REQUIRE(r.failure);
    const std::string& m = r.failure->message;
    INFO(m);
    CHECK(m.rfind("shot 2: no heading pots ball index 9 (the 9) in the top-left corner (pocket 0): ", 0) == 0);
    // Each listed ball on a line of its own, the struck ball and the ball to pot among them.
    int listed = 0;
    for (std::size_t at = m.find("\n    ball index "); at != std::string::npos;
         at = m.find("\n    ball index ", at + 1)) {
      const std::size_t end = m.find('\n', at + 1);
      const std::string line = m.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
      CHECK(line.find(" at (") != std::string::npos);
      CHECK(line.find(", ") == line.rfind(", "));  // one ball: one "(x, y)" pair
      ++listed;
    }
    CHECK(m.find("\n    ball index 0 (the cue ball) at (") != std::string::npos);
    CHECK(m.find("\n    ball index 9 (the 9) at (") != std::string::npos);
    // The others on the bed are counted: listed + counted + down = the ten balls.
    const int down = static_cast<int>(r.timeline.pocket_drops().size());
    const std::size_t others_at = m.find("\n    and ");
    REQUIRE(others_at != std::string::npos);
    const int others = std::stoi(m.substr(others_at + 9));
    CHECK(others > 0);
    CHECK(listed + others + down == 10);
  }

  TEST_CASE("twenty shots: the timeline grows with the events, not with the time") {
    std::string text = "ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\nball 1 0.3 0.1 0.028575 0 0 0 1 0 0 0\n";
    text += "cue 0 pot 1 2\nstroke 1.5 0 0 0\n";
    for (int k = 1; k < 20; ++k) text += "cue 0 pot 1 2\nstroke 1.5 0 0 0\nplace 0\nplace 1\n";
    Scene scene = parsed(text);
    const PlayResult played = play(scene);
    REQUIRE_FALSE(played.failure);
    write_found(scene, played.found);
    const Timeline& t = played.timeline;
    CHECK(t.shot_count() == 20);
    CHECK(t.pocket_drops().size() == 20);
    // Every shot is the same shot: the same heading and the same events, only later.
    for (int k = 1; k < 20; ++k) {
      CHECK(scene.cues[static_cast<std::size_t>(k)].heading_deg == scene.cues[0].heading_deg);
      CHECK(t.shots()[static_cast<std::size_t>(k)].rest - t.shots()[static_cast<std::size_t>(k)].start ==
            doctest::Approx(t.shots()[0].rest).epsilon(1e-9));
    }
    std::size_t segments = 0;
    for (int b = 0; b < t.ball_count(); ++b) segments += t.segments(b).size();
    CHECK(segments < 20 * 20);  // a handful per ball and shot
  }
}
