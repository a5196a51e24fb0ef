// Each program's option table drives its dispatch, its --help and its "did you mean": every option of
// the table does what it says, every one is listed, and a misspelled one is answered with the
// closest name.
#include <doctest/doctest.h>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "command_line.h"
#include "export_options.h"
#include "option_rejection.h"
#include "preview_options.h"
#include "support.h"

using namespace bsim;
using bsim::test::export_rejection;
using bsim::test::preview_rejection;

namespace {

/// A value each option accepts and how to see that the option took it.
template <class Options>
struct Sample {
  std::string value;
  std::function<bool(const Options&)> took;
};

/// Applies every option of `table` (each of its names) through the table, as the command line does,
/// and checks it with its sample; every option must have one.
template <class Options>
void check_dispatch(const std::function<OptionTable(Options&)>& make_table,
                    const std::map<std::string, Sample<Options>>& samples) {
  Options probe;
  for (const OptionRow& row : make_table(probe)) {
    if (!row.apply) continue;
    for (std::string_view name : option_names(row)) {
      CAPTURE(name);
      const auto sample = samples.find(std::string(name));
      REQUIRE_MESSAGE(sample != samples.end(), "an option of the table with no test");
      Options o;
      const OptionTable table = make_table(o);
      std::vector<std::string> args = {std::string(name)};
      if (!row.argument.empty()) args.push_back(sample->second.value);
      ArgReader reader(args);
      REQUIRE(reader.next());
      std::string message;
      CHECK_MESSAGE(apply_table_option(reader, table, message), message);
      CHECK(sample->second.took(o));
    }
  }
}

}  // namespace

