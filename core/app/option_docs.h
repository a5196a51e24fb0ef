#pragma once
// A program's manual page and bash completion, made from its option table and --help text at build
// time (packaging/CMakeLists.txt), so that neither can drift from what the program accepts.
#include <string>
#include <string_view>

#include "command_line.h"

namespace bsim {

/// What the manual page says besides the options.
struct ManPageText {
  std::string_view program;   ///< "billiards-export"
  std::string_view summary;   ///< the NAME line's "what it does"
  std::string_view version;   ///< "0.1.0"
  std::string_view usage;     ///< the program's whole --help text, made by usage_text from `table`
  std::string_view see_also;  ///< ".BR povray (1)" lines, as roff
  std::string_view files;     ///< the FILES section: a path, a line break, what it holds; or empty
};

/// The manual page (roff, section 1): NAME, SYNOPSIS (the usage line), DESCRIPTION (the usage's
/// head), OPTIONS (every row --help shows, with its headings and examples), EXIT STATUS (the usage's
/// tail), FILES and SEE ALSO.
std::string man_page(const ManPageText& text, const OptionTable& table);

/// A bash completion script for `program`: the shown options' names; after an option, the words of
/// its value (option_values), directories for a DIR, files for a FILE (of its extension, FILE.png);
/// otherwise the scene files (*.scn) and directories.
std::string bash_completion(std::string_view program, const OptionTable& table);

}  // namespace bsim
