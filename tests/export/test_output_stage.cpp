// Outputs are written beside or inside the destination and appear there only on commit; a run
// that fails leaves neither files nor a new directory.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "files.h"
#include "output_stage.h"
#include "support.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

void write(const std::string& path, const std::string& text) { REQUIRE(test::write_file(path, text)); }

std::string read(const fs::path& path) { return test::require_file(path); }

/// Everything under `dir`, hidden entries included, as sorted relative paths.
std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) out.push_back(fs::relative(e.path(), dir).string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_SUITE("output_stage") {
  TEST_CASE("a new directory appears only on commit, with every staged file") {
    test::TempDir tmp;
    const fs::path dest = tmp.path / "out" / "shot";
    OutputStage stage;
    std::string error;
    REQUIRE(stage.open(dest.string(), error));
    write(stage.path("events.json"), "{}");
    write(stage.path("frames/frame_00000.pov"), "// frame");
    CHECK_FALSE(fs::exists(dest));
    CHECK_FALSE(fs::exists(tmp.path / "out"));  // not even its parent is created early
    CHECK(fs::path(stage.staging()).parent_path() != dest);

    REQUIRE(stage.commit(error));
    CHECK(read(dest / "events.json") == "{}");
    CHECK(read(dest / "frames" / "frame_00000.pov") == "// frame");
    CHECK_FALSE(fs::exists(stage.staging()));
    CHECK(listing(tmp.path) == std::vector<std::string>{"out", "out/shot", "out/shot/events.json", "out/shot/frames",
                                                        "out/shot/frames/frame_00000.pov"});
  }

  TEST_CASE("a stage that is never committed leaves nothing behind") {
    test::TempDir tmp;
    const fs::path dest = tmp.path / "shot";
    {
      OutputStage stage;
      std::string error;
      REQUIRE(stage.open(dest.string(), error));
      write(stage.path("events.json"), "{}");
      CHECK(fs::exists(stage.staging()));
    }
    CHECK(listing(tmp.path).empty());
  }

  TEST_CASE("discard removes the staging directory and keeps the destination as it was") {
    test::TempDir tmp;
    const fs::path dest = tmp.path / "shot";
    fs::create_directory(dest);
    write((dest / "events.json").string(), "old");
    OutputStage stage;
    std::string error;
    REQUIRE(stage.open(dest.string(), error));
    write(stage.path("events.json"), "new");
    stage.discard();
    CHECK(listing(tmp.path) == std::vector<std::string>{"shot", "shot/events.json"});
    CHECK(read(dest / "events.json") == "old");
  }

  TEST_CASE("commit into an existing directory: staged files and folders replace theirs whole, others stay") {
    test::TempDir tmp;
    const fs::path dest = tmp.path / "shot";
    fs::create_directories(dest / "frames");
    write((dest / "events.json").string(), "old");
    write((dest / "frames" / "frame_00000.png").string(), "png");
    write((dest / "notes.txt").string(), "mine");
    write((dest / "movie.mp4").string(), "an older run's");
    OutputStage stage;
    std::string error;
    REQUIRE(stage.open(dest.string(), error));
    CHECK(fs::path(stage.staging()).parent_path() == dest);  // one file system for the renames
    write(stage.path("events.json"), "new");
    write(stage.path("frames/frame_00000.pov"), "pov");
    REQUIRE(stage.commit(error, {"events.json", "frames", "soundtrack.wav", "movie.mp4"}));
    CHECK(read(dest / "events.json") == "new");
    CHECK(read(dest / "frames" / "frame_00000.pov") == "pov");
    // The older frames folder went whole; the older movie this run did not make stays, named as
    // kept, and so does the file no run makes.
    CHECK(read(dest / "notes.txt") == "mine");
    CHECK(read(dest / "movie.mp4") == "an older run's");
    CHECK(stage.kept() == std::vector<std::string>{"movie.mp4"});
    CHECK(listing(dest) ==
          std::vector<std::string>{"events.json", "frames", "frames/frame_00000.pov", "movie.mp4", "notes.txt"});
  }

  TEST_CASE("an output this run makes after the commit (a farm's movie) replaces an older one: it goes at the commit") {
    test::TempDir tmp;
    const fs::path dest = tmp.path / "farm";
    fs::create_directories(dest);
    write((dest / "movie.mp4").string(), "an older run's");
    write((dest / "soundtrack.wav").string(), "an older run's");
    OutputStage stage;
    std::string error;
    REQUIRE(stage.open(dest.string(), error));
    write(stage.path("events.json"), "new");
    REQUIRE(stage.commit(error, {"events.json", "soundtrack.wav", "movie.mp4"}, {"movie.mp4"}));
    CHECK_FALSE(fs::exists(dest / "movie.mp4"));
    CHECK(stage.kept() == std::vector<std::string>{"soundtrack.wav"});
  }

  TEST_CASE("an output path that is a regular file is an error and stays untouched") {
    test::TempDir tmp;
    const std::string file = tmp.file("shot", "precious");
    OutputStage stage;
    std::string error;
    CHECK_FALSE(stage.open(file, error));
    CHECK(error.find("exists and is not a directory") != std::string::npos);
    CHECK(read(file) == "precious");
    CHECK(listing(tmp.path) == std::vector<std::string>{"shot"});
  }

  TEST_CASE("a relative destination stages in the working directory's tree") {
    test::TempDir tmp;
    struct WorkingDirectory {
      fs::path old = fs::current_path();
      ~WorkingDirectory() { fs::current_path(old); }
    } restore;
    fs::current_path(tmp.path);
    OutputStage stage;
    std::string error;
    REQUIRE(stage.open("shot", error));
    write(stage.path("camera.csv"), "frame");
    REQUIRE(stage.commit(error));
    CHECK(listing(tmp.path) == std::vector<std::string>{"shot", "shot/camera.csv"});
  }
}
