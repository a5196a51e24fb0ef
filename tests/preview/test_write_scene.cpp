// --write-scene: a scene aimed by `cue I pot B P` written back in the seed's form (a numeric heading,
// the struck ball's velocity and spin turned to it) plays the same shot, event for event, to the bit.
#include <doctest/doctest.h>

#include <string>

#include "files.h"
#include "number_format.h"
#include "shot.h"
#include "support.h"
#include "write_scene.h"

using namespace bsim;

namespace {

std::unique_ptr<Shot> loaded(const std::string& text) {
  ShotResult r = load_shot(text, "pot_corner");
  for (const Diagnostic& d : r.diagnostics) INFO(format_diagnostic(d, "pot_corner"));
  REQUIRE(r.shot != nullptr);
  return std::move(r.shot);
}

}  // namespace

TEST_SUITE("preview: --write-scene") {
  TEST_CASE("scenes/pot_corner.scn resolved: no 'pot' left, the stroke kept, the same events and drops to the bit") {
    const std::string text = test::require_file(test::source_path("scenes/pot_corner.scn"));
    const auto aimed = loaded(text);
    const std::string resolved = scene_text_resolved(text, aimed->scene);
    CHECK(resolved.find("cue 0 pot") == std::string::npos);
    CHECK(resolved.find("cue 0 " + format_number(aimed->scene.cue().heading_deg) + "\n") != std::string::npos);
    CHECK(resolved.find("stroke 1.5 0.4 0 0\n") != std::string::npos);  // the stroke strikes at the heading
    CHECK(resolved.find("ball 0  -0.9 -0.3 0.028575   0 0 0 ") != std::string::npos);  // no velocity written
    const auto replayed = loaded(resolved);
    CHECK_FALSE(replayed->scene.cue().aims());
    CHECK(replayed->scene.cue().heading_deg == aimed->scene.cue().heading_deg);
    CHECK(replayed->timeline.events() == aimed->timeline.events());
    CHECK(replayed->timeline.pocket_drops() == aimed->timeline.pocket_drops());
  }

  TEST_CASE("a seed-form 'pot' comes back with the heading, the velocity and the spin turned to it") {
    const std::string text =
        "cue 0 pot 1 2\n"
        "ball 0  -0.9 -0.3 0.028575   2.0 0 0   1 0 0 0\n"
        "ball 3  -0.4 -0.1 0.028575   0 0 0     1 0 0 0\n"
        "spin 0  0 0 60\n"
        "camera\nevent 0 0 0 hover  -0.2 -1.5 1.7  0.2 0.1 0\nendcamera\n";
    const auto aimed = loaded(text);
    const std::string resolved = scene_text_resolved(text, aimed->scene);
    CHECK(resolved.find("cue 0 " + format_number(aimed->scene.cue().heading_deg) + "\n") != std::string::npos);
    CHECK(resolved.find("ball 0  -0.9 -0.3 0.028575   2.0 0 0 ") == std::string::npos);  // turned to the heading
    CHECK(resolved.find("spin 0  0 0 60") != std::string::npos);  // side spin about the vertical stays
    const auto replayed = loaded(resolved);
    CHECK(replayed->timeline.events() == aimed->timeline.events());
    CHECK(replayed->timeline.pocket_drops() == aimed->timeline.pocket_drops());
  }

  TEST_CASE("tests/scene/three_shots.scn resolved: each shot's own heading, read back, the same events to the bit") {
    // Three `cue 0 pot B P` lines, each aimed from where the shot before left the balls (play.h): each
    // line gets the heading its own shot was played at, so the text plays the same run of shots.
    const std::string text = test::require_file(test::source_path("tests/scene/three_shots.scn"));
    const auto aimed = loaded(text);
    REQUIRE(aimed->scene.cues.size() == 3);
    const std::string resolved = scene_text_resolved(text, aimed->scene);
    CHECK(resolved.find("pot") == std::string::npos);
    std::size_t from = 0;
    for (const Cue& cue : aimed->scene.cues) {
      const std::string line = "cue 0 " + format_number(cue.heading_deg) + "\n";
      const std::size_t at = resolved.find(line, from);
      CHECK_MESSAGE(at != std::string::npos, line);
      from = at == std::string::npos ? from : at + line.size();
    }
    // Three different headings: the shots are aimed apart, not all at the first one's.
    CHECK(aimed->scene.cues[0].heading_deg != aimed->scene.cues[1].heading_deg);
    CHECK(aimed->scene.cues[1].heading_deg != aimed->scene.cues[2].heading_deg);
    const auto replayed = loaded(resolved);
    REQUIRE(replayed->scene.cues.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK_FALSE(replayed->scene.cues[k].aims());
      CHECK(replayed->scene.cues[k].heading_deg == aimed->scene.cues[k].heading_deg);
    }
    CHECK(replayed->timeline.events() == aimed->timeline.events());
    CHECK(replayed->timeline.pocket_drops() == aimed->timeline.pocket_drops());
    CHECK(replayed->timeline.shots() == aimed->timeline.shots());
  }

  TEST_CASE("a scene with a numeric heading comes back unchanged") {
    const std::string text = test::require_file(test::source_path("scenes/cut_corner.scn"));
    CHECK(scene_text_resolved(text, loaded(text)->scene) == text);
  }
}

TEST_SUITE("preview: --write-scene of a game") {
  TEST_CASE("a played game written as an explicit scene replays to the same events, drops and verdicts") {
    for (const char* text :
         {"game 9ball seed 7 shots 8\nplayer Ann noise 1.5\nplayer Bo\n", "game 8ball seed 2 shots 8\n"}) {
      CAPTURE(text);
      ShotResult played = load_shot(text, "game");
      REQUIRE(played.shot);
      REQUIRE(played.shot->game);
      const std::string written = game_scene_text(text, *played.shot);
      // Every shot written out: a cue line with its heading (no aim left to do), a stroke, its call.
      CHECK(written.find(" pot ") == std::string::npos);
      CHECK(written.find("game ") != std::string::npos);
      ShotResult replayed = load_shot(written, "game");
      for (const Diagnostic& d : replayed.diagnostics) INFO(format_diagnostic(d, "game"));
      REQUIRE(replayed.shot);
      REQUIRE(replayed.shot->game);
      CHECK(replayed.shot->timeline.events() == played.shot->timeline.events());
      CHECK(replayed.shot->timeline.pocket_drops() == played.shot->timeline.pocket_drops());
      const GameRecord& a = *played.shot->game;
      const GameRecord& b = *replayed.shot->game;
      CHECK(b.winner == a.winner);
      REQUIRE(b.turns.size() == a.turns.size());
      for (std::size_t k = 0; k < a.turns.size(); ++k) {
        CAPTURE(k);
        CHECK(b.turns[k].written);
        CHECK(b.turns[k].player == a.turns[k].player);
        CHECK(b.turns[k].verdict.legal == a.turns[k].verdict.legal);
        CHECK(b.turns[k].verdict.call == a.turns[k].verdict.call);
        CHECK(b.turns[k].verdict.pocketed == a.turns[k].verdict.pocketed);
      }
    }
  }
}
