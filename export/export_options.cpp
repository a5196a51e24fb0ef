// PLACEHOLDER until the command line lands.
#include "export_options.h"
namespace bsim {
CommandLineOutcome parse_export_options(const std::vector<std::string>& args, ExportOptions& options, std::string&) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--events-only") options.events_only = true;
    else if (args[i] == "-o" && i + 1 < args.size()) options.out_dir = args[++i];
    else options.scene_path = args[i];
  }
  return CommandLineOutcome::run;
}
}  // namespace bsim