TEST_SUITE("option tables") {
  TEST_CASE("every option of billiards-export's table is dispatched to what it does") {
    using E = ExportOptions;
    bsim::test::TempDir tmp;  // --music takes a file that is there
    const std::string bed = tmp.file("bed.wav", "sound");
    const std::map<std::string, Sample<E>> samples = {
        {"-o", {"somewhere", [](const E& o) { return o.out_dir == "somewhere"; }}},
        {"--output", {"elsewhere", [](const E& o) { return o.out_dir == "elsewhere"; }}},
        {"--events-only", {"", [](const E& o) { return o.events_only; }}},
        {"--no-render", {"", [](const E& o) { return o.no_render; }}},
        {"--quality", {"draft", [](const E& o) { return o.quality == Quality::draft; }}},
        {"--jobs", {"3", [](const E& o) { return o.jobs == 3; }}},
        {"--whole-frames", {"", [](const E& o) { return o.whole_frames; }}},
        {"--captions", {"off", [](const E& o) { return !o.captions; }}},
        {"--audio-lead", {"0.25", [](const E& o) { return o.audio_lead == 0.25; }}},
        {"--music", {bed, [bed](const E& o) { return o.music_path == bed; }}},
        {"--loudness",
         {"-20", [](const E& o) { return o.level.mode == LevelMode::normalised && o.level.loudness == -20.0; }}},
        {"--farm", {"assemble", [](const E& o) { return o.farm == FarmMode::assemble; }}},
        {"--chunk", {"12", [](const E& o) { return o.chunk == 12; }}},
        {"--sbatch-option",
         {"--partition=short",
          [](const E& o) { return o.sbatch_options == std::vector<std::string>{"--partition=short"}; }}},
        {"--frames", {"4-9", [](const E& o) { return o.first_frame == 4 && o.last_frame == 9; }}},
        {"--replay", {"off", [](const E& o) { return !o.replay; }}},
    };
    check_dispatch<E>(export_option_table, samples);
  }

  TEST_CASE("every option of billiards-preview's table is dispatched to what it does") {
    using P = PreviewOptions;
    const std::map<std::string, Sample<P>> samples = {
        {"--at", {"event:3", [](const P& o) { return o.at.size() == 1 && o.at[0].event == 3; }}},
        {"--timeline", {"", [](const P& o) { return o.timeline; }}},
        {"-o", {"a.png", [](const P& o) { return o.output == "a.png"; }}},
        {"--output", {"b.png", [](const P& o) { return o.output == "b.png"; }}},
        {"--movie", {"m.mp4", [](const P& o) { return o.movie == "m.mp4"; }}},
        {"--overlay", {"paths,table", [](const P& o) { return o.overlays.paths && o.overlays.table; }}},
        {"--write-camera", {"-", [](const P& o) { return o.write_camera == "-"; }}},
        {"--write-scene", {"-", [](const P& o) { return o.write_scene == "-"; }}},
        {"--quit-after", {"1.5", [](const P& o) { return o.quit_after == 1.5; }}},
        {"--screenshot", {"s.png", [](const P& o) { return o.screenshot == "s.png"; }}},
        {"--replay", {"off", [](const P& o) { return !o.replay; }}},
    };
    check_dispatch<P>(preview_option_table, samples);
  }

  TEST_CASE("every shown option of a table is in the program's --help, in the table's order") {
    ExportOptions e;
    PreviewOptions p;
    std::string help;
    REQUIRE(parse_export_options({"--help"}, e, help) == CommandLineOutcome::exit_success);
    std::size_t at = 0;
    for (const OptionRow& row : export_option_table(e)) {
      if (!row.shown || row.names.empty()) continue;
      at = help.find("  " + std::string(row.names), at);
      CHECK_MESSAGE(at != std::string::npos, row.names);
    }
    CHECK(help.find("--frames A-B   render the missing frames") != std::string::npos);
    REQUIRE(parse_preview_options({"--help"}, p, help) == PreviewCommandLineOutcome::exit_success);
    at = 0;
    for (const OptionRow& row : preview_option_table(p)) {
      at = help.find("  " + std::string(row.names), at);
      CHECK_MESSAGE(at != std::string::npos, row.names);
    }
  }

  TEST_CASE("the usage lays a row out in two columns, continuing its help in the second") {
    const OptionTable table = {
        {"-x, --example", "ARG", "first line\nsecond line", {}},
        {"--flag", "", "a flag", {}},
        {"", "", "a line as it is", {}},
        {"--hidden", "", "not listed", {}, false},
    };
    CHECK(usage_text("head\n", table, "tail\n") ==
          "head\n"
          "  -x, --example ARG      first line\n"
          "                         second line\n"
          "  --flag                 a flag\n"
          "a line as it is\n"
          "tail\n");
  }

  TEST_CASE("an unknown option is answered with the closest name of the table, or the shared ones") {
    CHECK(export_rejection({"--qualty", "draft"}) ==
          "unknown option '--qualty'; did you mean '--quality'? (see --help)");
    CHECK(export_rejection({"--frame", "1-2"}) == "unknown option '--frame'; did you mean '--frames'? (see --help)");
    CHECK(export_rejection({"--sbatch-optoin"}) ==
          "unknown option '--sbatch-optoin'; did you mean '--sbatch-option'? (see --help)");
    CHECK(export_rejection({"--zzz"}) == "unknown option '--zzz' (see --help)");
    CHECK(preview_rejection({"--timelin"}) == "unknown option '--timelin'; did you mean '--timeline'? (see --help)");
    CHECK(preview_rejection({"--screenshoot", "a.png"}) ==
          "unknown option '--screenshoot'; did you mean '--screenshot'? (see --help)");
    CHECK(preview_rejection({"--fsp", "24"}) == "unknown option '--fsp'; did you mean '--fps'? (see --help)");
    // A flag takes no value, and a value option needs one, whichever table row it is.
    CHECK(export_rejection({"--no-render=yes"}) == "--no-render takes no value, found 'yes'");
    CHECK(preview_rejection({"--movie"}) == "--movie needs a value");
  }
}
