// The options both programs take (--fps, --size, --strict, --quiet) are read in one place: the same
// defaults, the same accepted forms and the same words for a bad value in billiards-export and
// billiards-preview.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "command_line.h"
#include "export_options.h"
#include "option_rejection.h"
#include "preview_options.h"
#include "scene_parse.h"

using namespace bsim;
using bsim::test::export_rejection;
using bsim::test::preview_rejection;

namespace {

/// A program's --help with each run of whitespace made one space (its help column wraps).
template <class Options, class Parse>
std::string flat_help(Parse parse) {
  Options options;
  std::string usage;
  parse(std::vector<std::string>{"--help"}, options, usage);
  std::string flat;
  for (char c : usage)
    if (c != ' ' && c != '\n')
      flat += c;
    else if (!flat.empty() && flat.back() != ' ')
      flat += ' ';
  return flat;
}

}  // namespace

TEST_SUITE("shared options") {
  TEST_CASE("the same defaults") {
    ExportOptions e;
    PreviewOptions p;
    std::string message;
    REQUIRE(parse_export_options({}, e, message) == CommandLineOutcome::run);
    REQUIRE(parse_preview_options({}, p, message) == PreviewCommandLineOutcome::run);
    const SharedOptions defaults;
    CHECK(e.fps == defaults.fps);
    CHECK(p.fps == defaults.fps);
    CHECK(e.width == defaults.width);
    CHECK(p.width == defaults.width);
    CHECK(e.height == p.height);
    CHECK_FALSE(e.strict);
    CHECK_FALSE(p.strict);
    CHECK_FALSE(e.quiet);
    CHECK_FALSE(p.quiet);
    CHECK_FALSE(e.size_given);
    CHECK_FALSE(p.size_given);
  }

  TEST_CASE("the same accepted forms") {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"--fps", "24", "--size", "640x360", "--strict", "--quiet"},
          std::vector<std::string>{"--fps=24", "--size=640x360", "--strict", "--quiet"}}) {
      ExportOptions e;
      PreviewOptions p;
      std::string message;
      REQUIRE(parse_export_options(args, e, message) == CommandLineOutcome::run);
      REQUIRE(parse_preview_options(args, p, message) == PreviewCommandLineOutcome::run);
      for (const SharedOptions* o : {static_cast<const SharedOptions*>(&e), static_cast<const SharedOptions*>(&p)}) {
        CHECK(o->fps == 24);
        CHECK(o->width == 640);
        CHECK(o->height == 360);
        CHECK(o->size_given);
        CHECK(o->strict);
        CHECK(o->quiet);
      }
    }
  }

  TEST_CASE("the same words for a bad value, from the one reader") {
    const std::vector<std::vector<std::string>> bad = {
        {"--fps", "0"},     {"--fps", "2.5"},       {"--fps", "1001"}, {"--fps"},        {"--size", "12"},
        {"--size", "0x10"}, {"--size", "+640x360"}, {"--size"},        {"--strict=yes"}, {"--quiet=yes"}};
    for (const auto& args : bad) {
      CAPTURE(args.front());
      const std::string message = export_rejection(args);
      CHECK_FALSE(message.empty());
      CHECK(message == preview_rejection(args));
      // The message is the shared reader's own.
      ArgReader reader(args);
      REQUIRE(reader.next());
      SharedOptions o;
      std::string shared;
      CHECK(apply_shared_option(reader, o, shared) == SharedOption::bad);
      CHECK(shared == message);
    }
    CHECK(export_rejection({"--fps", "0"}) ==
          "bad value '0' for --fps: expected a whole number of frames per second from 1 to 1000");
    CHECK(export_rejection({"--size", "12"}) ==
          "bad value '12' for --size: expected WIDTHxHEIGHT in pixels, e.g. 1280x720, each from 1 to 16384");
    CHECK(export_rejection({"--strict=yes"}) == "--strict takes no value, found 'yes'");
    CHECK(export_rejection({"--bogus"}) == preview_rejection({"--bogus"}));
  }

  TEST_CASE("an option neither shares is left to its program") {
    const std::vector<std::string> args = {"--jobs", "2"};
    ArgReader reader(args);
    REQUIRE(reader.next());
    SharedOptions o;
    std::string message;
    CHECK(apply_shared_option(reader, o, message) == SharedOption::not_shared);
    CHECK(message.empty());
    CHECK(unknown_option_message("--jobs") == "unknown option '--jobs' (see --help)");
  }

  TEST_CASE("--strict's help names each extension --strict rejects, in both programs") {
    const std::string camera = "camera\nevent 0 0 0 hover 0 -2 2 0 0 0\nendcamera\n";
    const std::string rolling = "ball 0 0 0 0.028575 1 0 0 1 0 0 0\n";  // set going by its line, as in the seed
    const std::string still = "ball 0 0 0 0.028575 0 0 0 1 0 0 0\n";
    const std::string seed = "cue 0 0\n" + rolling + camera;
    const std::string stroked = "cue 0 0\nstroke 2 0 0 0\n" + still + camera;
    // Each extension as --help names it, and a scene that uses it (the seed's form otherwise).
    const std::vector<std::pair<std::string, std::string>> extensions = {
        {"comments", "# a comment\n" + seed},
        {"spin", seed + "spin 0 1 0 0\n"},
        {"pocket", seed + "pocket -1.27 0.635 0 0.08 pocket 0 0.635 0 0.065 pocket 1.27 0.635 0 0.08\n"
                          "pocket 1.27 -0.635 0 0.08 pocket 0 -0.635 0 0.065 pocket -1.27 -0.635 0 0.08\n"},
        {"short ball line", seed + "ball 1 0.5 0\n"},
        {"param", seed + "param mu_roll 0.01\n"},
        {"rack", seed + "rack 9ball\n"},
        {"stroke", stroked},
        {"place", stroked + "cue 0 0\nstroke 2 0 0 0\nplace 0\n"},
        {"pot", "cue 0 pot 1 2\n" + rolling + "ball 1 0.5 0 0.028575 0 0 0 1 0 0 0\n" + camera},
        {"second cue line", stroked + "cue 0 90\nstroke 2 0 0 0\n"},
        {"camera keys", "cue 0 0\n" + rolling + "camera\nevent start 0 0 hover 0 -2 2 0 0 0\nendcamera\n"},
        {"camera description is required", "cue 0 0\n" + rolling},
    };
    const std::string help[] = {flat_help<ExportOptions>(parse_export_options),
                                flat_help<PreviewOptions>(parse_preview_options)};
    REQUIRE(parse_scene(seed, "seed", {.strict = true}).scene);
    for (const auto& extension : extensions) {
      const std::string& name = extension.first;  // a plain name: clang cannot capture a binding
      const std::string& text = extension.second;
      CAPTURE(name);
      const ParseResult plain = parse_scene(text, "extension");
      CHECK_MESSAGE(plain.scene, (plain.diagnostics.empty() ? "" : plain.diagnostics.front().message));
      CHECK_FALSE(parse_scene(text, "extension", {.strict = true}).scene);
      for (const std::string& usage : help) CHECK(usage.find(name) != std::string::npos);
    }
  }
}
