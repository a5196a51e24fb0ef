// Camera keys as text: camera_key_text() writes what parse_camera_key() and the scene parser read
// back to the same key, for every kind.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "camera_key_text.h"
#include "files.h"
#include "fixtures.h"
#include "scene_parse.h"
#include "support.h"

using namespace bsim;
namespace fx = bsim::test::fixtures;

namespace {

CameraKey key_of(CameraKeyKind kind, int a = -1, int b = -1, int ordinal = 1, double seconds = 0) {
  CameraKey key;
  key.kind = kind;
  key.a = a;
  key.b = b;
  key.ordinal = ordinal;
  key.seconds = seconds;
  return key;
}

/// Keys of every kind, with every ordinal where the kind takes one.
std::vector<CameraKey> every_key() {
  std::vector<CameraKey> keys = {key_of(CameraKeyKind::start),
                                 key_of(CameraKeyKind::cue),
                                 key_of(CameraKeyKind::end),
                                 key_of(CameraKeyKind::drop, 1),
                                 key_of(CameraKeyKind::at, -1, -1, 1, 0.0),
                                 key_of(CameraKeyKind::at, -1, -1, 1, 1.25),
                                 key_of(CameraKeyKind::at, -1, -1, 1, 0.1 + 0.2)};
  for (int ordinal : {1, 2, 3, 4, 5, CameraKey::kLast}) {
    keys.push_back(key_of(CameraKeyKind::hit, 1, 0, ordinal));
    keys.push_back(key_of(CameraKeyKind::cushion, 0, -1, ordinal));
    keys.push_back(key_of(CameraKeyKind::jaw, 1, -1, ordinal));
  }
  return keys;
}

}  // namespace

TEST_SUITE("camera key text") {
  TEST_CASE("format then parse gives the same key, for every kind") {
    for (const CameraKey& key : every_key()) {
      const std::string text = camera_key_text(key);
      CAPTURE(text);
      const std::optional<CameraKey> back = parse_camera_key(text);
      REQUIRE(back);
      CHECK(same_camera_key(*back, key));
      CHECK(camera_key_text(*back) == text);
    }
    // An event number: kind event, the number beside it.
    for (int event : {0, 7, CameraShot::kLastEvent}) {
      const std::string text = camera_key_text(CameraKey{}, event);
      int back_event = -1;
      const std::optional<CameraKey> back = parse_camera_key(text, &back_event);
      REQUIRE(back);
      CHECK(back->kind == CameraKeyKind::event);
      CHECK(back_event == event);
    }
  }

  TEST_CASE("the scene parser reads every formatted key back to the same key") {
    for (const CameraKey& key : every_key()) {
      const std::string text = camera_key_text(key);
      CAPTURE(text);
      const std::string scene =
          std::string(fx::kTwoBalls) + "camera\n  event " + text + " 0.3 0 hover 0 -2 1.5 0 0 0\nendcamera\n";
      const ParseResult parsed = parse_scene(scene, "key");
      REQUIRE(parsed.scene);
      REQUIRE(parsed.scene->camera.size() == 1);
      CHECK(same_camera_key(parsed.scene->camera[0].key, key));
    }
  }

  TEST_CASE("the names: kinds, ordinals and what follows each") {
    CHECK(camera_key_text(key_of(CameraKeyKind::hit, 3, 8, 2)) == "second hit 3 8");
    CHECK(camera_key_text(key_of(CameraKeyKind::cushion, 3, -1, CameraKey::kLast)) == "last cushion 3");
    CHECK(camera_key_text(key_of(CameraKeyKind::drop, 5)) == "drop 5");
    // A pocket's jaw, not a rail: a kind of its own beside `cushion`, with the same ordinals.
    CHECK(camera_key_text(key_of(CameraKeyKind::jaw, 2)) == "jaw 2");
    CHECK(camera_key_text(key_of(CameraKeyKind::jaw, 2, -1, 3)) == "third jaw 2");
    CHECK(camera_key_kind("jaw") == CameraKeyKind::jaw);
    CHECK(camera_key_ordinal_kinds() == std::vector<std::string_view>{"hit", "cushion", "jaw"});
    CHECK(camera_key_list().find("before hit, cushion or jaw,") != std::string::npos);
    // `pocket I`, the older spelling of `drop I` (I a ball, not a pocket), is read as it, and written as it.
    CHECK(camera_key_kind("drop") == CameraKeyKind::drop);
    CHECK(camera_key_kind("pocket") == CameraKeyKind::drop);
    const std::optional<CameraKey> older = parse_camera_key("shot 2 pocket 5");
    REQUIRE(older);
    CHECK(same_camera_key(*older, parse_camera_key("shot 2 drop 5").value()));
    CHECK(camera_key_text(*older) == "shot 2 drop 5");
    CHECK(camera_key_text(key_of(CameraKeyKind::at, -1, -1, 1, 4.25)) == "at 4.25");
    CHECK(camera_key_ordinal("third") == 3);
    CHECK(camera_key_ordinal("first") == std::nullopt);
    CHECK(camera_key_kind("event") == std::nullopt);
    CHECK(camera_key_first_words().size() == 15);  // 8 kinds, `pocket` (drop's older spelling), 5 ordinals, `shot`
  }

  TEST_CASE("text that is no key is refused") {
    for (const char* text :
         {"",           "hit 0",     "second pocket 3", "second drop 3", "drop",     "last",    "at",
          "at x",       "hit 0 1 2", "pocket",          "70000",         "-1",       "start 3", "second  hit 0 1",
          "jaw",        "jaw 1 2",   "second jaw",      "shot 0 cue",    "shot cue", "shot 2",  "shot 2 shot 1 cue",
          "shot x cue", "cue shot 2"}) {
      CAPTURE(text);
      CHECK_FALSE(parse_camera_key(text));
    }
  }

  TEST_CASE("a key with `shot K` is written with it and reads back the same, in the parser too") {
    const std::string scene = test::require_file(test::source_path("tests/scene/three_shots.scn"));
    for (int shot : {0, 1, 2}) {
      for (CameraKey key : every_key()) {
        key.shot = shot;
        const std::string text = camera_key_text(key);
        CAPTURE(text);
        CHECK(text.starts_with("shot " + std::to_string(shot + 1) + " "));
        const std::optional<CameraKey> back = parse_camera_key(text);
        REQUIRE(back);
        CHECK(back->shot == shot);
        CHECK(same_camera_key(*back, key));
        CHECK(camera_key_text(*back) == text);
        // Not the same key as the one counting over the scene.
        CameraKey whole = key;
        whole.shot = -1;
        CHECK_FALSE(same_camera_key(whole, key));
        const ParseResult parsed =
            parse_scene(scene + "camera\n  event " + text + " 0.3 0 hover 0 -2 1.5 0 0 0\nendcamera\n", "key");
        REQUIRE(parsed.scene);
        REQUIRE(parsed.scene->camera.size() == 1);
        CHECK(same_camera_key(parsed.scene->camera[0].key, key));
      }
    }
    CameraKey second_hit;
    second_hit.kind = CameraKeyKind::hit;
    second_hit.ordinal = 2;
    second_hit.a = 0;
    second_hit.b = 3;
    second_hit.shot = 1;
    CHECK(camera_key_text(second_hit) == "shot 2 second hit 0 3");
  }
}
