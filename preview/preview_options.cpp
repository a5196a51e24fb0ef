// PLACEHOLDER until the command line lands.
#include "preview_options.h"
namespace bsim {
PreviewCommandLineOutcome parse_preview_options(const std::vector<std::string>&, PreviewOptions&, std::string& message) {
  message = "not built yet";
  return PreviewCommandLineOutcome::exit_usage;
}
}  // namespace bsim
