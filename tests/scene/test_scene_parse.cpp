// The scene grammar: every rule of the seed's format and of the extensions reads into the Scene it
// describes, with defaults filled in and every reference keeping its source location.
#include <doctest/doctest.h>

#include <cmath>

#include <filesystem>

#include "files.h"
#include "scene_lexer.h"
#include "scene_parse.h"
#include "support.h"

using namespace bsim;

namespace {

constexpr double kR = 0.028575;

std::string all_messages(const ParseResult& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics) out += format_diagnostic(d, "scene") + "\n";
  return out;
}

/// Parses text that must be free of errors and returns its scene.
Scene parse_ok(std::string_view text, ParseOptions options = {}) {
  ParseResult r = parse_scene(text, "test", options);
  INFO(all_messages(r));
  REQUIRE(r.scene.has_value());
  CHECK_FALSE(has_errors(r.diagnostics));
  return *r.scene;
}

void check_loc(SourceLoc loc, int line, int column) {
  CHECK(loc.line == line);
  CHECK(loc.column == column);
}

void check_vec(const Vec3& v, double x, double y, double z) {
  CHECK(v.x() == doctest::Approx(x));
  CHECK(v.y() == doctest::Approx(y));
  CHECK(v.z() == doctest::Approx(z));
}

const char* const kSeedScene =
    "cue 1 90\n"
    "ball 0 -0.5 0 0.028575  0 0 0  1 0 0 0\n"
    "ball 9  0.5 0.2 0.028575  0 1.5 0  0 0 0 2\n"
    "rail -1 0.6 0.0363  1 0.6 0.0363\n"
    // Closed at the ends (a table's cushions close round its bed), on the same line.
    "rail 1 -0.6 0.0363  -1 -0.6 0.0363  rail -1 -0.6 0.0363 -1 0.6 0.0363  rail 1 0.6 0.0363 1 -0.6 0.0363\n"
    "camera\n"
    "event 0 0 0.25 hover -1.5 -1.5 1.2  0 0 0\n"
    "event 1 0.5 0.5 look 0 -2 1  1\n"
    "event 65535 0.4 0 follow 0 -0.6 0 0.35\n"
    "endcamera\n";

}  // namespace

