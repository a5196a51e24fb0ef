#include "command_line.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <utility>

#include "spelling.h"

namespace bsim {

bool ArgReader::next() {
  inline_value_.reset();
  if (index_ >= args_.size()) return false;
  const std::string& arg = args_[index_++];
  if (!options_ended_ && arg == "--") {
    options_ended_ = true;
    return next();
  }
  option_ = !options_ended_ && arg.size() > 1 && arg[0] == '-';
  word_ = arg;
  if (option_ && arg.starts_with("--")) {
    if (const auto eq = arg.find('='); eq != std::string::npos) {
      word_ = arg.substr(0, eq);
      inline_value_ = arg.substr(eq + 1);
    }
  }
  return true;
}

std::optional<std::string> ArgReader::value(std::string& error) {
  if (inline_value_) return std::exchange(inline_value_, std::nullopt);
  if (index_ >= args_.size()) {
    error = word_ + " needs a value";
    return std::nullopt;
  }
  return args_[index_++];
}

bool ArgReader::no_value(std::string& error) const {
  if (!inline_value_) return true;
  error = word_ + " takes no value, found '" + *inline_value_ + "'";
  return false;
}

std::optional<int> parse_int_option(std::string_view text, int lo, int hi) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
    return std::nullopt;
  return value;
}

std::optional<double> parse_real_option(std::string_view text) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

bool parse_size_option(std::string_view text, int& width, int& height) {
  const auto x = text.find('x');
  if (x == std::string_view::npos) return false;
  const auto w = parse_int_option(text.substr(0, x), 1, kMaxImageSide);
  const auto h = parse_int_option(text.substr(x + 1), 1, kMaxImageSide);
  if (!w || !h || text.substr(0, x).starts_with('+') || text.substr(x + 1).starts_with('+')) return false;
  width = *w;
  height = *h;
  return true;
}

std::string bad_value_message(std::string_view name, std::string_view text, std::string_view expected) {
  return "bad value '" + std::string(text) + "' for " + std::string(name) + ": expected " + std::string(expected);
}

std::string unknown_option_message(std::string_view name, const std::vector<std::string_view>& own) {
  std::vector<std::string_view> known = {"--fps", "--size", "--strict", "--quiet", "--camera", "--help", "--version"};
  known.insert(known.end(), own.begin(), own.end());
  return "unknown option '" + std::string(name) + "'" + did_you_mean(name, known) + " (see --help)";
}

std::vector<std::string_view> option_names(const OptionRow& row) {
  std::vector<std::string_view> names;
  for (std::string_view rest = row.names; !rest.empty();) {
    const std::size_t comma = rest.find(", ");
    names.push_back(rest.substr(0, comma));
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 2);
  }
  return names;
}

namespace {

std::vector<std::string_view> split_choices(std::string_view choices) {
  std::vector<std::string_view> words;
  for (std::string_view rest = choices; !rest.empty();) {
    const std::size_t bar = rest.find('|');
    words.push_back(rest.substr(0, bar));
    rest = bar == std::string_view::npos ? std::string_view() : rest.substr(bar + 1);
  }
  return words;
}

/// "; did you mean 'WORD'?" for the first of the value's comma-separated words that is not one of
/// `words` but close to one, or "".
std::string value_suggestion(std::string_view value, const std::vector<std::string_view>& words) {
  for (std::string_view rest = value; !rest.empty();) {
    const std::size_t comma = rest.find(',');
    const std::string_view word = rest.substr(0, comma);
    if (std::find(words.begin(), words.end(), word) == words.end()) return did_you_mean(word, words);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
  }
  return {};
}

}  // namespace

std::vector<std::string_view> option_values(const OptionRow& row) {
  if (!row.values.empty()) return split_choices(row.values);
  std::vector<std::string_view> words;
  for (std::string_view word : split_choices(row.argument))
    if (std::all_of(word.begin(), word.end(), [](char c) { return c >= 'a' && c <= 'z'; })) words.push_back(word);
  return words;
}

