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

  TEST_CASE("a scene with a numeric heading comes back unchanged") {
    const std::string text = test::require_file(test::source_path("scenes/cut_corner.scn"));
    CHECK(scene_text_resolved(text, loaded(text)->scene) == text);
  }
}
