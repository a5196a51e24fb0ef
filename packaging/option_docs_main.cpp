// Writes a program's manual page or bash completion from its option table (core/app/option_docs.h):
//   bsim_option_docs man|completion export|preview OUTPUT
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "export_options.h"
#include "option_docs.h"
#include "preview_options.h"

namespace {

/// The program's --help text and option table.
struct Program {
  std::string name, summary, usage, see_also;
  bsim::OptionTable table;
};

Program export_program(bsim::ExportOptions& options) {
  std::string usage;
  bsim::parse_export_options({"--help"}, options, usage);
  return {"billiards-export", "simulate a billiards shot and film it with POV-Ray and ffmpeg", usage,
          ".BR billiards-preview (1),\n.BR povray (1),\n.BR ffmpeg (1)\n", bsim::export_option_table(options)};
}

Program preview_program(bsim::PreviewOptions& options) {
  std::string usage;
  bsim::parse_preview_options({"--help"}, options, usage);
  return {"billiards-preview", "look at a billiards shot: pictures, the timeline, the animatic, a window", usage,
          ".BR billiards-export (1)\n", bsim::preview_option_table(options)};
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() < 3 || (args[0] != "man" && args[0] != "completion") ||
      (args[1] != "export" && args[1] != "preview")) {
    std::cerr << "usage: bsim_option_docs man|completion export|preview OUTPUT\n";
    return 2;
  }
  bsim::ExportOptions export_options;
  bsim::PreviewOptions preview_options;
  const Program program = args[1] == "export" ? export_program(export_options) : preview_program(preview_options);
  const std::string files =
      "PREFIX/share/billiards-sim/scenes\nexample scenes (the default break is built in); PREFIX is /usr for the "
      "Debian package, /usr/local or what --prefix names for cmake --install";
  std::string text;
  if (args[0] == "man")
    text = bsim::man_page({program.name, program.summary, BSIM_VERSION, program.usage, program.see_also, files},
                          program.table);
  else
    text = bsim::bash_completion(program.name, program.table);
  std::ofstream out(args[2], std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    std::cerr << "bsim_option_docs: cannot write " << args[2] << "\n";
    return 1;
  }
  return 0;
}
