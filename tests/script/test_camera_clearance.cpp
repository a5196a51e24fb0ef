// The camera's clearance: a camera inside the table, below the floor, inside the lamp or too close
// to a ball gets one located warning per span of time (the run goes on); the shipped scenes get none.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "builtin_scene.h"
#include "camera_clearance.h"
#include "files.h"
#include "shot.h"
#include "support.h"
#include "table.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

// The cue ball (index 0) runs along y = 0 to the right cushion (event 2) and back; ball 1 rests at
// (0.5, 0.3).
const std::string kBalls =
    "cue 0 0\n"
    "ball 0 -0.5 0 0.028575 1.5 0 0 1 0 0 0\n"
    "ball 1 0.5 0.3 0.028575 0 0 0 1 0 0 0\n";
/// A good camera: high over the near long side, looking at the middle.
const std::string kGood = "hover 0 -2.5 2 0 0 0";

struct Loaded {
  ShotResult result;
  std::vector<Diagnostic> warnings;
};

/// Loads kBalls and the camera lines (the first on line 5) and collects the warnings.
Loaded load(const std::vector<std::string>& lines) {
  std::string text = kBalls + "camera\n";
  for (const std::string& line : lines) text += line + "\n";
  Loaded loaded{load_shot(text + "endcamera\n", "clearance"), {}};
  REQUIRE(loaded.result.scripted());
  for (const Diagnostic& d : loaded.result.diagnostics) {
    CHECK(d.severity == Severity::warning);
    if (d.severity == Severity::warning) loaded.warnings.push_back(d);
  }
  return loaded;
}

double event_time(const Loaded& loaded, int event) {
  return loaded.result.shot->timeline.events()[static_cast<std::size_t>(event)].time;
}

/// Within the 2-decimal printing of a span's end (and the 0.1 ms its ends are found to).
bool near(double printed, double exact) { return std::abs(printed - exact) <= 0.0051; }

double duration(const Loaded& loaded) { return loaded.result.shot->timeline.duration(); }

/// The span a warning names, "from A s to B s".
std::pair<double, double> span(const Diagnostic& d) {
  std::smatch m;
  const std::regex from(R"(from (-?[0-9.]+) s to (-?[0-9.]+) s)");
  REQUIRE_MESSAGE(std::regex_search(d.message, m, from), d.message);
  return {std::stod(m[1].str()), std::stod(m[2].str())};
}

/// Checks the one warning is at line `line`, column 1, starts with `start` and spans [begin, end].
void check_one(const Loaded& loaded, int line, const std::string& start, double begin, double end) {
  REQUIRE(loaded.warnings.size() == 1);
  const Diagnostic& d = loaded.warnings[0];
  CHECK(d.loc.line == line);
  CHECK(d.loc.column == 1);
  CHECK_MESSAGE(d.message.rfind(start, 0) == 0, d.message);
  const std::pair<double, double> named = span(d);  // no structured binding: the checks below capture
  const double from = named.first, to = named.second;
  CHECK_MESSAGE(near(from, begin), d.message << " (from " << begin << ")");
  CHECK_MESSAGE(near(to, end), d.message << " (to " << end << ")");
}

}  // namespace

