// The loaded shot: its scripts point into it, so it must stay where load_shot built it.
#include <doctest/doctest.h>

#include <type_traits>

#include "builtin_scene.h"
#include "shot.h"

using namespace bsim;

// A copy or a move would leave the copy's camera and cue scripts reading the original's scene and
// timeline, freed with it: neither compiles.
static_assert(!std::is_copy_constructible_v<Shot>);
static_assert(!std::is_copy_assignable_v<Shot>);
static_assert(!std::is_move_constructible_v<Shot>);
static_assert(!std::is_move_assignable_v<Shot>);

TEST_CASE("a loaded shot has its scripts, an unscripted one has none") {
  const ShotResult loaded = load_shot(builtin_scene_text(), "break");
  REQUIRE(loaded.shot);
  CHECK(loaded.shot->camera.has_value());
  CHECK(loaded.shot->cue.has_value());
  CHECK(loaded.scripted() == loaded.shot.get());

  // Event 99 does not exist in a short shot: the scene and timeline come back without scripts.
  const ShotResult wrong = load_shot(
      "ball 0 0 0 0.028575 1 0 0 1 0 0 0 cue 0 0 camera event 0 0 0 hover 0 0 3 0 0 0 "
      "event 99 0.1 0.1 hover 1 0 3 0 0 0 endcamera",
      "wrong");
  CHECK_FALSE(wrong.scripted());
  REQUIRE(wrong.shot);
  CHECK_FALSE(wrong.shot->camera.has_value());
  CHECK_FALSE(wrong.shot->cue.has_value());
  CHECK(wrong.shot->timeline.events().size() >= 3);
}
