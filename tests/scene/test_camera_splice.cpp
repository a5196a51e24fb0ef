// Writing a camera description into a scene's text (core/scene/camera_splice.h): in the block, before
// a later description or at its end, a block added where there is none, and what a description does
// replaced in place; everything else kept byte for byte.
#include <doctest/doctest.h>

#include <string>

#include "camera_splice.h"
#include "fixtures.h"
#include "scene_parse.h"

using namespace bsim;
namespace fx = bsim::test::fixtures;

namespace {

Scene parsed(const std::string& text) {
  ParseResult r = parse_scene(text, "splice");
  REQUIRE(r.scene);
  return *r.scene;
}

const std::string kLine = "event cue 0.3 0 hover 0 -2 1.5 0 0 0";

}  // namespace

TEST_SUITE("camera splice") {
  TEST_CASE("a text without a camera block gets one at its end") {
    const std::string text = std::string(fx::kTwoBalls) + "# the end";
    const CameraSplice s = insert_camera_description(text, parsed(text), std::nullopt, kLine);
    REQUIRE(s.error.empty());
    CHECK(s.text == text + "\ncamera\n" + kLine + "\nendcamera\n");
    CHECK(s.text.substr(s.begin, s.end - s.begin) == kLine);
  }

  TEST_CASE("before a later description, indented like it; at the block's end like the last one") {
    const std::string text = std::string(fx::kTwoBalls) + "camera\n  event 0 0 0 hover 0 -3 2 0 0 0\r\n" +
                             "  event end 0.5 0 hover 1 -3 2 0 0 0  # wide\r\nendcamera\r\n";
    const Scene scene = parsed(text);
    const CameraSplice before = insert_camera_description(text, scene, 1, kLine);
    REQUIRE(before.error.empty());
    CHECK(before.text.find("\r\n  " + kLine + "\r\n  event end 0.5") != std::string::npos);
    CHECK(before.text.substr(before.begin, before.end - before.begin) == kLine);
    const CameraSplice at_end = insert_camera_description(text, scene, std::nullopt, kLine);
    CHECK(at_end.text.find("# wide\r\n  " + kLine + "\r\nendcamera\r\n") != std::string::npos);
  }

  TEST_CASE("replacing what a description does keeps its key as written, its windows and its comment") {
    const std::string text =
        std::string(fx::kTwoBalls) + "camera\n  event second hit 0 1  0.25 0 look 0 -3 2 1  # close\nendcamera\n";
    const CameraSplice s = replace_camera_mode(text, parsed(text), 0, "hover 1 2 3 0 0 0");
    REQUIRE(s.error.empty());
    CHECK(s.text == std::string(fx::kTwoBalls) +
                        "camera\n  event second hit 0 1  0.25 0 hover 1 2 3 0 0 0  # close\nendcamera\n");
    CHECK(s.text.substr(s.begin, s.end - s.begin) == "event second hit 0 1  0.25 0 hover 1 2 3 0 0 0");
  }
}
