// The POV-Ray files: the shared include and a frame match their golden text; balls are placed by
// their quaternions, dropped balls lie in their pockets, the put-away stick leaves it, fast balls are
// drawn as their streaks and slow ones once, a fast stroke's stick is swept along its axis, the
// table follows the scene, the models compiled in are export/pov/*.inc byte for byte, POV-Ray itself
// parses what is written for several tables, and two renders of one frame are the same picture.
//
// After an intended change to the models, regenerate the golden files (with every other) with
//   BSIM_UPDATE_GOLDENS=1 build/bin/bsim_tests
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "camera_view.h"
#include "cue_pose.h"
#include "files.h"
#include "frames.h"
#include "golden.h"
#include "pocket_fall.h"
#include "pov_format.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "shot.h"
#include "shots.h"
#include "shutter_cover.h"
#include "support.h"
#include "table.h"

using namespace bsim;
using bsim::test::stick_cover;
using bsim::test::streak_cover;
namespace fs = std::filesystem;

namespace {

// A small shot on the standard table: the cue ball, a solid and a stripe, turned different ways.
const char* const kTinyScene =
    "cue 0 0\n"
    "ball 0  -0.6 0.1 0.028575   1.2 0 0   1 0 0 0\n"
    "ball 3   0.3 0.1 0.028575   0 0 0     0.7071067811865476 0 0 0.7071067811865476\n"
    "ball 11  0.5 -0.3 0.028575  0 0 0     0.5 0.5 0.5 0.5\n"
    "camera\nevent 0 0 0 hover -1.8 -1.2 1.1  0 0 0\nendcamera\n";

// A ball rolled into the top-right corner pocket.
const char* const kPocketScene =
    "cue 0 40.6\n"
    "ball 0 0.9 0.3 0.028575  0.8 0.686 0  1 0 0 0\n"
    "ball 1 -0.5 0 0.028575  0 0 0  1 0 0 0\n"
    "camera\nevent 0 0 0 hover 0 -2.5 2  0 0 0\nendcamera\n";

// A table of the scene's own: a 3 x 1.6 m box of cushions 4 cm high and a pocket in the middle of
// the cloth, far from every cushion; seen from straight above.
const char* const kBoxScene =
    "cue 0 0\n"
    "ball 0 -1 0.4 0.028575  0.5 0 0  1 0 0 0\n"
    "rail -1.5 0.8 0.04   1.5 0.8 0.04\n"
    "rail 1.5 0.8 0.04   1.5 -0.8 0.04\n"
    "rail 1.5 -0.8 0.04   -1.5 -0.8 0.04\n"
    "rail -1.5 -0.8 0.04   -1.5 0.8 0.04\n"
    "pocket 0.2 -0.3 0 0.07\n"
    "camera\nevent 0 0 0 hover 0 0 3  0 0 0\nendcamera\n";

// One ball far from the top-right corner, which a camera looks straight down at from 0.5 m.
const char* const kCornerFromAbove =
    "ball 0 -0.6 0 0.028575  0 0 0  1 0 0 0\n"
    "cue 0 180\n"
    "stroke 0.3 0 0 0\n"
    "camera\nevent 0 0 0 hover  1.27 0.62 0.5  1.27 0.62 0\nendcamera\n";

std::unique_ptr<Shot> load(const char* text) { return test::load_scene(text, "tiny"); }

std::string include_text(const Shot& shot, Quality quality = Quality::draft) {
  std::ostringstream out;
  write_pov_include(shot.scene, quality, out);
  return out.str();
}

std::string frame_text(const Shot& shot, int frame, int fps = 30) {
  std::ostringstream out;
  write_pov_frame(shot, frame, fps, out);
  return out.str();
}

void check_golden(const std::string& name, const std::string& text) {
  test::check_golden_text(test::golden_path("pov", name), text);
}

/// Writes the include and the given frames of `shot` into `dir`, renders them at 32x18 with
/// POV-Ray (all at once: each process spends most of its time starting), returns the log.
test::CommandResult render_tiny(const Shot& shot, const fs::path& dir, const std::vector<int>& frames) {
  std::ostringstream include;
  write_pov_include(shot.scene, Quality::final, include);
  REQUIRE(test::write_file(dir / std::string(kPovIncludeName), include.str()));
  std::string command = "cd '" + dir.string() + "' && status=0; pids=; for f in";
  for (int k : frames) {
    REQUIRE(test::write_file(dir / (frame_name(k) + ".pov"), frame_text(shot, k)));
    command += " " + frame_name(k);
  }
  command +=
      "; do povray -D +FN +WT1 +I$f.pov +O$f.png +W32 +H18 +Q9 +A0.3 2>$f.log & pids=\"$pids $!\"; done; "
      "for p in $pids; do wait $p || status=1; done; "
      "for f in *.log; do grep -h 'Error' $f; done; exit $status";
  return test::run_command(command);
}

}  // namespace

