#include "option_docs.h"

#include <algorithm>

namespace bsim {

namespace {

/// Text for roff: a backslash printed as itself, '-' as a minus (so options can be searched and
/// copied), a line that would start with a control character guarded.
std::string roff(std::string_view text) {
  std::string out;
  bool line_start = true;
  for (char c : text) {
    if (line_start && (c == '.' || c == '\'')) out += "\\&";
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else
      out += c;
    line_start = c == '\n';
  }
  return out;
}

/// The help column's lines joined into one paragraph that man fills.
std::string joined(std::string_view help) {
  std::string text(help);
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\n')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\n')) text.remove_suffix(1);
  return text;
}

/// The options' rows: ".TP" with the names and argument, a heading (a line ending in ':') as ".SS",
/// examples (indented lines) kept as they are.
std::string man_options(const OptionTable& table) {
  std::string out = ".SH OPTIONS\n";
  bool in_example = false;
  for (const OptionRow& row : table) {
    if (!row.shown) continue;
    const bool example = row.names.empty() && row.help.starts_with("  ");
    if (in_example && !example) out += ".fi\n.RE\n";
    if (example && !in_example) out += ".PP\n.RS\n.nf\n";
    in_example = example;
    if (example) {
      out += roff(trimmed(row.help)) + "\n";
    } else if (row.names.empty()) {
      const std::string_view heading = trimmed(row.help);
      if (!heading.empty()) out += ".SS \"" + roff(heading.substr(0, heading.find_last_not_of(':') + 1)) + "\"\n";
    } else {
      out += ".TP\n";
      const std::vector<std::string_view> names = option_names(row);
      for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", \\fB" : "\\fB") + roff(names[i]) + "\\fR";
      if (!row.argument.empty()) out += " \\fI" + roff(row.argument) + "\\fR";
      out += "\n" + roff(joined(row.help)) + "\n";
    }
  }
  if (in_example) out += ".fi\n.RE\n";
  return out;
}

std::string upper(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](char c) { return c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c; });
  return out;
}

}  // namespace

std::string man_page(const ManPageText& text, const OptionTable& table) {
  // The usage is head + the table's rows + tail (usage_text): the rows' text splits it.
  const std::string rows = usage_text("", table, "");
  const std::size_t at = text.usage.find(rows);
  const std::string_view head = text.usage.substr(0, at == std::string_view::npos ? text.usage.size() : at);
  const std::string_view tail = at == std::string_view::npos ? "" : text.usage.substr(at + rows.size());
  // head: "usage: PROGRAM ARGS\n\nDESCRIPTION\n\noptions:\n"
  const std::size_t line_end = head.find('\n');
  const std::string_view usage_line = head.substr(0, line_end);
  std::string_view description = head.substr(std::min(line_end, head.size()));
  if (const std::size_t options = description.rfind("options:"); options != std::string_view::npos)
    description = description.substr(0, options);
  const std::size_t program_end = usage_line.find(text.program);
  const std::string_view arguments =
      program_end == std::string_view::npos ? "" : trimmed(usage_line.substr(program_end + text.program.size()));
  std::string exit_status(trimmed(tail));
  if (exit_status.starts_with("exit status: ")) exit_status.erase(0, 13);

  std::string out = ".\\\" Generated from the program's option table; do not edit.\n";
  out += ".TH \"" + upper(text.program) + "\" \"1\" \"\" \"billiards-sim " + std::string(text.version) +
         "\" \"User Commands\"\n";
  out += ".SH NAME\n" + roff(text.program) + " \\- " + roff(text.summary) + "\n";
  out += ".SH SYNOPSIS\n.B " + roff(text.program) + "\n" + roff(arguments) + "\n";
  out += ".SH DESCRIPTION\n" + roff(joined(trimmed(description))) + "\n";
  out += man_options(table);
  if (!exit_status.empty()) out += ".SH \"EXIT STATUS\"\n" + roff(exit_status) + "\n";
  if (!text.files.empty()) out += ".SH FILES\n.TP\n.I " + roff(text.files) + "\n";
  if (!text.see_also.empty()) out += ".SH \"SEE ALSO\"\n" + std::string(text.see_also);
  return out;
}

namespace {

std::string shell_words(const std::vector<std::string_view>& words) {
  std::string out;
  for (std::string_view word : words) out += (out.empty() ? "" : " ") + std::string(word);
  return out;
}

/// The `case` branch completing the value of `row`: its words, directories, files, or nothing.
std::string value_branch(const OptionRow& row, std::string_view function) {
  std::string names;
  for (std::string_view name : option_names(row)) names += (names.empty() ? "" : "|") + std::string(name);
  const std::vector<std::string_view> values = option_values(row);
  std::string action;
  if (!values.empty()) {
    action = std::string(function) + "_words \"" + shell_words(values) + "\"";
  } else if (row.argument == "DIR") {
    action = "COMPREPLY=($(compgen -d -- \"$cur\"))";
  } else if (row.argument.starts_with("FILE.")) {
    const std::string extension(row.argument.substr(4));
    action = "COMPREPLY=($(compgen -f -X '!*" + extension + "' -- \"$cur\") $(compgen -d -- \"$cur\"))";
  } else if (row.argument.starts_with("FILE")) {
    action = "COMPREPLY=($(compgen -f -- \"$cur\"))";
  }
  return "    " + names + ")\n      " + (action.empty() ? "" : action + "\n      ") + "return ;;\n";
}

}  // namespace

std::string bash_completion(std::string_view program, const OptionTable& table) {
  std::string function = "_" + std::string(program);
  std::replace(function.begin(), function.end(), '-', '_');
  std::vector<std::string_view> options;
  std::string branches;
  for (const OptionRow& row : table) {
    if (!row.shown || row.names.empty()) continue;
    const std::vector<std::string_view> names = option_names(row);
    options.insert(options.end(), names.begin(), names.end());
    if (!row.argument.empty()) branches += value_branch(row, function);
  }
  std::string out = "# bash completion for " + std::string(program) +
                    ", generated from its option table; do not edit.\n\n"
                    "# The words of a value; for a comma-separated list, of its last item.\n" +
                    function + "_words() {\n  local item=${cur##*,}\n" +
                    "  COMPREPLY=($(compgen -P \"${cur%\"$item\"}\" -W \"$1\" -- \"$item\"))\n}\n\n";
  out += function +
         "() {\n"
         "  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
         "  # --option=value: bash splits the word at '='.\n"
         "  if [[ $cur == = ]]; then cur=''; elif [[ $prev == = ]]; then prev=${COMP_WORDS[COMP_CWORD-2]}; fi\n"
         "  case $prev in\n" +
         branches +
         "  esac\n"
         "  if [[ $cur == -* ]]; then\n"
         "    COMPREPLY=($(compgen -W \"" +
         shell_words(options) +
         "\" -- \"$cur\"))\n"
         "    return\n"
         "  fi\n"
         "  # The scene (or a farm run's directory).\n"
         "  COMPREPLY=($(compgen -f -X '!*.scn' -- \"$cur\") $(compgen -d -- \"$cur\"))\n"
         "}\n"
         "complete -o filenames -F " +
         function + " " + std::string(program) + "\n";
  return out;
}

}  // namespace bsim