TEST_SUITE("scene_parse") {
  TEST_CASE("a scene in the seed's grammar reads into SI values with its locations") {
    const Scene s = parse_ok(kSeedScene);
    CHECK(s.name == "test");
    CHECK(s.cue().target == 1);
    CHECK(s.cue().heading_deg == 90);
    check_loc(s.cue().loc, 1, 1);
    check_loc(s.cue().target_loc, 1, 5);
    check_loc(s.cue().heading_loc, 1, 7);

    REQUIRE(s.balls.size() == 2);
    CHECK(s.balls[0].number == 0);
    check_vec(s.balls[0].position, -0.5, 0, kR);
    CHECK(s.balls[1].number == 9);
    check_vec(s.balls[1].position, 0.5, 0.2, kR);
    check_vec(s.balls[1].velocity, 0, 1.5, 0);
    check_vec(s.balls[1].spin, 0, 0, 0);
    check_loc(s.balls[1].loc, 3, 1);

    REQUIRE(s.rails.size() == 4);
    check_vec(s.rails[0].a, -1, 0.6, 0.0363);
    check_vec(s.rails[1].b, -1, -0.6, 0.0363);
    check_loc(s.rails[1].loc, 5, 1);

    check_loc(s.camera_loc, 6, 1);
    REQUIRE(s.camera.size() == 3);
    const CameraShot& hover = s.camera[0];
    CHECK(hover.mode == CameraMode::hover);
    CHECK(hover.event == 0);
    CHECK(hover.pre == 0);
    CHECK(hover.post == 0.25);
    check_vec(hover.location, -1.5, -1.5, 1.2);
    check_vec(hover.target, 0, 0, 0);
    check_loc(hover.loc, 7, 1);
    check_loc(hover.event_loc, 7, 7);

    const CameraShot& look = s.camera[1];
    CHECK(look.mode == CameraMode::look);
    CHECK(look.event == 1);
    CHECK(look.pre == 0.5);
    check_vec(look.location, 0, -2, 1);
    CHECK(look.ball == 1);
    check_loc(look.ball_loc, 8, 30);

    const CameraShot& follow = s.camera[2];
    CHECK(follow.mode == CameraMode::follow);
    CHECK(follow.event == CameraShot::kLastEvent);
    CHECK(follow.ball == 0);
    check_vec(follow.location, -0.6, 0, 0.35);
    check_loc(follow.event_loc, 9, 7);
    check_loc(follow.ball_loc, 9, 26);
  }

  TEST_CASE("a non-unit quaternion is normalised") {
    const Scene s = parse_ok(kSeedScene);
    const Quat& q = s.balls[1].orientation;  // written 0 0 0 2: half a turn about z
    CHECK(q.w() == doctest::Approx(0));
    CHECK(q.z() == doctest::Approx(1));
    CHECK(q.norm() == doctest::Approx(1));
    const Scene big = parse_ok("cue 0 0\nball 0 0 0 0.028575 1 0 0 1e300 1e300 0 0\n");
    CHECK(big.balls[0].orientation.w() == doctest::Approx(std::sqrt(0.5)));
    CHECK(big.balls[0].orientation.x() == doctest::Approx(std::sqrt(0.5)));
  }

  TEST_CASE("top-level items may come in any order") {
    const Scene s = parse_ok(
        "camera event 0 0 0 look 0 -3 2 1 endcamera\n"
        "rail -1 0.6 0.0363 1 0.6 0.0363  rail 1 0.6 0.0363 1 -0.6 0.0363\n"
        "ball 3 0.3 0 0.028575 0 0 0 1 0 0 0\n"
        "rail 1 -0.6 0.0363 -1 -0.6 0.0363  rail -1 -0.6 0.0363 -1 0.6 0.0363\n"
        "cue 1 180\n"
        "ball 0 0.6 0 0.028575 -1 0 0 1 0 0 0\n");
    REQUIRE(s.balls.size() == 2);
    CHECK(s.balls[0].number == 3);
    CHECK(s.cue().target == 1);
    CHECK(s.rails.size() == 4);
    CHECK(s.camera.size() == 1);
  }

  TEST_CASE("tokens may be split by any whitespace, and columns count bytes") {
    const Scene s = parse_ok("cue\t0 0\r\nball 0\t\t0 0 0.028575\n1 0 0\n1 0 0 0");
    CHECK(s.balls[0].velocity.x() == 1);
    check_loc(s.cue().heading_loc, 1, 7);
    check_loc(s.balls[0].loc, 2, 1);
  }

  TEST_CASE("numbers may be written in any decimal form") {
    const Scene s = parse_ok("cue +0 -0\nball 0 .5 -0. 28.575e-3 +1.5 2E-1 0 1 0 0 0\n");
    check_vec(s.balls[0].position, 0.5, 0, kR);
    check_vec(s.balls[0].velocity, 1.5, 0.2, 0);
    const Scene tiny = parse_ok("cue 0 0\nball 0 1e-400 0 0.028575 1 0 0 1 0 0 0\n");
    CHECK(tiny.balls[0].position.x() == 0);  // an underflow is just a very small number
  }

  TEST_CASE("a scene without rails or pockets gets the standard table") {
    const Scene s = parse_ok("cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\n");
    REQUIRE(s.rails.size() == 6);
    REQUIRE(s.pockets.size() == 6);
    const auto rails = standard_rails();
    for (std::size_t i = 0; i < 6; ++i) {
      CHECK(s.rails[i].a == rails[i].a);
      CHECK(s.rails[i].b == rails[i].b);
      CHECK_FALSE(s.rails[i].loc.known());
    }
    // Rail 0 ends at the top-left corner's jaw point, a corner mouth (4.5875 in) over sqrt 2 from the corner.
    check_vec(s.rails[0].a, -1.27 + 0.1165225 / std::sqrt(2.0), 0.635, kStandardNoseHeight);
    // The bottom-right corner's hole lies behind its mouth, on the diagonal through the corner.
    CHECK(s.pockets[3].center.x() - 1.27 == doctest::Approx(-(s.pockets[3].center.y() + 0.635)));
    CHECK(s.pockets[3].center.x() > 1.27);
    CHECK(s.pockets[3].cut);
    CHECK(s.pockets[1].radius == kStandardTable.jaws.side_hole);
    CHECK(s.camera.empty());
  }

  TEST_CASE("the scene's own rails replace the standard cushions but keep the standard pockets") {
    const Scene s = parse_ok(
        "cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nrail -2 1 0.03 2 1 0.03\nrail 2 1 0.03 2 -1 0.03\n"
        "rail 2 -1 0.03 -2 -1 0.03\nrail -2 -1 0.03 -2 1 0.03\n");
    CHECK(s.rails.size() == 4);
    CHECK(s.pockets.size() == 6);
    // Round cushions of its own the standard pockets are plain drop circles: no jaws.
    for (const Pocket& p : s.pockets) CHECK_FALSE(p.cut);
    CHECK(s.pockets[1].radius == kStandardTable.jaws.bare_side_radius);
  }

  TEST_CASE("param names the standard pockets' mouths, shelves and jaw points' radius") {
    const Scene s = parse_ok(
        "cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nparam corner_mouth 0.108\nparam side_mouth 0.125\n"
        "param corner_shelf 0.03\nparam side_shelf 0.002\nparam jaw_radius 0.002\n");
    CHECK((s.rails[0].a - s.rails[5].b).norm() == doctest::Approx(0.108));  // a 4.25 in "pro-cut" corner
    CHECK((s.rails[1].a - s.rails[0].b).norm() == doctest::Approx(0.125));
    const PocketMouth corner = pocket_mouth(s.pockets[0], s.rails), side = pocket_mouth(s.pockets[1], s.rails);
    REQUIRE(corner.cut);
    REQUIRE(side.cut);
    CHECK(corner.mouth() == doctest::Approx(0.108));
    CHECK(corner.shelf() == doctest::Approx(0.03));
    CHECK(side.shelf() == doctest::Approx(0.002));
    CHECK(corner.round_radius == 0.002);
  }

  TEST_CASE("default physical constants") {
    const Scene s = parse_ok("cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\n");
    CHECK(s.physics.ball_radius == kR);
    CHECK(s.physics.g == 9.81);
    CHECK(s.physics.e_ball == 0.95);
  }

  TEST_CASE("an empty camera description is allowed") {
    const Scene s = parse_ok("cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\ncamera endcamera\n");
    CHECK(s.camera.empty());
    check_loc(s.camera_loc, 3, 1);
  }
}