TEST_SUITE("camera clearance") {
  TEST_CASE("a good script has no warning") {
    const Loaded loaded =
        load({"event 0 0 0 " + kGood, "event 1 0.5 0.5 look 1.9 -1.2 1.0 0", "event 2 0.5 0 " + kGood});
    CHECK(loaded.warnings.empty());
  }

  TEST_CASE("inside the table: below the rails' top over the bed") {
    const Loaded loaded = load({"event 0 0 0 " + kGood, "event 1 0 0 hover 0 -0.5 0.02 0 0 0"});
    check_one(loaded, 6, "the camera is inside the table from ", event_time(loaded, 1), duration(loaded));
    CHECK(loaded.warnings[0].message.find("(down to z = 0.020 m)") != std::string::npos);
    CHECK(loaded.warnings[0].message.find("z = 0.048 m") != std::string::npos);
    CHECK(format_diagnostic(loaded.warnings[0], "clearance.scn").rfind("clearance.scn:6:1: warning: the camera", 0) ==
          0);
  }

  TEST_CASE("inside the table: beside the cushion, below the wood's top") {
    // Over the wooden rail at the right end, 3 cm above the bed: in the wood.
    const double x = kStandardTable.half_length + kStandardTable.cushion.width + 0.5 * kStandardTable.rail.width;
    const Loaded loaded = load({"event 0 0 0 hover " + std::to_string(x) + " 0.4 0.03 0 0 0", "event 1 0 0 " + kGood});
    check_one(loaded, 5, "the camera is inside the table from ", 0.0, event_time(loaded, 1));
  }

  TEST_CASE("inside the table: under the bed") {
    const Loaded loaded = load({"event 0 0 0 " + kGood, "event 2 0 0 hover 0.2 -0.3 -0.4 0 0 0"});
    check_one(loaded, 6, "the camera is inside the table from ", event_time(loaded, 2), duration(loaded));
  }

  TEST_CASE("below the floor beside the table") {
    const Loaded loaded = load({"event 0 0 0 " + kGood, "event 1 0 0 hover 0 -2.5 -0.9 0 0 0", "event 2 0 0 " + kGood});
    check_one(loaded, 6, "the camera is below the floor from ", event_time(loaded, 1), event_time(loaded, 2));
    CHECK(loaded.warnings[0].message.find("z = -0.760 m") != std::string::npos);
  }

  TEST_CASE("low beside the table but above the floor is fine") {
    const Loaded loaded = load({"event 0 0 0 hover 0 -1.5 -0.5 0 0 0"});
    CHECK(loaded.warnings.empty());
  }

  TEST_CASE("inside the lamp") {
    const Loaded loaded = load({"event 0 0 0 hover 0.3 0.1 1.1 0 0 0", "event 1 0 0 " + kGood});
    check_one(loaded, 5, "the camera is inside the lamp over the table from ", 0.0, event_time(loaded, 1));
  }

  TEST_CASE("just under the lamp is fine") {
    const Loaded loaded = load({"event 0 0 0 hover 0.3 0.1 1.0 0 0 0"});
    CHECK(loaded.warnings.empty());
  }

  TEST_CASE("too close to a resting ball") {
    // 0.1 m beside ball 1 and 0.07 m above its centre: 0.123 m from it.
    const Loaded loaded = load({"event 0 0 0 " + kGood, "event 1 0 0 look 0.5 0.4 0.1 1", "event 2 0 0 " + kGood});
    check_one(loaded, 6, "the camera is too close to ball 1 from ", event_time(loaded, 1), event_time(loaded, 2));
    CHECK(loaded.warnings[0].message.find("(0.123 m from its centre)") != std::string::npos);
    CHECK(loaded.warnings[0].message.find("at least 0.149 m") != std::string::npos);
  }

  TEST_CASE("a follow camera too close to its ball, for the whole shot") {
    const Loaded loaded = load({"event 0 0 0 follow 0 -0.1 0 0.05"});
    check_one(loaded, 5, "the camera is too close to ball 0 from ", 0.0, duration(loaded));
  }

  TEST_CASE("two spans, two warnings, each at its description") {
    const Loaded loaded =
        load({"event 0 0 0 hover 0.3 0.1 1.1 0 0 0", "event 1 0 0 " + kGood, "event 2 0 0 hover -0.3 0 1.12 0 0 0"});
    REQUIRE(loaded.warnings.size() == 2);
    CHECK(loaded.warnings[0].loc.line == 5);
    CHECK(loaded.warnings[1].loc.line == 7);
    CHECK(near(span(loaded.warnings[0]).second, event_time(loaded, 1)));
    CHECK(near(span(loaded.warnings[1]).first, event_time(loaded, 2)));
  }

  TEST_CASE("the shipped scenes and the built-in break keep the camera clear") {
    std::vector<std::pair<std::string, std::string>> scenes{{"built-in break", std::string(builtin_scene_text())}};
    for (const auto& entry : fs::directory_iterator(test::source_path("scenes"))) {
      if (entry.path().extension() == ".scn")
        scenes.push_back({entry.path().filename().string(), test::require_file(entry.path())});
    }
    CHECK(scenes.size() >= 8);
    for (const auto& scene : scenes) {
      const std::string name = scene.first;
      CAPTURE(name);
      const ShotResult result = load_shot(scene.second, name);
      REQUIRE(result.scripted());
      for (const Diagnostic& d : result.diagnostics) CHECK_MESSAGE(false, format_diagnostic(d, name));
    }
  }

  TEST_CASE("billiards-export warns on stderr and still exits 0") {
    test::TempDir tmp;
    const std::string scene = tmp.file(
        "low.scn", kBalls + "camera\nevent 0 0 0 " + kGood + "\nevent 1 0 0 hover 0 -0.5 0.02 0 0 0\nendcamera\n");
    const std::string out = (tmp.path / "o").string();
    const test::CommandResult r = test::run_command(quoted(test::bin("billiards-export")) + " " + quoted(scene) +
                                                    " --events-only -o " + quoted(out));
    CHECK(r.exit_code == 0);
    CHECK_MESSAGE(r.err.find(scene + ":6:1: warning: the camera is inside the table from ") != std::string::npos,
                  r.err);
    CHECK(r.err.find("error") == std::string::npos);
    CHECK(fs::exists(fs::path(out) / "events.json"));
  }
}
