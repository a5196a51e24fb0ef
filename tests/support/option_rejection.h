#pragma once
// What each program says when its command line is refused, for the tests of the option tables and of
// the options both programs share.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "export_options.h"
#include "preview_options.h"

namespace bsim::test {

/// billiards-export's message for `args`, which must be refused as a usage error.
inline std::string export_rejection(const std::vector<std::string>& args) {
  ExportOptions o;
  std::string message;
  CHECK(parse_export_options(args, o, message) == CommandLineOutcome::exit_usage);
  return message;
}

/// billiards-preview's message for `args`, which must be refused as a usage error.
inline std::string preview_rejection(const std::vector<std::string>& args) {
  PreviewOptions o;
  std::string message;
  CHECK(parse_preview_options(args, o, message) == PreviewCommandLineOutcome::exit_usage);
  return message;
}

}  // namespace bsim::test
