#pragma once
// Reading command-line arguments and their values, shared by both front ends so that they accept
// the same forms (`--fps 24`, `--fps=24`, `--` before a scene path starting with '-') and say the
// same things about bad values.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bsim {

/// Walks argv[1..]: each step is an option (with a value taken on request) or a positional word.
class ArgReader {
 public:
  explicit ArgReader(const std::vector<std::string>& args) : args_(args) {}

  /// Advances to the next argument; false at the end.
  bool next();
  /// Whether the current argument is an option ("-x", "--name"), not a positional word.
  bool is_option() const { return option_; }
  /// The option's name ("--fps") or the positional word.
  const std::string& word() const { return word_; }
  /// The option's value: after '=' or the next argument. Sets `error` when there is none.
  std::optional<std::string> value(std::string& error);
  /// For a flag: false (with `error`) when it was written with "=value".
  bool no_value(std::string& error) const;

 private:
  const std::vector<std::string>& args_;
  std::size_t index_ = 0;
  bool options_ended_ = false;
  bool option_ = false;
  std::string word_;
  std::optional<std::string> inline_value_;
};

/// An integer from lo to hi written in decimal.
std::optional<int> parse_int_option(std::string_view text, int lo, int hi);
/// A finite decimal number.
std::optional<double> parse_real_option(std::string_view text);
/// "WxH" with both parts from 1 to kMaxImageSide.
bool parse_size_option(std::string_view text, int& width, int& height);

/// "bad value 'TEXT' for NAME: expected EXPECTED": how both programs reject an option's value.
std::string bad_value_message(std::string_view name, std::string_view text, std::string_view expected);
/// "unknown option 'NAME' (see --help)", or "unknown option 'NAME'; did you mean 'OPTION'? (see --help)"
/// when NAME looks like a misspelling of one of the program's `own` options or of the shared ones.
std::string unknown_option_message(std::string_view name, const std::vector<std::string_view>& own = {});

/// One row of a program's option table, which drives its dispatch, its usage (--help) and its
/// "did you mean" suggestions: an option, with its names, the argument it takes, its help and what it
/// does; or, with no names, a line of the usage printed as it is (a heading, a blank line, an example).
struct OptionRow {
  /// As --help shows them, comma-separated ("-o, --output"); empty for a line of text.
  std::string_view names;
  /// The argument's name in the usage ("DIR"); empty for a flag.
  std::string_view argument;
  /// The help: each '\n' starts another line in the help column. For a line of text, the line.
  std::string_view help;
  /// Applies the option given as `name` with its `value` (empty for a flag): false with `message`
  /// set when the value is bad. Empty for the options read_arguments reads itself (the shared ones,
  /// -h and --version).
  std::function<bool(const std::string& name, const std::string& value, std::string& message)> apply;
  /// Whether --help lists the row (an option the program's jobs use may be left out).
  bool shown = true;
  /// The words the value is made of, '|'-separated, when ARGUMENT does not list them itself (--overlay
  /// LIST: "paths|events|camera|table"); the man pages and the shell completion offer them.
  std::string_view values = {};
};
using OptionTable = std::vector<OptionRow>;

/// The names of an option row: "-o, --output" gives {"-o", "--output"}.
std::vector<std::string_view> option_names(const OptionRow& row);

/// The words an option's value is chosen from, which the man pages and the shell completion offer:
/// the row's `values`, or else the literal words of its ARGUMENT ("draft|final" gives {"draft", "final"},
/// "LUFS|off" gives {"off"}, "N" none).
std::vector<std::string_view> option_values(const OptionRow& row);

/// The place of `word` among '|'-separated `choices` ("draft|final"): how an option whose ARGUMENT
/// lists its values reads them, so that the parser, --help and the completion share one list.
std::optional<std::size_t> choice_index(std::string_view choices, std::string_view word);

/// --camera's values, for both programs' rows and apply_shared_option.
inline constexpr std::string_view kCameraChoices = "auto|scene";

