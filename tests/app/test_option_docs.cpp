// The manual pages and bash completions are made from the programs' option tables: every option
// --help lists is in both, the values the parser accepts are the ones offered, and roff's control
// characters are guarded.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "command_line.h"
#include "export_options.h"
#include "option_docs.h"
#include "preview_options.h"

using namespace bsim;

namespace {

/// "-o, --output" as the manual page writes it: "\fB\-o\fR, \fB\-\-output\fR".
std::string roff_name(std::string_view name) {
  std::string out;
  for (char c : name) out += c == '-' ? std::string("\\-") : std::string(1, c);
  return "\\fB" + out + "\\fR";
}

/// The options the completion offers for a word starting with '-', each between spaces.
std::string offered_options(const std::string& completion) {
  const std::string start = "if [[ $cur == -* ]]; then\n    COMPREPLY=($(compgen -W \"";
  const std::size_t from = completion.find(start);
  if (from == std::string::npos) return "";
  const std::size_t first = from + start.size();
  return " " + completion.substr(first, completion.find('"', first) - first) + " ";
}

void check_docs(std::string_view program, const OptionTable& table, const std::string& usage) {
  const std::string man = man_page({program, "what it does", "9.9.9", usage, ".BR other (1)\n", ""}, table);
  const std::string completion = bash_completion(program, table);
  CHECK(man.find(".SH NAME\n" + std::string(program).replace(std::string(program).find('-'), 1, "\\-") +
                 " \\- what it does") != std::string::npos);
  CHECK(man.find("billiards-sim 9.9.9") != std::string::npos);
  CHECK(man.find(".SH \"EXIT STATUS\"\n0 done, 1 bad scene or failed run, 2 bad command line") != std::string::npos);
  CHECK(completion.find("complete -o filenames -F _" +
                        std::string(program == "billiards-export" ? "billiards_export" : "billiards_preview") + " " +
                        std::string(program)) != std::string::npos);
  for (const OptionRow& row : table) {
    if (row.names.empty()) continue;
    for (std::string_view name : option_names(row)) {
      CAPTURE(name);
      // A hidden option (--frames, the farm's tasks) is in neither.
      CHECK((man.find(roff_name(name)) != std::string::npos) == row.shown);
      CHECK((offered_options(completion).find(" " + std::string(name) + " ") != std::string::npos) == row.shown);
    }
  }
}

}  // namespace

TEST_CASE("a value list is read by the parser and offered by the completion from one string") {
  CHECK(choice_index("draft|final", "draft") == 0u);
  CHECK(choice_index("draft|final", "final") == 1u);
  CHECK_FALSE(choice_index("draft|final", "Final"));
  CHECK_FALSE(choice_index("draft|final", ""));
  CHECK(option_values({"--quality", "draft|final", "", {}}) == std::vector<std::string_view>{"draft", "final"});
  CHECK(option_values({"--loudness", "LUFS|off", "", {}}) == std::vector<std::string_view>{"off"});
  CHECK(option_values({"--at", "SECONDS|event:N", "", {}}).empty());
  CHECK(option_values({"--overlay", "LIST", "", {}, true, "a|b"}) == std::vector<std::string_view>{"a", "b"});
}

TEST_CASE("billiards-export's manual page and completion list every option --help lists") {
  ExportOptions options;
  std::string usage;
  REQUIRE(parse_export_options({"--help"}, options, usage) == CommandLineOutcome::exit_success);
  const OptionTable table = export_option_table(options);
  check_docs("billiards-export", table, usage);
  const std::string completion = bash_completion("billiards-export", table);
  CHECK(completion.find("    --quality)\n      _billiards_export_words \"draft final\"") != std::string::npos);
  CHECK(completion.find("    --camera)\n      _billiards_export_words \"auto scene\"") != std::string::npos);
  CHECK(completion.find("    -o|--output)\n      COMPREPLY=($(compgen -d") != std::string::npos);
  CHECK(completion.find("compgen -f -X '!*.scn'") != std::string::npos);
  const std::string man = man_page({"billiards-export", "x", "1", usage, "", ""}, table);
  // The usage's head is the description, its farm heading a subsection, its examples kept as lines.
  CHECK(man.find(".SH SYNOPSIS\n.B billiards\\-export\n[SCENE] [\\-o DIR] [options]\n") != std::string::npos);
  CHECK(man.find(".SH DESCRIPTION\nSimulates SCENE") != std::string::npos);
  CHECK(man.find(".SS \"rendering on a Slurm cluster (see README)\"") != std::string::npos);
  CHECK(man.find(".nf\nbilliards\\-export DIR \\-\\-farm status") != std::string::npos);
}

TEST_CASE("billiards-preview's manual page and completion list every option and --overlay's names") {
  PreviewOptions options;
  std::string usage;
  REQUIRE(parse_preview_options({"--help"}, options, usage) == PreviewCommandLineOutcome::exit_success);
  const OptionTable table = preview_option_table(options);
  check_docs("billiards-preview", table, usage);
  const std::string completion = bash_completion("billiards-preview", table);
  CHECK(completion.find("    --overlay)\n      _billiards_preview_words \"paths events camera table aim\"") !=
        std::string::npos);
  CHECK(completion.find("    --screenshot)\n      COMPREPLY=($(compgen -f -X '!*.png'") != std::string::npos);
  // Each offered overlay name is one the parser takes.
  for (const char* name : {"paths", "events", "camera", "table"}) {
    CAPTURE(name);
    PreviewOptions parsed;
    std::string message;
    CHECK(parse_preview_options({"--overlay", name, "--at", "1", "-o", "t.png"}, parsed, message) ==
          PreviewCommandLineOutcome::run);
  }
}

TEST_CASE("roff's control characters in the help are guarded") {
  const OptionTable table = {
      {"--x", "", ".starts with a dot\\ and a backslash", [](auto&, auto&, auto&) { return true; }}};
  const std::string man = man_page({"p", "s", "1", "usage: p\n", "", ""}, table);
  CHECK(man.find("\n\\&.starts with a dot\\e and a backslash\n") != std::string::npos);
}
