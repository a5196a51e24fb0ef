// billiards-export's command line: every option and its default, one-line reasons for bad ones
// (exit 2), and end to end, bad scenes give located errors (exit 1) and leave no output behind.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <tuple>

#include "export_options.h"
#include "fixtures.h"
#include "mastering.h"
#include "run_summary.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

CommandLineOutcome parse(std::vector<std::string> args, ExportOptions& options, std::string& message) {
  return parse_export_options(args, options, message);
}

/// The reason given for a rejected command line.
std::string rejection(std::vector<std::string> args) {
  ExportOptions options;
  std::string message;
  const CommandLineOutcome outcome = parse(std::move(args), options, message);
  CHECK(outcome == CommandLineOutcome::exit_usage);
  CHECK(message.find('\n') == std::string::npos);
  CHECK_FALSE(message.empty());
  return message;
}

test::CommandResult run_export(const std::string& arguments) {
  return test::run_command(quoted(test::bin("billiards-export")) + " " + arguments);
}

const std::string kGoodScene = std::string(test::fixtures::kOneBall) + test::fixtures::kHoverCamera;

}  // namespace

TEST_SUITE("export command line") {
  TEST_CASE("defaults") {
    ExportOptions o;
    std::string message;
    REQUIRE(parse({}, o, message) == CommandLineOutcome::run);
    CHECK_FALSE(o.scene_path);
    CHECK_FALSE(o.out_dir);
    CHECK_FALSE(o.events_only);
    CHECK_FALSE(o.no_render);
    CHECK(o.fps == 30);
    CHECK(o.width == 1280);
    CHECK(o.height == 720);
    CHECK(o.quality == Quality::final);
    CHECK(o.jobs == 0);
    CHECK(o.audio_lead == kDefaultAudioLead);
    CHECK(o.music_path.empty());
    CHECK_FALSE(o.strict);
  }

  TEST_CASE("every option") {
    test::TempDir tmp;
    const std::string song = tmp.file("song.wav", "any bytes: read when the sound track is mixed");
    ExportOptions o;
    std::string message;
    REQUIRE(parse({"shot.scn", "-o", "dir", "--fps", "24", "--size", "96x54", "--quality", "draft", "--jobs", "3",
                   "--audio-lead", "0.02", "--music", song, "--strict"},
                  o, message) == CommandLineOutcome::run);
    CHECK(*o.scene_path == "shot.scn");
    CHECK(*o.out_dir == "dir");
    CHECK(o.fps == 24);
    CHECK(o.width == 96);
    CHECK(o.height == 54);
    CHECK(o.quality == Quality::draft);
    CHECK(o.jobs == 3);
    CHECK(o.audio_lead == 0.02);
    CHECK(o.music_path == song);
    CHECK(o.strict);
    REQUIRE(parse({"--events-only", "--fps", "24", "--camera", "auto"}, o, message) == CommandLineOutcome::run);
    CHECK(o.events_only);
    REQUIRE(parse({"--no-render", "--quality", "draft", "--size", "96x54", "--music", song}, o, message) ==
            CommandLineOutcome::run);
    CHECK(o.no_render);
  }

  TEST_CASE("an option that does nothing beside the others is a mistake, as --chunk without --farm is") {
    test::TempDir tmp;
    const std::string song = tmp.file("song.wav", "bytes");
    for (const auto& row : std::vector<std::tuple<std::vector<std::string>, std::string, std::string>>{
             {{"--events-only", "--no-render"}, "--no-render", "--events-only"},
             {{"--events-only", "--music", song}, "--music", "--events-only"},
             {{"--events-only", "--size", "64x36"}, "--size", "--events-only"},
             {{"--quality", "draft", "--events-only"}, "--quality", "--events-only"},
             {{"--events-only", "--loudness", "off"}, "--loudness", "--events-only"},
             {{"--events-only", "--audio-lead", "0"}, "--audio-lead", "--events-only"},
             {{"--no-render", "--jobs", "2"}, "--jobs", "--no-render"},
             {{"--whole-frames", "--no-render"}, "--whole-frames", "--no-render"},
         }) {
      const auto& [args, option_name, mode] = row;
      const std::string option = option_name;  // a plain name: clang cannot capture a binding
      CAPTURE(option);
      CHECK(rejection(args).starts_with(option + " does nothing with " + mode + " ("));
    }
  }

  TEST_CASE("--music names a file that exists: exit 2 naming it, not the sound library's words") {
    test::TempDir tmp;
    const std::string missing = (tmp.path / "missing.wav").string();
    CHECK(rejection({"--music", missing}) == "--music: cannot read '" + missing + "': no such file");
    CHECK(rejection({"--music", tmp.path.string()}) ==
          "--music: cannot read '" + tmp.path.string() + "': it is a directory");
    const test::CommandResult r =
        run_export("--no-render --music " + quoted(missing) + " -o " + quoted((tmp.path / "o").string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err == "billiards-export: --music: cannot read '" + missing + "': no such file\n");
    // A file that is there but is no sound: the run fails (exit 1) naming it, in plain words.
    const std::string text = tmp.file("notes.wav", "not a sound");
    const test::CommandResult unreadable = run_export("--no-render --fps 1 --size 16x10 --music " + quoted(text) +
                                                      " -o " + quoted((tmp.path / "o").string()));
    CHECK(unreadable.exit_code == 1);
    CHECK(unreadable.err.find("cannot read the music file '" + text + "': ") != std::string::npos);
    CHECK(unreadable.err.find("System error") == std::string::npos);
    CHECK_FALSE(fs::exists(tmp.path / "o"));
  }

  TEST_CASE("--name=value, --output, and -- before a scene that starts with '-'") {
    ExportOptions o;
    std::string message;
    REQUIRE(parse({"--fps=12", "--output=out/x", "--audio-lead=0", "--", "-odd.scn"}, o, message) ==
            CommandLineOutcome::run);
    CHECK(o.fps == 12);
    CHECK(*o.out_dir == "out/x");
    CHECK(o.audio_lead == 0);
    CHECK(*o.scene_path == "-odd.scn");
  }

  TEST_CASE("bad options and values are rejected with one-line reasons") {
    CHECK(rejection({"--fps", "0"}).find("bad value '0' for --fps") != std::string::npos);
    CHECK(rejection({"--fps", "2.5"}).find("--fps") != std::string::npos);
    CHECK(rejection({"--size", "12"}).find("bad value '12' for --size: expected WIDTHxHEIGHT") != std::string::npos);
    CHECK(rejection({"--size", "0x10"}).find("--size") != std::string::npos);
    CHECK(rejection({"--size", "10x"}).find("--size") != std::string::npos);
    CHECK(rejection({"--jobs", "0"}).find("bad value '0' for --jobs") != std::string::npos);
    CHECK(rejection({"--quality", "ultra"}).find("expected draft or final") != std::string::npos);
    CHECK(rejection({"--audio-lead", "-0.1"}).find("--audio-lead") != std::string::npos);
    CHECK(rejection({"--audio-lead", "nan"}).find("--audio-lead") != std::string::npos);
    CHECK(rejection({"--frobnicate"}) == "unknown option '--frobnicate' (see --help)");
    CHECK(rejection({"-x"}).find("unknown option '-x'") != std::string::npos);
    CHECK(rejection({"--fps"}) == "--fps needs a value");
    CHECK(rejection({"-o"}) == "-o needs a value");
    CHECK(rejection({"--strict=yes"}).find("--strict takes no value") != std::string::npos);
    CHECK(rejection({"a.scn", "b.scn"}) == "more than one scene given: 'a.scn' and 'b.scn'");
  }

  TEST_CASE("--loudness takes LUFS from -40 to -10 or off; by default the level is the calibrated one") {
    ExportOptions o;
    std::string message;
    REQUIRE(parse({}, o, message) == CommandLineOutcome::run);
    CHECK(o.level.mode == LevelMode::calibrated);
    REQUIRE(parse({"--loudness", "-23"}, o, message) == CommandLineOutcome::run);
    CHECK(o.level == SoundLevel{.mode = LevelMode::normalised, .loudness = -23.0});
    REQUIRE(parse({"--loudness=off"}, o, message) == CommandLineOutcome::run);
    CHECK(o.level.mode == LevelMode::off);
    for (const char* bad : {"-9", "-41", "loud", "nan", ""})
      CHECK(rejection({"--loudness", bad}).find("expected LUFS from -40 to -10, or off") != std::string::npos);
    REQUIRE(parse({"--help"}, o, message) == CommandLineOutcome::exit_success);
    CHECK(message.find("--loudness LUFS|off") != std::string::npos);
    CHECK(message.find("(default: one calibrated level for every shot") != std::string::npos);
  }

  TEST_CASE("run.json says which sound level was used") {
    test::TempDir dir;
    const std::string path = (dir.path / "run.json").string();
    const std::pair<std::vector<std::string>, std::string> cases[] = {
        {{}, R"("sound": {"level": "calibrated", "target_lufs": null, )"},
        {{"--loudness", "-23"}, R"("sound": {"level": "normalised", "target_lufs": -23.00, )"},
        {{"--loudness", "off"}, R"("sound": {"level": "off", "target_lufs": null, )"}};
    for (const auto& sound_case : cases) {
      const std::vector<std::string>& args = sound_case.first;
      const std::string& expected = sound_case.second;  // a plain reference: CAPTURE's lambda may not take a binding
      CAPTURE(expected);
      ExportOptions o;
      std::string message, error;
      REQUIRE(parse(args, o, message) == CommandLineOutcome::run);
      RunSummary summary;
      summary.loudness_lufs = -20.0;
      REQUIRE(write_run_summary(summary, o, dir.path.string(), error));
      CHECK(test::require_file(path).find(expected) != std::string::npos);
    }
  }

  TEST_CASE("--help lists every option with its default; --version names the program") {
    ExportOptions o;
    std::string help;
    REQUIRE(parse({"--events-only", "--help"}, o, help) == CommandLineOutcome::exit_success);
    for (const char* option : {"-o", "--events-only", "--no-render", "--fps N", "--size WxH", "--quality draft|final",
                               "--jobs N", "--audio-lead SECONDS", "--music FILE", "--strict", "--help", "--version",
                               "(default: 30)", "(default: 1280x720)", "(default: final)", "(default: 0.005)",
                               "(default: out/<scene name>)", "(default: one per core)"})
      CHECK_MESSAGE(help.find(option) != std::string::npos, option);
    std::string version;
    REQUIRE(parse({"--version"}, o, version) == CommandLineOutcome::exit_success);
    CHECK(version == std::string("billiards-export ") + BSIM_VERSION + "\n");
  }
}

TEST_SUITE("export end to end") {
  TEST_CASE("bad scenes: a located error, exit 1, no output directory") {
    test::TempDir tmp;
    const std::pair<const char*, int> cases[] = {
        {"cue 0 0\nbal 0 0 0 0.028575 1 0 0 1 0 0 0\n", 2},
        {"cue 0 0\nball 0 0\n", 2},
        {"", 1},
        {"cue 3 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\n", 1},
        // Several shots: a later cue without its stroke; a place onto a ball (found when shot 2 comes);
        // a later pot of a ball shot 1 already potted (found when shot 2 is aimed).
        {"ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\ncue 0 0\nstroke 1 0 0 0\ncue 0 90\n", 4},
        {"ball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\nball 1 0.3 0 0.028575 0 0 0 1 0 0 0\ncue 1 90\nstroke 0.3 0 0 0\n"
         "cue 0 0\nstroke 1 0 0 0\nplace 1 -0.6 0\n",
         7},
        {"ball 0 -0.45 -0.25 0.028575 0 0 0 1 0 0 0\nball 1 0.55 0.25 0.028575 0 0 0 1 0 0 0\ncue 0 pot 1 2\n"
         "stroke 2 0 0 0\ncue 0 pot 1 2\nstroke 2 0 0 0\n",
         5},
    };
    int n = 0;
    for (const auto& [text, line] : cases) {
      const std::string shown = text;
      CAPTURE(shown);
      const std::string scene = tmp.file("bad" + std::to_string(n) + ".scn", text);
      const std::string out = (tmp.path / ("out" + std::to_string(n++))).string();
      const test::CommandResult r = run_export(quoted(scene) + " --events-only -o " + quoted(out));
      CHECK(r.exit_code == 1);
      const std::regex located(std::regex_replace(scene, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") + ":" +
                               std::to_string(line) + R"(:\d+: error: \S.*\n)");
      CHECK_MESSAGE(std::regex_search(r.err, located), r.err);
      CHECK_FALSE(fs::exists(out));
    }
    // Nothing else appeared beside the outputs either (no staging directory left over).
    std::size_t entries = 0;
    for (const auto& e : fs::directory_iterator(tmp.path)) entries += e.path().extension() != ".scn";
    CHECK(entries == 0);
  }

  TEST_CASE("warnings have the same shape and do not stop the run") {
    test::TempDir tmp;
    const std::string scene = tmp.file("warn.scn", "cue 0 45\nball 0 0 0 0.028575 1 0 0 1 0 0 0\n");
    const test::CommandResult r = run_export(quoted(scene) + " --events-only -o " + quoted((tmp.path / "o").string()));
    CHECK_MESSAGE(r.err.find(scene + ":1:7: warning: ") != std::string::npos, r.err);
    CHECK(r.err.find("error") == std::string::npos);
  }

  TEST_CASE("--strict reaches the parser") {
    test::TempDir tmp;
    const std::string scene = tmp.file("ext.scn", "# a comment\n" + kGoodScene);
    const test::CommandResult r =
        run_export(quoted(scene) + " --strict --events-only -o " + quoted((tmp.path / "o").string()));
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(r.err.find(scene + ":1:1: error: '#' comments are an extension") != std::string::npos, r.err);
  }

  TEST_CASE("a scene file that cannot be read: exit 1 naming it") {
    test::TempDir tmp;
    const std::string missing = (tmp.path / "nowhere.scn").string();
    const test::CommandResult r =
        run_export(quoted(missing) + " --events-only -o " + quoted((tmp.path / "o").string()));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find(missing) != std::string::npos);
    CHECK_FALSE(fs::exists(tmp.path / "o"));
  }

  TEST_CASE("bad command lines: exit 2 with one line naming the problem") {
    for (const std::string args :
         {"--fps 0", "--size 12", "--jobs 0", "--quality ultra", "--bogus", "--fps", "a.scn b.scn"}) {
      CAPTURE(args);
      const test::CommandResult r = run_export(args);
      CHECK(r.exit_code == 2);
      CHECK(r.err.starts_with("billiards-export: "));
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      CHECK(r.out.empty());
    }
  }

  TEST_CASE("--help and --version print on standard output and exit 0") {
    const test::CommandResult help = run_export("--help");
    CHECK(help.exit_code == 0);
    CHECK(help.out.starts_with("usage: billiards-export"));
    const test::CommandResult version = run_export("--version");
    CHECK(version.exit_code == 0);
    CHECK(version.out == std::string("billiards-export ") + BSIM_VERSION + "\n");
  }

  TEST_CASE("an output path that is a regular file: exit 1, file untouched") {
    test::TempDir tmp;
    const std::string scene = tmp.file("good.scn", kGoodScene);
    const std::string target = tmp.file("taken", "keep me");
    const test::CommandResult r = run_export(quoted(scene) + " --events-only -o " + quoted(target));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("error") != std::string::npos);
    CHECK(test::require_file(target) == "keep me");
  }

  TEST_CASE("a good scene with --events-only writes the three data files and nothing else") {
    test::TempDir tmp;
    const std::string scene = tmp.file("good.scn", kGoodScene);
    const fs::path out = tmp.path / "deep" / "out";
    const test::CommandResult r = run_export(quoted(scene) + " --events-only -o " + quoted(out.string()));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    CHECK(names == std::vector<std::string>{"camera.csv", "events.json", "trajectory.csv"});
    std::vector<std::string> beside;
    for (const auto& e : fs::directory_iterator(tmp.path)) beside.push_back(e.path().filename().string());
    std::sort(beside.begin(), beside.end());
    CHECK(beside == std::vector<std::string>{"deep", "good.scn"});
  }
}
