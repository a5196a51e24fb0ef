// Tracing only what changed (export/changed_region.h) makes the same pictures as tracing every pixel:
// every frame of two scenes, rendered both ways by POV-Ray at final quality (the preset whose
// adaptive antialiasing shares samples within a render block and whose area light is sampled
// adaptively: what could make a partial render differ), compared pixel for pixel.
#include <doctest/doctest.h>

#include <filesystem>
#include <regex>

#include "changed_region.h"
#include "files.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  REQUIRE(std::regex_search(json, m, std::regex("\"" + key + "\": ?([0-9.]+)")));
  return std::stod(m[1]);
}

/// Renders `scene` (empty: the built-in break) into `out` with the frame store off, so that every
/// frame is traced in this run.
void render(const std::string& scene, const fs::path& out, int fps, const std::string& extra) {
  const test::CommandResult r = test::run_command(
      "BSIM_CACHE_DIR=off " + quoted(test::bin("billiards-export")) + " " + scene + " -o " + quoted(out.string()) +
      " --size 320x180 --quality final --quiet --fps " + std::to_string(fps) + " " + extra);
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
}

/// Renders the scene both ways and compares every frame. The PNGs are compared byte for byte: the
/// develop stage writes the same bytes for the same pixels (develop.h), so equal bytes are equal
/// pixels and any pixel that differs shows.
void same_both_ways(const std::string& scene, int fps) {
  test::TempDir dir;
  render(scene, dir.path / "whole", fps, "--whole-frames");
  render(scene, dir.path / "partial", fps, "");
  const std::string summary = test::require_file(dir.path / "partial" / "run.json");
  // The path under test was taken: some frames were traced in part, and less than every pixel.
  CHECK(json_number(summary, "partial") >= 3);
  CHECK(json_number(summary, "traced") < 0.9);
  CHECK(json_number(test::require_file(dir.path / "whole" / "run.json"), "partial") == 0);
  int frames = 0;
  for (const auto& e : fs::directory_iterator(dir.path / "whole" / "frames")) {
    if (e.path().extension() != ".png") continue;
    ++frames;
    const auto whole = test::read_file(e.path());
    const auto partial = test::read_file(dir.path / "partial" / "frames" / e.path().filename());
    REQUIRE(whole);
    REQUIRE_MESSAGE(partial, e.path().filename().string());
    const std::string name = e.path().filename().string();
    CHECK_MESSAGE(*whole == *partial, name);
  }
  CHECK(frames >= 8);
}

}  // namespace

TEST_SUITE("partial frames") {
  TEST_CASE("the built-in break, traced only where it changed, is the whole-frame render pixel for pixel") {
    test::require_program("povray");
    test::require_program("ffmpeg");
    same_both_ways("", 1);  // 11 frames: the stick's strokes, the spread, the balls coming to rest
  }

  TEST_CASE("a bank shot with the stick, traced only where it changed, is the whole-frame render pixel for pixel") {
    test::require_program("povray");
    test::require_program("ffmpeg");
    same_both_ways(quoted(test::source_path("scenes/bank.scn").string()), 2);
  }

  TEST_CASE("regions: rectangles on the block grid merge when one round both costs less") {
    // Two blocks side by side: one rectangle of two blocks costs less than two starts.
    const std::vector<PixelRect> two = merge_regions({{0, 0, 32, 32}, {32, 0, 64, 32}});
    REQUIRE(two.size() == 1);
    CHECK(two[0] == PixelRect{0, 0, 64, 32});
    // Far apart (the box round both would trace 40 blocks more): kept apart.
    CHECK(merge_regions({{0, 0, 32, 32}, {320, 320, 352, 352}}).size() == 2);
    // One inside another goes; empty ones go.
    CHECK(merge_regions({{0, 0, 128, 128}, {32, 32, 64, 64}, {64, 64, 64, 96}}).size() == 1);
  }
}