std::optional<std::size_t> choice_index(std::string_view choices, std::string_view word) {
  const std::vector<std::string_view> words = split_choices(choices);
  const auto found = std::find(words.begin(), words.end(), word);
  if (found == words.end()) return std::nullopt;
  return static_cast<std::size_t>(found - words.begin());
}

std::string usage_text(std::string_view head, const OptionTable& table, std::string_view tail) {
  constexpr std::size_t kHelpColumn = 25;  // the help starts after this many characters
  std::string text(head);
  for (const OptionRow& row : table) {
    if (!row.shown) continue;
    if (row.names.empty()) {
      text.append(row.help).append("\n");
      continue;
    }
    std::string line = "  " + std::string(row.names);
    if (!row.argument.empty()) line.append(" ").append(row.argument);
    line.append(line.size() + 2 > kHelpColumn ? 2 : kHelpColumn - line.size(), ' ');
    std::string_view help = row.help;
    for (std::size_t end; (end = help.find('\n')) != std::string_view::npos; help.remove_prefix(end + 1)) {
      line.append(help.substr(0, end)).append("\n").append(kHelpColumn, ' ');
    }
    text.append(line).append(help).append("\n");
  }
  return text.append(tail);
}

bool apply_table_option(ArgReader& reader, const OptionTable& table, std::string& message) {
  const std::string& name = reader.word();
  std::vector<std::string_view> own;
  for (const OptionRow& row : table) {
    if (!row.apply) continue;
    const std::vector<std::string_view> names = option_names(row);
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      own.insert(own.end(), names.begin(), names.end());
      continue;
    }
    if (row.argument.empty()) return reader.no_value(message) && row.apply(name, "", message);
    const std::optional<std::string> value = reader.value(message);
    if (!value) return false;
    if (row.apply(name, *value, message)) return true;
    // A misspelt word of the value: the closest of the words the option takes.
    if (message.find("did you mean") == std::string::npos) message += value_suggestion(*value, option_values(row));
    return false;
  }
  message = unknown_option_message(name, own);
  return false;
}

SharedOption apply_shared_option(ArgReader& reader, SharedOptions& o, std::string& message) {
  const std::string& name = reader.word();
  if (name == "--strict" || name == "--quiet") {
    if (!reader.no_value(message)) return SharedOption::bad;
    (name == "--strict" ? o.strict : o.quiet) = true;
    return SharedOption::applied;
  }
  if (name != "--fps" && name != "--size" && name != "--camera") return SharedOption::not_shared;
  const auto v = reader.value(message);
  if (!v) return SharedOption::bad;
  if (name == "--camera") {
    if (!choice_index(kCameraChoices, *v)) {
      message = bad_value_message(name, *v, "auto (the automatic director's script) or scene (the scene's own)") +
                value_suggestion(*v, split_choices(kCameraChoices));
      return SharedOption::bad;
    }
    o.auto_camera = *v == "auto";
    o.camera_given = true;
    return SharedOption::applied;
  }
  if (name == "--fps") {
    const auto fps = parse_int_option(*v, 1, kMaxFps);
    if (!fps) {
      message = bad_value_message(name, *v, "a whole number of frames per second from 1 to " + std::to_string(kMaxFps));
      return SharedOption::bad;
    }
    o.fps = *fps;
    o.fps_given = true;
  } else {
    if (!parse_size_option(*v, o.width, o.height)) {
      message = bad_value_message(
          name, *v, "WIDTHxHEIGHT in pixels, e.g. 1280x720, each from 1 to " + std::to_string(kMaxImageSide));
      return SharedOption::bad;
    }
    o.size_given = true;
  }
  return SharedOption::applied;
}

OptionRow replay_option_row(bool& replay) {
  return {"--replay", "on|off",
          "off: a game's movie ends with the game; on: the shot that won it follows,\n"
          "again at half speed from a second camera (default: on)",
          [&replay](const std::string& name, const std::string& value, std::string& message) {
            const auto choice = choice_index("on|off", value);
            if (!choice) {
              message = bad_value_message(name, value, "on or off");
              return false;
            }
            replay = *choice == 0;
            return true;
          }};
}

}  // namespace bsim
