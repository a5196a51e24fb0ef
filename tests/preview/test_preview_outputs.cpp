// billiards-preview's outputs: several --at times drawn in one run into a directory or a %t pattern,
// each picture the same bytes as its own single --at run; and the file names checked for the
// extension of what they hold (.png pictures, .mp4 animatic), a wrong one a usage error.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "fixtures.h"
#include "preview_options.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
using bsim::test::require_file;
using bsim::test::run_command;
using bsim::test::TempDir;
namespace fs = std::filesystem;

namespace {

PreviewOptions accepted(std::vector<std::string> args) {
  PreviewOptions o;
  std::string message;
  const PreviewCommandLineOutcome outcome = parse_preview_options(args, o, message);
  INFO(message);
  CHECK(outcome == PreviewCommandLineOutcome::run);
  return o;
}

std::string rejection(std::vector<std::string> args) {
  PreviewOptions o;
  std::string message;
  CHECK(parse_preview_options(args, o, message) == PreviewCommandLineOutcome::exit_usage);
  CHECK(message.find('\n') == std::string::npos);
  return message;
}

test::CommandResult preview(const std::string& args) {
  return run_command(quoted(test::bin("billiards-preview")) + " " + args);
}

}  // namespace

TEST_SUITE("preview outputs") {
  TEST_CASE("one --at and -o FILE.png: that file, as before") {
    const PreviewOptions o = accepted({"--at", "1.5", "-o", "f.png"});
    REQUIRE(o.at.size() == 1);
    CHECK(o.pictures == std::vector<std::string>{"f.png"});
    CHECK_FALSE(o.picture_dir);
  }

  TEST_CASE("several --at: -o DIR/ names at_SECONDS.png and at_event_N.png inside it") {
    const PreviewOptions o = accepted({"--at", "0.5", "--at", "1", "--at=event:3", "--at", "2.25", "-o", "shots/"});
    REQUIRE(o.at.size() == 4);
    CHECK(o.at[2].event == 3);
    CHECK(o.pictures == std::vector<std::string>{"shots/at_0.500.png", "shots/at_1.000.png", "shots/at_event_3.png",
                                                 "shots/at_2.250.png"});
    CHECK(o.picture_dir == std::optional<std::string>("shots/"));
    TempDir dir;  // an existing directory needs no slash
    const std::string existing = dir.path.string();
    const PreviewOptions in_existing = accepted({"--at", "0.5", "--at", "1", "-o", existing});
    CHECK(in_existing.pictures == std::vector<std::string>{existing + "/at_0.500.png", existing + "/at_1.000.png"});
  }

  TEST_CASE("several --at: a pattern's %t becomes the time's label") {
    const PreviewOptions o = accepted({"--at", "0.5", "--at", "event:12", "-o", "out/shot_%t.PNG"});
    CHECK(o.pictures == std::vector<std::string>{"out/shot_0.500.PNG", "out/shot_event_12.PNG"});
    CHECK_FALSE(o.picture_dir);
    CHECK(accepted({"--at", "1", "-o", "%t_%t.png"}).pictures == std::vector<std::string>{"1.000_1.000.png"});
  }

  TEST_CASE("several --at need a directory or a pattern; two times may not share a picture") {
    CHECK(rejection({"--at", "0.5", "--at", "1", "-o", "f.png"}) ==
          "several --at write one picture each: -o needs a directory (e.g. shots/) or a name with %t (e.g. "
          "shot_%t.png), found 'f.png'");
    CHECK(rejection({"--at", "1", "--at", "1.0001", "-o", "shots/"}) ==
          "two --at times would both write 'shots/at_1.000.png'; give each time once");
    CHECK(rejection({"--at", "1", "--at", "2", "-o", "shot_%t.jpg"}) ==
          "bad value 'shot_%t.jpg' for -o: expected a name ending in .png (e.g. shot_%t.png)");
  }

  TEST_CASE("pictures end in .png and the animatic in .mp4, in any case") {
    CHECK(accepted({"--at", "1", "-o", "F.PNG"}).pictures == std::vector<std::string>{"F.PNG"});
    CHECK(accepted({"--timeline", "-o", "t.Png"}).output == std::optional<std::string>("t.Png"));
    CHECK(accepted({"--movie", "a.MP4"}).movie == std::optional<std::string>("a.MP4"));
    CHECK(rejection({"--at", "1", "-o", "frame.jpg"}) ==
          "bad value 'frame.jpg' for -o: expected a file name ending in .png (or, for --at, a directory or a name "
          "with %t)");
    CHECK(rejection({"--at", "1", "-o", ".png"}).starts_with("bad value '.png' for -o"));
    CHECK(rejection({"--timeline", "-o", "timeline"}) ==
          "bad value 'timeline' for -o: expected a file name ending in .png");
    CHECK(rejection({"--timeline", "-o", "shots/"}) ==
          "bad value 'shots/' for -o: expected a file name ending in .png");
    CHECK(rejection({"--movie", "tour.avi"}) ==
          "bad value 'tour.avi' for --movie: expected a file name ending in .mp4");
    CHECK(rejection({"--movie", "tour.mp4.png"}).starts_with("bad value 'tour.mp4.png' for --movie"));
  }

  TEST_CASE("the binary: a wrong extension is exit 2 with one line, and nothing is written") {
    TempDir dir;
    for (const std::string& args : {std::string("--at 1 -o ") + quoted((dir.path / "f.jpg").string()),
                                    std::string("--timeline -o ") + quoted((dir.path / "t.gif").string()),
                                    std::string("--movie ") + quoted((dir.path / "a.mov").string())}) {
      CAPTURE(args);
      const test::CommandResult r = preview(args);
      CHECK(r.exit_code == 2);
      CHECK(r.err.starts_with("billiards-preview: bad value '"));
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
    CHECK(fs::is_empty(dir.path));
  }

  TEST_CASE("the binary: several --at in one run, each the same bytes as its own run") {
    TempDir dir;
    const std::string scene = dir.file("cluster.scn", test::fixtures::cluster_scene());
    const std::string common = quoted(scene) + " --size 160x90 ";
    const fs::path shots = dir.path / "shots";
    const test::CommandResult r =
        preview(common + "--at 0.5 --at event:2 --at 1.25 -o " + quoted(shots.string() + "/"));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::vector<std::string> names = {"at_0.500.png", "at_event_2.png", "at_1.250.png"};
    for (const std::string& name : names)
      CHECK(r.err.find("wrote " + (shots / name).string() + "\n") != std::string::npos);
    CHECK(std::distance(fs::directory_iterator(shots), fs::directory_iterator()) == 3);

    const fs::path alone = dir.path / "alone.png";
    for (const auto& entry : {std::pair{"0.5", "at_0.500.png"}, std::pair{"event:2", "at_event_2.png"},
                              std::pair{"1.25", "at_1.250.png"}}) {
      const std::string at = entry.first, name = entry.second;  // plain names: CAPTURE cannot take a binding
      CAPTURE(name);
      REQUIRE(preview(common + "--at " + at + " -o " + quoted(alone.string())).exit_code == 0);
      CHECK(require_file(shots / name) == require_file(alone));
    }
    CHECK(require_file(shots / names[0]) != require_file(shots / names[2]));

    const test::CommandResult pattern =
        preview(common + "--at 0.5 --at 1.25 -o " + quoted((dir.path / "s_%t.png").string()));
    REQUIRE(pattern.exit_code == 0);
    CHECK(require_file(dir.path / "s_0.500.png") == require_file(shots / "at_0.500.png"));
    CHECK(require_file(dir.path / "s_1.250.png") == require_file(shots / "at_1.250.png"));
  }

  TEST_CASE("the binary: -o into a folder that is missing makes it, and every picture says `wrote`") {
    TempDir dir;
    const std::string scene = dir.file("cluster.scn", test::fixtures::cluster_scene());
    const std::string common = quoted(scene) + " --size 160x90 ";
    for (const auto& run : std::vector<std::pair<std::string, std::vector<fs::path>>>{
             {"--at 0.5 --at 1.25 -o " + quoted((dir.path / "takes/take_%t.png").string()),
              {dir.path / "takes/take_0.500.png", dir.path / "takes/take_1.250.png"}},
             {"--at 0.5 -o " + quoted((dir.path / "one/deeper/still.png").string()),
              {dir.path / "one/deeper/still.png"}},
             {"--timeline -o " + quoted((dir.path / "lines/timeline.png").string()), {dir.path / "lines/timeline.png"}},
         }) {
      const std::string& args = run.first;  // plain names: clang cannot capture a binding
      const std::vector<fs::path>& files = run.second;
      CAPTURE(args);
      const test::CommandResult r = preview(common + args);
      REQUIRE_MESSAGE(r.exit_code == 0, r.err);
      std::string expected;
      for (const fs::path& file : files) {
        CHECK(fs::is_regular_file(file));
        expected += "wrote " + file.string() + "\n";
      }
      // Every picture reported, in order (a sanitizer's note at exit may follow them).
      CAPTURE(r.err);
      CHECK(r.err.find(expected) != std::string::npos);
    }
  }

  TEST_CASE("the binary: a missing event among several is a usage error before any picture") {
    TempDir dir;
    const std::string scene = dir.file("cluster.scn", test::fixtures::cluster_scene());
    const fs::path shots = dir.path / "shots";
    const test::CommandResult r =
        preview(quoted(scene) + " --size 160x90 --at 0.5 --at event:999 -o " + quoted(shots.string() + "/"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--at event:999: this shot has") != std::string::npos);
    CHECK_FALSE(fs::exists(shots));
  }
}