/// --replay: whether a game's movie shows its winning shot again, slowed, after the game. One row for
/// both programs (the export's movie, the preview's animatic, window and timeline picture).
OptionRow replay_option_row(bool& replay);

/// --strict's help, for both programs' rows: each extension the scene parser rejects under --strict.
inline constexpr std::string_view kStrictHelp =
    "accept only the original scene language: no comments, short ball line,\n"
    "spin, pocket, param, rack, stroke, place, pot, second cue line (several\n"
    "shots) or camera keys; a camera description is required";

/// The usage text: `head`, then each shown row of `table` (an option as "  NAMES ARGUMENT" with its
/// help from the 26th column on, a line of text as it is), then `tail`.
std::string usage_text(std::string_view head, const OptionTable& table, std::string_view tail);

/// Applies the reader's current option by its row of `table`: its value read (or, for a flag, none
/// allowed) and handed to the row's `apply`. False with `message` set when the value is bad or the
/// option is not in the table (then with the closest of the table's names suggested).
bool apply_table_option(ArgReader& reader, const OptionTable& table, std::string& message);

/// The options both programs take, with their defaults. apply_shared_option() reads and checks
/// them, so each is parsed in one place and rejected in the same words by both.
struct SharedOptions {
  int fps = 30;            ///< --fps N: frames per second of the movie or the animatic
  bool fps_given = false;  ///< --fps was given
  int width = 1280;        ///< --size WxH: pixels
  int height = 720;
  bool size_given = false;    ///< --size was given
  bool strict = false;        ///< --strict: accept only the original scene language
  bool quiet = false;         ///< --quiet: no progress lines (errors and warnings still print)
  bool auto_camera = false;   ///< --camera auto: the automatic director's script replaces the scene's
  bool camera_given = false;  ///< --camera was given (scene or auto)
};

enum class SharedOption { not_shared, applied, bad };

/// Applies the reader's current option when it is one of the shared ones (--fps, --size, --strict, --quiet,
/// --camera):
/// `applied`, or `bad` with `message` set; `not_shared` leaves it to the program.
SharedOption apply_shared_option(ArgReader& reader, SharedOptions& options, std::string& message);

enum class ArgumentsOutcome { run, exit_success, exit_usage };

/// The loop both front ends share: one positional scene path, `-h`/`--help` (prints `usage`),
/// `--version` (prints `version_line`), the shared options into `shared`, and `apply(reader, message)`
/// for every other option, which returns false with `message` set for a bad option or value.
template <class Apply>
ArgumentsOutcome read_arguments(const std::vector<std::string>& args, std::optional<std::string>& scene_path,
                                SharedOptions& shared, std::string_view usage, std::string_view version_line,
                                Apply&& apply, std::string& message) {
  message.clear();
  ArgReader reader(args);
  while (reader.next()) {
    const std::string& word = reader.word();
    if (!reader.is_option()) {
      if (scene_path) {
        message = "more than one scene given: '" + *scene_path + "' and '" + word + "'";
        return ArgumentsOutcome::exit_usage;
      }
      scene_path = word;
      continue;
    }
    if (word == "-h" || word == "--help") {
      message = usage;
      return ArgumentsOutcome::exit_success;
    }
    if (word == "--version") {
      message = version_line;
      return ArgumentsOutcome::exit_success;
    }
    switch (apply_shared_option(reader, shared, message)) {
      case SharedOption::applied: continue;
      case SharedOption::bad: return ArgumentsOutcome::exit_usage;
      case SharedOption::not_shared: break;
    }
    if (!apply(reader, message)) return ArgumentsOutcome::exit_usage;
  }
  return ArgumentsOutcome::run;
}

inline constexpr int kMaxImageSide = 16384;  ///< pixels; larger frames are surely a typo
inline constexpr int kMaxFps = 1000;

}  // namespace bsim
