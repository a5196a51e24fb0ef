// Reading the scene file: both programs read it with the one reader and say the same words when
// they cannot: a directory is not a scene, and an unreadable file gets the system's reason.
#include <doctest/doctest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "fixtures.h"
#include "scene_file.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

/// Runs `program` on `scene` with an output that exists only if the program got past the scene.
test::CommandResult run_on(const std::string& program, const std::string& scene, const fs::path& out) {
  const std::string output = program == "billiards-export" ? " --events-only -o " + quoted(out.string())
                                                           : " --at 0.5 -o " + quoted((out / "x.png").string());
  return test::run_command(quoted(test::bin(program)) + " " + quoted(scene) + output);
}

}  // namespace

TEST_SUITE("scene file") {
  TEST_CASE("the reader: the text, or the line to print for a directory or an unreadable file") {
    test::TempDir dir;
    const std::string good = dir.file("good.scn", test::fixtures::kOneBall);
    std::string error;
    const std::optional<std::string> text = read_scene_file(good, error);
    REQUIRE(text);
    CHECK(*text == test::fixtures::kOneBall);
    CHECK(error.empty());
    const std::string empty = dir.file("empty.scn", "");
    CHECK(read_scene_file(empty, error) == std::optional<std::string>(""));

    const std::string folder = dir.path.string();
    CHECK_FALSE(read_scene_file(folder, error));
    CHECK(error == folder + ": error: is a directory, not a scene file");
    const std::string missing = (dir.path / "nowhere.scn").string();
    CHECK_FALSE(read_scene_file(missing, error));
    CHECK(error == missing + ": error: cannot read the scene file: " + std::strerror(ENOENT));
    const std::string under_a_file = good + "/x.scn";
    CHECK_FALSE(read_scene_file(under_a_file, error));
    CHECK(error == under_a_file + ": error: cannot read the scene file: " + std::strerror(ENOTDIR));
  }

  TEST_CASE("both programs: a directory given as the scene says so, exit 1, nothing written") {
    for (const std::string program : {"billiards-export", "billiards-preview"}) {
      CAPTURE(program);
      test::TempDir dir;
      const fs::path scene = dir.path / "scenes";
      fs::create_directory(scene);
      const test::CommandResult r = run_on(program, scene.string(), dir.path / "out");
      CHECK(r.exit_code == 1);
      CHECK(r.err == scene.string() + ": error: is a directory, not a scene file\n");
      CHECK_FALSE(fs::exists(dir.path / "out"));
    }
  }

  TEST_CASE("both programs: an unreadable scene file gives the reason, in the same words") {
    for (const std::string program : {"billiards-export", "billiards-preview"}) {
      CAPTURE(program);
      test::TempDir dir;
      const std::string missing = (dir.path / "nowhere.scn").string();
      const test::CommandResult r = run_on(program, missing, dir.path / "out");
      CHECK(r.exit_code == 1);
      CHECK(r.err == missing + ": error: cannot read the scene file: No such file or directory\n");
      const std::string under_a_file = dir.file("a.scn", test::fixtures::kOneBall) + "/b.scn";
      const test::CommandResult r2 = run_on(program, under_a_file, dir.path / "out");
      CHECK(r2.exit_code == 1);
      CHECK(r2.err == under_a_file + ": error: cannot read the scene file: Not a directory\n");
      CHECK_FALSE(fs::exists(dir.path / "out"));
    }
  }
}