TEST_SUITE("pov") {
  TEST_CASE("numbers are fixed to the micrometre, shortest, never -0") {
    CHECK(pov_number(0) == "0.0");
    CHECK(pov_number(-0.0) == "0.0");
    CHECK(pov_number(-1e-9) == "0.0");
    CHECK(pov_number(1.5) == "1.5");
    CHECK(pov_number(-2) == "-2.0");
    CHECK(pov_number(0.12345678) == "0.123457");
    CHECK(pov_number(0.028575) == "0.028575");
    CHECK(pov_vector(Vec3(1, -0.5, 0)) == "<1.0, -0.5, 0.0>");
  }

  TEST_CASE("the shared include and the first frame of a tiny shot match their golden text") {
    const auto shot = load(kTinyScene);
    check_golden("billiards.inc", include_text(*shot, Quality::final));
    check_golden("tiny_frame_00000.pov", frame_text(*shot, 0));
  }

  TEST_CASE("the models compiled in are export/pov/*.inc, byte for byte, in the include's order") {
    // Every .inc in the folder is compiled in, in the order export/CMakeLists.txt names them.
    const std::vector<std::string> in_include = {"settings.inc", "materials.inc", "table.inc",
                                                 "balls.inc",    "cue.inc",       "room.inc"};
    std::vector<std::string> in_folder, sorted = in_include;
    for (const auto& entry : fs::directory_iterator(test::source_path("export/pov")))
      if (entry.path().extension() == ".inc") in_folder.push_back(entry.path().filename().string());
    std::sort(in_folder.begin(), in_folder.end());
    std::sort(sorted.begin(), sorted.end());
    CHECK(in_folder == sorted);
    std::string files;
    for (const std::string& name : in_include) {
      const auto text = test::read_file(test::source_path("export/pov/" + name));
      REQUIRE_MESSAGE(text, name);
      files += *text;
    }
    CHECK(files == std::string(pov_models_text()));
  }

  TEST_CASE("a ball's matrix turns its axes by its orientation and moves it to its centre") {
    const auto shot = load(kTinyScene);
    const std::string frame = frame_text(*shot, 0);
    // 90 degrees about z: x goes to y, y to -x.
    CHECK(frame.find("object { Ball(3) matrix <0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.3, 0.1, 0.028575> }") !=
          std::string::npos);
    // 120 degrees about (1,1,1): x to y, y to z, z to x.
    CHECK(frame.find("object { Ball(11) matrix <0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.5, -0.3, 0.028575> }") !=
          std::string::npos);
    CHECK(frame.find("object { Ball(0) matrix <1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, -0.6, 0.1, 0.028575> }") !=
          std::string::npos);
    CHECK(frame.find("location <-1.8, -1.2, 1.1>") != std::string::npos);
    CHECK(frame.find("angle 55.0") != std::string::npos);
  }

  TEST_CASE("a pocketed ball lies in its pocket; the put-away stick is gone") {
    const auto shot = load(kPocketScene);
    REQUIRE(shot->timeline.pocket_drops().size() == 1);
    const int last = frame_count(shot->timeline.duration(), 30) - 1;
    const std::string first = frame_text(*shot, 0), end = frame_text(*shot, last);
    CHECK(first.find("// ball 0") != std::string::npos);
    // In the pocket's cup, its centre PocketDepth below its height on the bed.
    const double rest = shot->scene.physics.ball_radius - kPocketDepth;
    CHECK(end.find(", " + pov_number(rest) + "> }  // ball 0") != std::string::npos);
    CHECK(end.find("// ball 1") != std::string::npos);
    CHECK(end.find("CueStick") == std::string::npos);
    bool stick_seen = false;
    for (int k = 0; k <= last && !stick_seen; k += 5)
      stick_seen = frame_text(*shot, k).find("CueStick") != std::string::npos;
    CHECK(stick_seen);
  }

  TEST_CASE("the table is the scene's: its cushions, pockets and each pocket's jaws") {
    const std::string standard = include_text(*load(kTinyScene));
    CHECK(standard.find("#declare RailCount = 6;") != std::string::npos);
    CHECK(standard.find("#declare PocketCount = 6;") != std::string::npos);
    // every pocket opens between two jaws; each cushion end is cut along its jaw's facing: the corner
    // pockets' by cot(38 deg), the side pockets' by cot(76 deg)
    CHECK(standard.find("#declare PocketJawed = array[6] { 1, 1, 1, 1, 1, 1 }") != std::string::npos);
    CHECK(standard.find("#declare RailSlantA = array[6] { 1.279942, 0.249328,") != std::string::npos);

    const std::string box = include_text(*load(kBoxScene));
    CHECK(box.find("#declare RailCount = 4;") != std::string::npos);
    CHECK(box.find("#declare RailH = array[4] { 0.04, 0.04, 0.04, 0.04 }") != std::string::npos);
    CHECK(box.find("#declare PocketC = array[1] { <0.2, -0.3> }") != std::string::npos);
    CHECK(box.find("#declare PocketJawed = array[1] { 0 }") != std::string::npos);  // no cushion near it
    CHECK(box.find("#declare RailSlantA = array[4] { -1.0, -1.0, -1.0, -1.0 }") != std::string::npos);
    CHECK(box.find("#declare NoseMin = <-1.5, -0.8>;") != std::string::npos);
    CHECK(box.find("#declare Final = 0;") != std::string::npos);
    CHECK(include_text(*load(kBoxScene), Quality::final).find("#declare Final = 1;") != std::string::npos);
  }

  TEST_CASE("a camera looking straight down still has a direction POV-Ray can orient") {
    const std::string frame = frame_text(*load(kBoxScene), 0);
    CHECK(frame.find("location <0.0, 0.0, 3.0>") != std::string::npos);
    CHECK(frame.find("look_at <0.0, 0.0003, 0.0>") != std::string::npos);
  }

  TEST_CASE("a fast ball is drawn as its streak over the shutter, a still frame once") {
    const auto shot = load(kTinyScene);
    // Before the strike nothing moves: every ball once, no streak.
    CHECK(frame_text(*shot, 0).find("BallStreak") == std::string::npos);
    // Just after it the cue ball runs at 1.2 m/s: many pixels while the shutter is open, in a straight
    // line, so one capsule as long as the way the ball goes in half a frame.
    const int after = static_cast<int>(std::ceil(shot->timeline.cue_time() * 30)) + 1;
    const std::string text = frame_text(*shot, after);
    CHECK(text.find("BallShadow") != std::string::npos);
    const std::size_t streak = text.find("object { BallStreak(0, ");
    REQUIRE(streak != std::string::npos);
    CHECK(text.find("// ball 0, streak 1/1") != std::string::npos);
    const double t = after / 30.0, half = 0.5 * kShutter / 30.0;
    const double way = (shot->timeline.state(0, t + half).position - shot->timeline.state(0, t - half).position).norm();
    const double length = std::stod(text.substr(streak + std::string("object { BallStreak(0, ").size()));
    CHECK(length == doctest::Approx(way).epsilon(0.05));         // the camera looks down at it: seen at full length
    CHECK(text.find("object { Ball(3) ") != std::string::npos);  // the balls at rest stay sharp
  }

  TEST_CASE("a streak lets through what a box filter over the shutter would, and sums to one ball") {
    const double r = 0.028575, length = 0.1, weight = 1 / length;
    // Where the ball is for the whole shutter (a short streak's middle) nothing shows through; at
    // the far ends of its sweep almost all; half-way along a long ramp, half.
    CHECK(streak_cover(0.01, 0, 0.02, 1 / 0.02, r) == doctest::Approx(1));
    CHECK(streak_cover(-r + 1e-4, 0, length, weight, r) < 0.01);
    CHECK(streak_cover(length + r - 1e-4, 0, length, weight, r) < 0.01);
    CHECK(streak_cover(0, 0, length, weight, r) == doctest::Approx(r / length));
    CHECK(streak_cover(0.05, 0, length, weight, r) == doctest::Approx(2 * r / length));
    CHECK(streak_cover(0.05, r, length, weight, r) == doctest::Approx(0));
    // Its opacity over the picture adds up to one ball's disc, however long the streak: a fast ball is
    // as much there as a still one, spread along its way.
    for (double l : {0.002, 0.03, 0.3}) {
      const double step = 2e-4;
      double sum = 0;
      for (double a = -r; a < l + r; a += step)
        for (double c = -r; c < r; c += step)
          sum += streak_cover(a + step / 2, c + step / 2, l, 1 / l, r) * step * step;
      CHECK(sum == doctest::Approx(std::numbers::pi * r * r).epsilon(0.01));
    }
    // A ball at rest for part of the shutter (a piece of no length) is a still ball that covers
    // that share of it.
    CHECK(streak_cover(0, 0, kStreakLeast, 0.25 / kStreakLeast, r) == doctest::Approx(0.25));
  }

  TEST_CASE("a fast stroke's stick is one stick swept along its axis, with an unseen stick for its shadow") {
    const auto shot = load(kTinyScene);
    const int strike = static_cast<int>(std::lround(shot->timeline.cue_time() * 30));
    int swept = -1;
    for (int k = strike - 3; k <= strike + 1 && swept < 0; ++k)
      if (frame_text(*shot, k).find("CueSweep(") != std::string::npos) swept = k;
    REQUIRE(swept >= 0);
    const std::string text = frame_text(*shot, swept);
    CHECK(text.find("#declare StickCover = function(X) { StickPiece(X, ") != std::string::npos);
    CHECK(text.find("object { CueShadow matrix <") != std::string::npos);
    CHECK(text.find("// blurred: swept along its axis") != std::string::npos);
    CHECK(text.find("CueStickT") == std::string::npos);  // no copies
  }

  TEST_CASE("a stick swung across the picture is drawn as copies that cast no shadow, and one unseen stick does") {
    const auto text = test::read_file(test::source_path("scenes/break.scn"));
    REQUIRE(text);
    const auto shot = test::load_scene(*text, "break");
    int checked = 0;
    for (int k = 0; k < 40; ++k) {
      const std::string frame = frame_text(*shot, k);
      if (frame.find("CueStickT(") == std::string::npos) continue;
      ++checked;
      std::size_t copies = 0, unshadowed = 0;
      for (std::size_t at = frame.find("CueStickT("); at != std::string::npos; at = frame.find("CueStickT(", at + 1)) {
        ++copies;
        const std::string line = frame.substr(at, frame.find('\n', at) - at);
        unshadowed += line.find(" no_shadow }") != std::string::npos;
      }
      CHECK(copies >= 3);
      CHECK(unshadowed == copies);
      const std::size_t shadow = frame.find("object { CueShadow matrix <");
      CHECK(shadow != std::string::npos);
      CHECK(frame.find("object { CueShadow", shadow + 1) == std::string::npos);
    }
    CHECK(checked >= 3);  // the break's stick swings down onto the table over several frames
  }

  TEST_CASE("a swept stick lets through what a box filter over the shutter would") {
    const double length = kCueLength;
    // An even stroke 0.1 m forward (towards -x along the axis): one piece; solid between the ends'
    // travels, each end fading linearly over its 0.1 m.
    std::vector<double> even;
    for (int k = 0; k <= 16; ++k) even.push_back(0.05 - 0.1 * k / 16);
    const std::vector<StickTravel> stroke = stick_travel(even);
    REQUIRE(stroke.size() == 1);
    CHECK(stroke[0].share == doctest::Approx(1));
    CHECK(stick_cover(-0.051, stroke, length) == 0);
    CHECK(stick_cover(-0.025, stroke, length) == doctest::Approx(0.25));
    CHECK(stick_cover(0.0, stroke, length) == doctest::Approx(0.5));
    CHECK(stick_cover(0.04, stroke, length) == doctest::Approx(0.9));
    for (double a : {0.051, 0.7, length - 0.051}) CHECK(stick_cover(a, stroke, length) == doctest::Approx(1));
    CHECK(stick_cover(length - 0.025, stroke, length) == doctest::Approx(0.75));
    CHECK(stick_cover(length + 0.025, stroke, length) == doctest::Approx(0.25));
    CHECK(stick_cover(length + 0.051, stroke, length) == 0);

    // The tip comes forward 0.08 m in the first half of the shutter and rests on the ball in the
    // second: the tip's resting place is covered half the time, and ahead of it nothing.
    const std::vector<StickTravel> stop = stick_travel({0.08, 0.06, 0.04, 0.02, 0.0, 0.0, 0.0, 0.0, 0.0});
    REQUIRE(stop.size() == 2);
    CHECK(stick_cover(-0.001, stop, length) == 0);
    CHECK(stick_cover(0.0005, stop, length) == doctest::Approx(0.5 + 0.5 * 0.0005 / 0.08));
    CHECK(stick_cover(0.04, stop, length) == doctest::Approx(0.75));
    CHECK(stick_cover(0.09, stop, length) == doctest::Approx(1));
    // Forward and back again: the front-most place is passed twice, briefly.
    const std::vector<StickTravel> back = stick_travel({0.04, 0.02, 0.0, 0.02, 0.04});
    REQUIRE(back.size() == 2);
    CHECK(stick_cover(0.01, back, length) == doctest::Approx(0.25));
    CHECK(stick_cover(length + 0.03, back, length) == doctest::Approx(0.25));

    // At rest: the plain stick, solid from its tip to its butt.
    const std::vector<StickTravel> still = stick_travel(std::vector<double>(17, 0.0));
    REQUIRE(still.size() == 1);
    CHECK(stick_cover(-1e-3, still, length) == 0);
    CHECK(stick_cover(2 * kStreakLeast, still, length) == 1);
    CHECK(stick_cover(length - 1e-3, still, length) == 1);
    CHECK(stick_cover(length + 2 * kStreakLeast, still, length) == 0);

    // However it moves, its opacity along the axis adds up to one stick's length: as much stick as a
    // still one, spread along its way.
    const std::vector<double> accelerating = {0.1, 0.098, 0.092, 0.082, 0.068, 0.05, 0.028, 0.002, -0.028};
    for (const std::vector<StickTravel>& pieces :
         {stroke, stop, back, still, stick_travel(accelerating), std::vector<StickTravel>{{0.02, -0.03, 0.5}}}) {
      const double step = 1e-4;
      double sum = 0;
      for (double a = -0.2; a < length + 0.2; a += step) sum += stick_cover(a + step / 2, pieces, length) * step;
      double shares = 0;
      for (const StickTravel& piece : pieces) shares += piece.share;
      CHECK(sum == doctest::Approx(shares * length).epsilon(1e-3));
    }
  }

  TEST_CASE("POV-Ray's StickCover of a swept stick is the C++ stick_cover of its pieces") {
    test::require_program("povray");
    const auto shot = load(kTinyScene);
    const int strike = static_cast<int>(std::lround(shot->timeline.cue_time() * 30));
    const std::string text = frame_text(*shot, strike);
    const std::size_t start = text.find("#declare StickCover");
    REQUIRE(start != std::string::npos);
    const std::string cover = text.substr(start, text.find('\n', start) - start);
    // The pieces as the frame writes them (to the micrometre).
    std::vector<StickTravel> pieces;
    for (std::size_t at = cover.find("StickPiece(X, "); at != std::string::npos;
         at = cover.find("StickPiece(X, ", at + 1)) {
      std::istringstream terms(cover.substr(at + std::string("StickPiece(X, ").size()));
      StickTravel piece;
      char comma = 0;
      terms >> piece.from >> comma >> piece.to >> comma >> piece.share;
      pieces.push_back(piece);
    }
    REQUIRE(pieces.size() >= 2);  // the tip meets the ball in this frame: not an even stroke
    double front = 0, back = 0;
    for (const StickTravel& piece : pieces) {
      front = std::min({front, piece.from, piece.to});
      back = std::max({back, piece.from, piece.to});
    }
    std::vector<double> xs;
    for (int i = 0; i <= 40; ++i) xs.push_back(front - 0.01 + (back - front + 0.02) * i / 40);
    for (int i = 0; i <= 40; ++i) xs.push_back(kCueLength + front - 0.01 + (back - front + 0.02) * i / 40);
    test::TempDir dir;
    std::ostringstream include;
    write_pov_include(shot->scene, Quality::draft, include);
    REQUIRE(test::write_file(dir.path / std::string(kPovIncludeName), include.str()));
    std::string probe = "#version 3.7;\n#include \"" + std::string(kPovIncludeName) + "\"\n" + cover + "\n";
    for (double x : xs) probe += "#debug concat(\"cover \", str(StickCover(" + pov_number(x) + "), 0, 9), \"\\n\")\n";
    REQUIRE(test::write_file(dir.path / "probe.pov", probe));
    const test::CommandResult r =
        test::run_command("cd '" + dir.path.string() + "' && povray -D +FN +WT1 +Iprobe.pov +Oprobe.png +W1 +H1");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    std::istringstream lines(r.err);
    std::size_t i = 0, fading = 0;
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("cover ", 0) != 0) continue;
      REQUIRE(i < xs.size());
      const double expected = stick_cover(std::stod(pov_number(xs[i])), pieces, kCueLength);
      CHECK(std::stod(line.substr(6)) == doctest::Approx(expected).epsilon(1e-6));
      fading += expected > 0.05 && expected < 0.95;
      ++i;
    }
    CHECK(i == xs.size());
    CHECK(fading > 20);  // the probes lie along both ends' fades
  }

  TEST_CASE("POV-Ray's StreakCover of a ball's streak is the C++ streak_cover") {
    test::require_program("povray");
    const auto shot = load(kTinyScene);
    const double r = shot->scene.physics.ball_radius;
    // Points along and across short, middling and long pieces, inside the ball's chord and beyond,
    // and a piece of no length (a ball at rest for a quarter of the shutter); as the frame writes
    // numbers (to the micrometre).
    std::vector<std::vector<double>> probes;  // along, across, length, weight
    for (double length : {0.002, 0.03, 0.3})
      for (int i = 0; i <= 12; ++i)
        for (double across : {0.0, 0.5 * r, 0.9 * r, 1.1 * r})
          probes.push_back({-r + (length + 2 * r) * i / 12, across, length, 1 / length});
    probes.push_back({0.0, 0.0, kStreakLeast, 0.25 / kStreakLeast});
    for (std::vector<double>& p : probes)
      for (double& x : p) x = std::stod(pov_number(x));
    test::TempDir dir;
    std::ostringstream include;
    write_pov_include(shot->scene, Quality::draft, include);
    REQUIRE(test::write_file(dir.path / std::string(kPovIncludeName), include.str()));
    std::string probe = "#version 3.7;\n#include \"" + std::string(kPovIncludeName) + "\"\n";
    for (const std::vector<double>& p : probes)
      probe += "#debug concat(\"cover \", str(StreakCover(" + pov_number(p[0]) + ", " + pov_number(p[1]) + ", " +
               pov_number(p[2]) + ", " + pov_number(p[3]) + "), 0, 9), \"\\n\")\n";
    REQUIRE(test::write_file(dir.path / "probe.pov", probe));
    const test::CommandResult result =
        test::run_command("cd '" + dir.path.string() + "' && povray -D +FN +WT1 +Iprobe.pov +Oprobe.png +W1 +H1");
    REQUIRE_MESSAGE(result.exit_code == 0, result.err);
    std::istringstream lines(result.err);
    std::size_t i = 0, partly = 0;
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("cover ", 0) != 0) continue;
      REQUIRE(i < probes.size());
      const std::vector<double>& p = probes[i];
      const double expected = test::streak_cover(p[0], p[1], p[2], p[3], r);
      CHECK(std::stod(line.substr(6)) == doctest::Approx(expected).epsilon(1e-6));
      partly += expected > 0.01 && expected < 0.99;
      ++i;
    }
    CHECK(i == probes.size());
    CHECK(partly > 20);  // the probes lie where the streak lets some through
  }

  TEST_CASE("two renders of one frame are the same picture") {
    test::require_program("povray");
    const auto shot = load(kTinyScene);
    test::TempDir dir;
    const int after = static_cast<int>(std::ceil(shot->timeline.cue_time() * 30)) + 1;
    REQUIRE(render_tiny(*shot, dir.path, {after}).exit_code == 0);
    // Picture files carry the time they were made, so compare the pixels: two renders as binary PPM
    // (32 x 18 x 3 bytes at the end of each file).
    const std::string name = frame_name(after);
    const test::CommandResult r =
        test::run_command("cd '" + dir.path.string() + "' && for o in a b; do povray -D +FP +WT1 +I" + name +
                          ".pov +O$o.ppm +W32 +H18 +Q9 +A0.3 2>/dev/null || exit 2; done; "
                          "tail -c 1728 a.ppm > a.rgb && tail -c 1728 b.ppm > b.rgb && cmp a.rgb b.rgb");
    CHECK_MESSAGE(r.exit_code == 0, r.out);
  }

  TEST_CASE("POV-Ray parses and renders the frames of three different tables") {
    struct Case {
      const char* text;
      const char* name;
    };
    test::require_program("povray");
    for (const Case& c : {Case{kTinyScene, "tiny"}, Case{kPocketScene, "pocket"}, Case{kBoxScene, "box"}}) {
      CAPTURE(c.name);
      const auto shot = load(c.text);
      test::TempDir dir;
      const int last = frame_count(shot->timeline.duration(), 30) - 1;
      const int strike = static_cast<int>(shot->timeline.cue_time() * 30);
      const test::CommandResult r = render_tiny(*shot, dir.path, {0, strike - 10, strike + 3, last});
      CHECK_MESSAGE(r.exit_code == 0, r.out);
      for (int k : {0, strike - 10, strike + 3, last}) CHECK(fs::file_size(dir.path / (frame_name(k) + ".png")) > 0);
    }
    // A fast stroke's swept stick parses and renders.
    {
      const auto shot = load(kTinyScene);
      const int strike = static_cast<int>(std::lround(shot->timeline.cue_time() * 30));
      test::TempDir dir;
      const test::CommandResult r = render_tiny(*shot, dir.path, {strike - 1, strike});
      CHECK_MESSAGE(r.exit_code == 0, r.out);
      CHECK(test::read_file(dir.path / (frame_name(strike) + ".pov")).value_or("").find("CueSweep(") !=
            std::string::npos);
    }
  }

  TEST_CASE("from above, POV-Ray's corner pocket is open where the physics drops a ball and cloth on its shelf") {
    test::require_program("povray");
    const auto shot = load(kCornerFromAbove);
    test::TempDir dir;
    REQUIRE(test::write_file(dir.path / std::string(kPovIncludeName), include_text(*shot)));
    REQUIRE(test::write_file(dir.path / (frame_name(0) + ".pov"), frame_text(*shot, 0)));
    const int width = 320, height = 180;
    const test::CommandResult r = test::run_command("cd '" + dir.path.string() + "' && povray -D +FP +WT1 +I" +
                                                    frame_name(0) + ".pov +Ocorner.ppm +W320 +H180 +Q9 -A 2>&1");
    REQUIRE_MESSAGE(r.exit_code == 0, r.out);
    // A binary PPM: its pixels are the last width x height x 3 bytes.
    const std::string ppm = test::read_file(dir.path / "corner.ppm").value_or("");
    REQUIRE(ppm.size() > static_cast<std::size_t>(width * height * 3));
    const std::string rgb = ppm.substr(ppm.size() - static_cast<std::size_t>(width * height * 3));
    const CameraView view(CameraPose{Vec3(1.27, 0.62, 0.5), Vec3(1.27, 0.62, 0), false}, kCameraFovDeg,
                          static_cast<double>(width) / height);
    const auto colour = [&](const Vec3& at) {
      const auto p = view.project(at);
      REQUIRE(p);
      const int x = static_cast<int>(0.5 * width * (1 + p->x)), y = static_cast<int>(0.5 * height * (1 - p->y));
      const auto* c = reinterpret_cast<const unsigned char*>(&rgb[3 * (static_cast<std::size_t>(y) * width + x)]);
      return std::array<int, 3>{c[0], c[1], c[2]};
    };
    const auto cloth = [](const std::array<int, 3>& c) { return c[1] > c[0] + 25 && c[1] > c[2] + 10; };
    const auto open = [](const std::array<int, 3>& c) { return std::max({c[0], c[1], c[2]}) < 90 && c[1] < c[0] + 15; };
    const auto text = [](const std::array<int, 3>& c) {
      return std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]);
    };
    const PocketMouth m = table_layout(shot->scene).pockets[2];
    REQUIRE(m.cut);
    // The physics' hole, round: open 5 mm inside its edge all round, and in its middle.
    CHECK_MESSAGE(open(colour(m.centre)), text(colour(m.centre)));
    for (int k = 0; k < 16; ++k) {
      const double a = 2 * std::numbers::pi * k / 16;
      const Vec3 inside = m.centre + (m.drop_radius - 0.005) * Vec3(std::cos(a), std::sin(a), 0);
      CAPTURE(k);
      CHECK_MESSAGE(open(colour(inside)), text(colour(inside)));
    }
    // The shelf before the hole, between the facings: cloth, up to 5 mm from the hole's rounded lip.
    const Vec3 middle = (m.nose[0] + m.nose[1]) / 2;
    for (const Vec3& at : {Vec3(middle + m.axis * 0.01), Vec3(middle + m.axis * (m.shelf() / 2)),
                           Vec3(m.centre - m.axis * (m.drop_radius + kStandardTable.jaws.lip_round + 0.005))})
      CHECK_MESSAGE(cloth(colour(at)), text(colour(at)));
  }
}