TEST_SUITE("scene_parse extensions") {
  TEST_CASE("'#' comments run to the end of the line, even straight after a token") {
    const Scene s = parse_ok(
        "# a break\n"
        "cue 0 0 # aim straight\n"
        "ball 0 0 0 0.028575 1#comment\n"
        "0 0 1 0 0 0 ### more\n");
    CHECK(s.balls[0].velocity.x() == 1);
    check_loc(s.cue().loc, 2, 1);
  }

  TEST_CASE("spin gives a ball its angular velocity by file-order index") {
    const Scene s = parse_ok(
        "spin 1 0 0 30\n"
        "cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nball 5 0.5 0 0.028575 0 0 0 1 0 0 0\n");
    check_vec(s.balls[1].spin, 0, 0, 30);
    check_vec(s.balls[0].spin, 0, 0, 0);
  }

  TEST_CASE("pocket lines replace the standard pockets") {
    const Scene s = parse_ok(
        "cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\npocket 1.27 0.635 0 0.08\npocket -1.27 0.635 0 0.07\n"
        "pocket 0 0.635 0 0.065  pocket 1.27 -0.635 0 0.08  pocket 0 -0.635 0 0.065  pocket -1.27 -0.635 0 0.08\n");
    REQUIRE(s.pockets.size() == 6);
    check_vec(s.pockets[1].center, -1.27, 0.635, 0);
    CHECK(s.pockets[1].radius == 0.07);
    check_loc(s.pockets[1].loc, 4, 1);
    CHECK(s.rails.size() == 6);
  }

  TEST_CASE("every param sets its constant") {
    const Scene s = parse_ok(
        "cue 0 0\nball 0 0 0 0.03 1 0 0 1 0 0 0\n"
        "param ball_radius 0.03\nparam ball_mass 0.2\nparam g 9.8\nparam mu_slide 0.3\nparam mu_roll 0.02\n"
        "param mu_spin 0.05\nparam e_ball 0.9\nparam mu_ball 0\nparam e_rail 0.7\nparam mu_rail 0.1\n");
    const PhysicsParams& p = s.physics;
    CHECK(p.ball_radius == 0.03);
    CHECK(p.ball_mass == 0.2);
    CHECK(p.g == 9.8);
    CHECK(p.mu_slide == 0.3);
    CHECK(p.mu_roll == 0.02);
    CHECK(p.mu_spin == 0.05);
    CHECK(p.e_ball == 0.9);
    CHECK(p.mu_ball == 0);
    CHECK(p.e_rail == 0.7);
    CHECK(p.mu_rail == 0.1);
  }

  TEST_CASE("table_speed sets mu_roll to its reciprocal") {
    const Scene s = parse_ok("cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nparam table_speed 40\n");
    CHECK(s.physics.mu_roll == doctest::Approx(1.0 / 40));
  }

  TEST_CASE("a param governs the checks wherever it appears in the file") {
    // The balls sit on the bed and apart only with the larger radius, given after them.
    const Scene s =
        parse_ok("cue 0 0\nball 0 0 0 0.05 1 0 0 1 0 0 0\nball 1 0.1 0 0.05 0 0 0 1 0 0 0\nparam ball_radius 0.05\n");
    CHECK(s.physics.ball_radius == 0.05);
  }

  TEST_CASE("a param given twice warns and the last value wins") {
    ParseResult r = parse_scene("param g 9\ncue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nparam g 10\n", "t");
    REQUIRE(r.scene);
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].severity == Severity::warning);
    CHECK(r.diagnostics[0].loc.line == 4);
    CHECK(r.diagnostics[0].message.find("first on line 1") != std::string::npos);
    CHECK(r.scene->physics.g == 10);
  }

  TEST_CASE("--strict accepts the seed's grammar") {
    const Scene s = parse_ok(kSeedScene, {.strict = true});
    CHECK(s.rails.size() == 4);
  }
}

