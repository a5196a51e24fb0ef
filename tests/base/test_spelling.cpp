// "Did you mean ...?": the edit distance, when a word is close enough to suggest, and the
// suggestions the scene parser and both command lines append to their messages.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "export_options.h"
#include "fixtures.h"
#include "preview_options.h"
#include "scene_parse.h"
#include "spelling.h"
#include "support.h"

using namespace bsim;

namespace {

/// The first error's message for `text`.
std::string first_error(const std::string& text, ParseOptions options = {}) {
  const ParseResult r = parse_scene(text, "t", options);
  for (const Diagnostic& d : r.diagnostics)
    if (d.severity == Severity::error) return d.message;
  FAIL("no error for:\n" << text);
  return {};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kBall0 = "ball 0 0 0 0.028575 1 0 0 1 0 0 0\n";

}  // namespace

TEST_SUITE("spelling") {
  TEST_CASE("a word in the wrong case: the known word, however short, and said so") {
    CHECK(closest_word("BALL", {"cue", "ball"}) == "ball");
    CHECK(closest_word("G", {"g", "e"}) == "g");  // a one-letter word is never otherwise suggested
    CHECK(did_you_mean("BALL", {"ball"}, "keywords") == "; did you mean 'ball'? (keywords are lower case)");
    CHECK(did_you_mean("wpa", {"WPA"}) == "; did you mean 'WPA'? (case matters)");
    CHECK(did_you_mean("bal", {"ball"}) == "; did you mean 'ball'?");
    CHECK_FALSE(closest_word("ball", {"ball", "BALL"}));  // a known word needs no suggestion
  }

  TEST_CASE("edit distance: insertions, deletions, substitutions and swapped neighbours count one each") {
    CHECK(edit_distance("", "") == 0);
    CHECK(edit_distance("ball", "ball") == 0);
    CHECK(edit_distance("bal", "ball") == 1);
    CHECK(edit_distance("balls", "ball") == 1);
    CHECK(edit_distance("bell", "ball") == 1);
    CHECK(edit_distance("--fsp", "--fps") == 1);
    CHECK(edit_distance("mu_rol", "mu_roll") == 1);
    CHECK(edit_distance("", "cue") == 3);
    CHECK(edit_distance("kitten", "sitting") == 3);
    CHECK(edit_distance("ca", "abc") == 3);  // a swap is not edited again
    CHECK(edit_distance("Ball", "ball") == 1);
    CHECK(edit_distance("abc", "xyz") == edit_distance("xyz", "abc"));
  }

  TEST_CASE("a suggestion only for a word close to a known one, relative to its length") {
    const std::vector<std::string_view> known = {"cue", "ball", "rail", "camera"};
    CHECK(closest_word("bal", known) == std::optional<std::string>("ball"));
    CHECK(closest_word("camrea", known) == std::optional<std::string>("camera"));
    CHECK(closest_word("cmaera", known) == std::optional<std::string>("camera"));
    CHECK(closest_word("raill", known) == std::optional<std::string>("rail"));
    CHECK_FALSE(closest_word("ball", known));    // known: nothing to suggest
    CHECK_FALSE(closest_word("b", known));       // one letter: too short to guess
    CHECK_FALSE(closest_word("cu", known));      // 1 edit is half of 2 letters: not less
    CHECK_FALSE(closest_word("carpet", known));  // 3 edits from camera
    CHECK_FALSE(closest_word("xyz", known));
    CHECK_FALSE(closest_word("bal", {}));
    CHECK(closest_word("rall", known) == std::optional<std::string>("ball"));  // ties: the first listed
    CHECK(did_you_mean("bal", known) == "; did you mean 'ball'?");
    CHECK(did_you_mean("table", known).empty());
  }

  TEST_CASE("the scene parser suggests a keyword, a param name, a camera line and a camera mode") {
    const std::string keyword = first_error("cue 0 0\nbal 0 0 0 0.028575 1 0 0 1 0 0 0\n");
    CHECK(contains(keyword, "unknown keyword 'bal'; expected one of"));
    CHECK(keyword.ends_with("; did you mean 'ball'?"));
    const std::string param = first_error("cue 0 0\n" + kBall0 + "param mu_rol 0.02\n");
    CHECK(contains(param, "unknown parameter 'mu_rol'"));
    CHECK(param.ends_with("; did you mean 'mu_roll'?"));
    CHECK(first_error("cue 0 0\n" + kBall0 + "camera\nevnt 0 0 0 hover 0 -3 2 0 0 0\nendcamera\n")
              .ends_with("found 'evnt'; did you mean 'event'?"));
    CHECK(first_error("cue 0 0\n" + kBall0 + "camera\nevent 0 0 0 folow 0 0 -1 1\nendcamera\n")
              .ends_with("found 'folow'; did you mean 'follow'?"));
  }

  TEST_CASE("no suggestion when nothing is close, nor an extension under --strict") {
    CHECK_FALSE(contains(first_error("cue 0 0\nbox 1\n" + kBall0), "did you mean"));
    CHECK_FALSE(contains(first_error("cue 0 0\n" + kBall0 + "param friction 0.2\n"), "did you mean"));
    CHECK_FALSE(contains(first_error("cue 0 0\n" + kBall0 + "spni 0 0 0 1\n", {.strict = true}), "did you mean"));
    CHECK(contains(first_error("cue 0 0\n" + kBall0 + "spni 0 0 0 1\n"), "did you mean 'spin'?"));
  }

  TEST_CASE("the located message keeps its shape, with the suggestion at its end") {
    test::TempDir dir;
    const std::string scene =
        dir.file("typo.scn", "cue 0 0\nbal 0 0 0 0.028575 1 0 0 1 0 0 0\n" + std::string(test::fixtures::kHoverCamera));
    const test::CommandResult r =
        test::run_command(test::quoted(test::bin("billiards-export")) + " " + test::quoted(scene) +
                          " --events-only -o " + test::quoted((dir.path / "out").string()));
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.err, scene + ":2:1: error: unknown keyword 'bal'; expected one of "), r.err);
    CHECK_MESSAGE(contains(r.err, "; did you mean 'ball'?\n"), r.err);
  }

  TEST_CASE("both command lines suggest an option, their own or a shared one") {
    ExportOptions e;
    PreviewOptions p;
    std::string message;
    CHECK(parse_export_options({"--fsp", "24"}, e, message) == CommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--fsp'; did you mean '--fps'? (see --help)");
    CHECK(parse_preview_options({"--fsp", "24"}, p, message) == PreviewCommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--fsp'; did you mean '--fps'? (see --help)");
    // Every shared option is suggested by both programs.
    CHECK(parse_export_options({"--quite"}, e, message) == CommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--quite'; did you mean '--quiet'? (see --help)");
    CHECK(parse_preview_options({"--quite"}, p, message) == PreviewCommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--quite'; did you mean '--quiet'? (see --help)");
    CHECK(parse_export_options({"--event-only"}, e, message) == CommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--event-only'; did you mean '--events-only'? (see --help)");
    CHECK(parse_export_options({"--qualty=draft"}, e, message) == CommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--qualty'; did you mean '--quality'? (see --help)");
    CHECK(parse_preview_options({"--timline", "-o", "t.png"}, p, message) == PreviewCommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--timline'; did you mean '--timeline'? (see --help)");
    CHECK(parse_preview_options({"--overlays", "paths"}, p, message) == PreviewCommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--overlays'; did you mean '--overlay'? (see --help)");
    CHECK(parse_preview_options({"--stirct"}, p, message) == PreviewCommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--stirct'; did you mean '--strict'? (see --help)");
    // An option of the other program is not suggested, and a far-off word gets no suggestion.
    CHECK(parse_preview_options({"--job", "2"}, p, message) == PreviewCommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--job' (see --help)");
    CHECK(parse_export_options({"--bogus"}, e, message) == CommandLineOutcome::exit_usage);
    CHECK(message == "unknown option '--bogus' (see --help)");
  }

  TEST_CASE("the binaries print the suggestion, exit 2") {
    for (const std::string program : {"billiards-export", "billiards-preview"}) {
      const test::CommandResult r = test::run_command(test::quoted(test::bin(program)) + " --fsp 24");
      CHECK(r.exit_code == 2);
      CHECK(r.err == program + ": unknown option '--fsp'; did you mean '--fps'? (see --help)\n");
    }
  }
}
