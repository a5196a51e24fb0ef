// billiards-preview's command line: every option, which ones go together, and one-line reasons
// (exit 2) for the rest.
#include <doctest/doctest.h>

#include <algorithm>

#include "preview_options.h"
#include "support.h"

using namespace bsim;

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
  CHECK_FALSE(message.empty());
  return message;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("preview command line") {
  TEST_CASE("defaults: the interactive window on the built-in scene") {
    const PreviewOptions o = accepted({});
    CHECK_FALSE(o.scene_path);
    CHECK_FALSE(o.output);
    CHECK(o.at.empty());
    CHECK_FALSE(o.timeline);
    CHECK_FALSE(o.movie);
    CHECK(o.width == 1280);
    CHECK(o.height == 720);
    CHECK_FALSE(o.size_given);
    CHECK(o.fps == 30);
    CHECK_FALSE(o.overlays.paths);
    CHECK_FALSE(o.overlays.events);
    CHECK_FALSE(o.overlays.camera);
    CHECK_FALSE(o.overlays.table);
    CHECK_FALSE(o.strict);
    CHECK(o.quit_after == 0);
    CHECK_FALSE(o.screenshot);
  }

  TEST_CASE("--at takes seconds or event:N") {
    const PreviewOptions seconds = accepted({"s.scn", "--at", "1.5", "-o", "f.png", "--size", "320x180"});
    REQUIRE(seconds.at.size() == 1);
    CHECK(seconds.at[0].seconds == 1.5);
    CHECK(seconds.at[0].event == -1);
    CHECK(*seconds.output == "f.png");
    CHECK(*seconds.scene_path == "s.scn");
    CHECK(seconds.width == 320);
    CHECK(seconds.height == 180);
    CHECK(seconds.size_given);
    const PreviewOptions event = accepted({"--at=event:3", "--output", "f.png"});
    REQUIRE(event.at.size() == 1);
    CHECK(event.at[0].event == 3);
    // shot:K counts from 1, as `shot K` camera keys do; its picture is named after it.
    const PreviewOptions shot = accepted({"--at", "shot:2", "--at", "1", "-o", "shots/"});
    REQUIRE(shot.at.size() == 2);
    CHECK(shot.at[0].shot == 2);
    CHECK(shot.at[0].event == -1);
    CHECK(shot.at[1].shot == 0);
    CHECK(shot.pictures[0] == "shots/at_shot_2.png");
  }

  TEST_CASE("--timeline, --movie, --overlay, --fps, --strict") {
    const PreviewOptions timeline = accepted({"--timeline", "-o", "t.png"});
    CHECK(timeline.timeline);
    CHECK(accepted({"--at", "1", "-o", "f.png", "--overlay", "events"}).overlays.events);
    const PreviewOptions movie =
        accepted({"--movie", "a.mp4", "--fps", "12", "--overlay", "paths,camera,events", "--strict"});
    CHECK(*movie.movie == "a.mp4");
    CHECK(movie.fps == 12);
    CHECK(movie.overlays.paths);
    CHECK(movie.overlays.camera);
    CHECK(movie.overlays.events);
    CHECK(movie.overlays.any());
    CHECK_FALSE(PreviewOverlays{}.any());
    for (bool PreviewOverlays::*flag : {&PreviewOverlays::paths, &PreviewOverlays::events, &PreviewOverlays::camera,
                                        &PreviewOverlays::table, &PreviewOverlays::aim}) {
      PreviewOverlays one;
      one.*flag = true;
      CHECK(one.any());  // every overlay, the table's numbers included, is drawn on the animatic's frames
    }
    CHECK_FALSE(movie.overlays.table);
    CHECK(movie.strict);
    CHECK(accepted({"--at", "0", "-o", "n.png", "--overlay", "table"}).overlays.table);
  }

  TEST_CASE("interactive options") {
    const PreviewOptions o = accepted({"--quit-after", "0.5", "--screenshot", "last.png", "--overlay", "paths"});
    CHECK(o.quit_after == 0.5);
    CHECK(*o.screenshot == "last.png");
  }

  TEST_CASE("bad values") {
    CHECK(contains(rejection({"--at", "soon", "-o", "f.png"}), "bad value 'soon' for --at"));
    CHECK(contains(rejection({"--at", "-1", "-o", "f.png"}), "--at"));
    CHECK(contains(rejection({"--at", "event:x", "-o", "f.png"}), "--at"));
    // Shots count from 1: shot:0 is no shot; the message says what is accepted.
    CHECK(contains(rejection({"--at", "shot:0", "-o", "f.png"}), "bad value 'shot:0' for --at"));
    CHECK(contains(rejection({"--at", "shot:0", "-o", "f.png"}), "shot:K from 1"));
    CHECK(contains(rejection({"--at", "shot:two", "-o", "f.png"}), "bad value 'shot:two' for --at"));
    CHECK(contains(rejection({"--at", "shot:", "-o", "f.png"}), "--at"));
    CHECK(contains(rejection({"--size", "12"}), "bad value '12' for --size"));
    CHECK(contains(rejection({"--fps", "0", "--movie", "a.mp4"}), "--fps"));
    CHECK(contains(rejection({"--overlay", "paths,stars"}), "bad value 'paths,stars' for --overlay"));
    CHECK(contains(rejection({"--overlay", ""}), "--overlay"));
    CHECK(contains(rejection({"--quit-after", "0"}), "--quit-after"));
    CHECK(rejection({"--bogus"}) == "unknown option '--bogus' (see --help)");
    CHECK(rejection({"--at"}) == "--at needs a value");
    CHECK(rejection({"a.scn", "b.scn"}) == "more than one scene given: 'a.scn' and 'b.scn'");
  }

  TEST_CASE("options that must or must not go together") {
    CHECK(contains(rejection({"--at", "1"}), "--at needs -o"));
    CHECK(contains(rejection({"--timeline"}), "--timeline needs -o"));
    CHECK(contains(rejection({"--at", "1", "--timeline", "-o", "f.png"}), "give only one"));
    CHECK(contains(rejection({"-o", "f.png"}), "give one of them"));
    CHECK(contains(rejection({"--movie", "a.mp4", "--at", "1", "-o", "f.png"}), "--movie cannot be combined"));
    CHECK(contains(rejection({"--screenshot", "s.png", "--movie", "a.mp4"}), "interactive window only"));
    CHECK(contains(rejection({"--quit-after", "1", "--timeline", "-o", "t.png"}), "interactive window only"));
  }

  TEST_CASE("an option that does nothing beside the others is a mistake, as in billiards-export") {
    CHECK(rejection({"--at", "1", "-o", "f.png", "--fps", "24"}) ==
          "--fps does nothing with --at (it draws instants, not frames); leave one of them out");
    CHECK(rejection({"--timeline", "-o", "t.png", "--fps", "24"}).starts_with("--fps does nothing with --timeline"));
    CHECK(rejection({"--timeline", "-o", "t.png", "--overlay", "paths"})
              .starts_with("--overlay does nothing with --timeline"));
    CHECK(rejection({"--write-camera", "-", "--size", "64x36"})
              .starts_with("--size does nothing with --write-camera alone"));
    CHECK(rejection({"--write-scene", "s.scn", "--overlay", "aim"})
              .starts_with("--overlay does nothing with --write-scene alone"));
    // Where they do something, they are taken: the animatic's frames, the window's steps.
    CHECK(accepted({"--movie", "a.mp4", "--fps", "12", "--size", "64x36"}).fps == 12);
    CHECK(accepted({"--fps", "12"}).fps == 12);
    CHECK(accepted({"--write-camera", "-", "--at", "1", "-o", "f.png", "--size", "64x36"}).width == 64);
  }

  TEST_CASE("--help lists every option with its default; --version names the program") {
    PreviewOptions o;
    std::string help;
    REQUIRE(parse_preview_options({"--help"}, o, help) == PreviewCommandLineOutcome::exit_success);
    for (const char* option : {"--at SECONDS|event:N", "--timeline", "-o", "--movie FILE.mp4", "--size WxH", "--fps N",
                               "--overlay LIST", "--strict", "--quit-after SECONDS", "--screenshot FILE.png", "--help",
                               "--version", "(default: 1280x720)", "(default: 30)"})
      CHECK_MESSAGE(contains(help, option), option);
    std::string version;
    REQUIRE(parse_preview_options({"--version"}, o, version) == PreviewCommandLineOutcome::exit_success);
    CHECK(version == std::string("billiards-preview ") + BSIM_VERSION + "\n");
  }

  TEST_CASE("the binary exits 2 with one line for a bad command line") {
    for (const std::string args : {"--at 1", "--size 12 --timeline -o x.png", "--bogus", "--overlay stars"}) {
      CAPTURE(args);
      const test::CommandResult r = test::run_command("'" + test::bin("billiards-preview") + "' " + args);
      CHECK(r.exit_code == 2);
      CHECK(r.err.starts_with("billiards-preview: "));
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
  }
}