TEST_SUITE("scene_parse lexer") {
  TEST_CASE("tokens carry their line and byte column") {
    const LexedText lexed = lex_scene("  cue 0\n\tball # x\n  1.5");
    REQUIRE(lexed.tokens.size() == 4);
    CHECK(lexed.tokens[1].text == "0");
    check_loc(lexed.tokens[1].loc, 1, 7);
    check_loc(lexed.tokens[2].loc, 2, 2);
    check_loc(lexed.tokens[3].loc, 3, 3);
    REQUIRE(lexed.comments.size() == 1);
    check_loc(lexed.comments[0], 2, 7);
    check_loc(lexed.end, 3, 6);
  }

  TEST_CASE("a file without tokens ends at 1:1") {
    check_loc(lex_scene("").end, 1, 1);
    check_loc(lex_scene("# only a comment\n\n").end, 1, 1);
  }

  TEST_CASE("tokens in messages are quoted, escaped and cut short") {
    CHECK(quote_token("abc") == "'abc'");
    CHECK(quote_token(std::string_view("a\x01\xff", 3)) == "'a\\x01\\xff'");
    CHECK(quote_token(std::string(100, 'z')) == "'" + std::string(40, 'z') + "...'");
  }
}

TEST_SUITE("scene_parse gallery") {
  TEST_CASE("every scene in scenes/ parses without errors, strict where it uses no extension") {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenes"))) {
      if (entry.path().extension() != ".scn") continue;
      ++count;
      const std::string text = test::require_file(entry.path());
      const ParseResult r = parse_scene(text, entry.path().stem().string());
      INFO(entry.path().filename().string() << ":\n" << all_messages(r));
      CHECK(r.scene.has_value());
      CHECK_FALSE(has_errors(r.diagnostics));
      if (r.scene) CHECK(r.scene->name == entry.path().stem().string());
      // With --strict the only errors are the extensions it uses (a scene using none parses).
      const ParseResult strict = parse_scene(text, entry.path().stem().string(), {.strict = true});
      INFO("with --strict:\n" << all_messages(strict));
      CHECK(strict.scene.has_value() == !has_errors(strict.diagnostics));
      for (const Diagnostic& d : strict.diagnostics)  // a long scene's many may end in "too many errors"
        CHECK((d.message.find("an extension that --strict rejects") != std::string::npos ||
               d.message.find("too many errors") != std::string::npos));
    }
    CHECK(count >= 1);
  }
}
